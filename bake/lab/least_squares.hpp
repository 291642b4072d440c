// Dense linear least squares by Householder QR (Golub and Van Loan, alg. 5.3.2): the fitting
// tool of the lab. Small problems only (tens of unknowns).
#pragma once

#include <vector>

namespace onelight::lab {

// Minimizes |A x - b| for A with `rows` rows and `cols` columns, row-major, rows >= cols.
// Throws std::runtime_error when A is rank deficient.
[[nodiscard]] std::vector<double> solveLeastSquares(std::vector<double> A, std::vector<double> b,
                                                    int rows, int cols);

}  // namespace onelight::lab
