#include "least_squares.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace onelight::lab {

std::vector<double> solveLeastSquares(std::vector<double> A, std::vector<double> b, int rows,
                                      int cols) {
    auto at = [&](int r, int c) -> double& { return A[size_t(r) * cols + c]; };
    // Columns whose remaining norm falls below this, relative to the largest, are dependent.
    double largest = 0.0;
    for (double x : A) largest = std::max(largest, std::abs(x));
    const double negligible = 1e-12 * largest * std::sqrt(double(rows));
    for (int k = 0; k < cols; ++k) {
        // Householder vector zeroing column k below the diagonal.
        double norm = 0.0;
        for (int r = k; r < rows; ++r) norm += at(r, k) * at(r, k);
        norm = std::sqrt(norm);
        if (norm <= negligible)
            throw std::runtime_error("least squares: rank-deficient matrix (column " +
                                     std::to_string(k) + ")");
        double alpha = at(k, k) > 0.0 ? -norm : norm;
        std::vector<double> v(rows - k);
        for (int r = k; r < rows; ++r) v[r - k] = at(r, k);
        v[0] -= alpha;
        double vv = 0.0;
        for (double x : v) vv += x * x;
        if (vv == 0.0) continue;
        // Apply I - 2 v v^T / (v^T v) to the remaining columns and to b.
        for (int c = k; c < cols; ++c) {
            double dot = 0.0;
            for (int r = k; r < rows; ++r) dot += v[r - k] * at(r, c);
            double s = 2.0 * dot / vv;
            for (int r = k; r < rows; ++r) at(r, c) -= s * v[r - k];
        }
        double dot = 0.0;
        for (int r = k; r < rows; ++r) dot += v[r - k] * b[r];
        double s = 2.0 * dot / vv;
        for (int r = k; r < rows; ++r) b[r] -= s * v[r - k];
    }
    std::vector<double> x(cols);
    for (int k = cols - 1; k >= 0; --k) {
        double sum = b[k];
        for (int c = k + 1; c < cols; ++c) sum -= at(k, c) * x[c];
        x[k] = sum / at(k, k);
    }
    return x;
}

}  // namespace onelight::lab
