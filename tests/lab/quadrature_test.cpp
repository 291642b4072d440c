#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "quadrature.hpp"

using onelight::lab::integrate;
using onelight::lab::Vec;

TEST(Quadrature, IntegratesPolynomialsAndTranscendentalsToTolerance) {
    EXPECT_NEAR(integrate<1>([](double x) { return Vec<1>{std::pow(x, 5)}; }, 0, 1)[0], 1.0 / 6,
                1e-12);
    EXPECT_NEAR(integrate<1>([](double x) { return Vec<1>{std::sin(x)}; }, 0, std::numbers::pi)[0],
                2.0, 1e-10);
    EXPECT_NEAR(integrate<1>([](double x) { return Vec<1>{std::exp(-x * x)}; }, -8, 8)[0],
                std::sqrt(std::numbers::pi), 1e-10);
}

TEST(Quadrature, AdaptsToEndpointSingularitiesAndKinks) {
    // sqrt has an infinite derivative at 0; |x - 1/3| has a kink inside.
    EXPECT_NEAR(integrate<1>([](double x) { return Vec<1>{std::sqrt(x)}; }, 0, 1)[0], 2.0 / 3,
                1e-9);
    EXPECT_NEAR(integrate<1>([](double x) { return Vec<1>{std::abs(x - 1.0 / 3)}; }, 0, 1)[0],
                (1.0 / 9 + 4.0 / 9) / 2, 1e-9);
}

TEST(Quadrature, VectorComponentsAreIntegratedTogetherAndDeterministically) {
    auto f = [](double x) { return Vec<2>{x, std::cos(40 * x)}; };
    Vec<2> a = integrate<2>(f, 0, 1), b = integrate<2>(f, 0, 1);
    EXPECT_NEAR(a[0], 0.5, 1e-12);
    EXPECT_NEAR(a[1], std::sin(40.0) / 40, 1e-9);
    EXPECT_EQ(a, b);
}
