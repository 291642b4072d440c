#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "least_squares.hpp"

using onelight::lab::solveLeastSquares;

TEST(LeastSquares, RecoversExactPolynomialCoefficients) {
    const double c[4] = {0.5, -2.0, 3.0, 0.25};
    std::vector<double> A, b;
    for (int i = 0; i < 20; ++i) {
        double x = -1.0 + i / 9.5;
        double y = 0.0;
        for (int k = 0; k < 4; ++k) {
            A.push_back(std::pow(x, k));
            y += c[k] * std::pow(x, k);
        }
        b.push_back(y);
    }
    std::vector<double> x = solveLeastSquares(A, b, 20, 4);
    for (int k = 0; k < 4; ++k) EXPECT_NEAR(x[k], c[k], 1e-12);
}

TEST(LeastSquares, MinimizesTheResidualOfAnInconsistentSystem) {
    // Fitting a constant to {1, 2, 3, 10} gives the mean.
    std::vector<double> x = solveLeastSquares({1, 1, 1, 1}, {1, 2, 3, 10}, 4, 1);
    EXPECT_NEAR(x[0], 4.0, 1e-14);
}

TEST(LeastSquares, RejectsRankDeficientSystems) {
    EXPECT_THROW(solveLeastSquares({1, 2, 2, 4, 3, 6}, {1, 2, 3}, 3, 2), std::runtime_error);
}
