#include "bake/textures/gloss_tables.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

namespace onelight::bake {

namespace {

constexpr int kLast = GlossTable::kEntries - 1;

// Minimizes |A x - b| for A of `rows` x `cols`, row-major, by Householder QR (Golub and Van Loan
// 2013, "Matrix Computations", alg. 5.3.2). Throws when A is rank deficient.
std::vector<double> solveLeastSquares(std::vector<double> A, std::vector<double> b, int rows,
                                      int cols) {
    auto at = [&](int r, int c) -> double& { return A[std::size_t(r) * std::size_t(cols) + c]; };
    for (int k = 0; k < cols; ++k) {
        double norm = 0.0;
        for (int r = k; r < rows; ++r) norm += at(r, k) * at(r, k);
        norm = std::sqrt(norm);
        if (norm == 0.0) throw std::runtime_error("solveLeastSquares: rank deficient");
        double alpha = at(k, k) > 0.0 ? -norm : norm;
        // v = x - alpha e1, H = I - 2 v v^T / (v^T v).
        std::vector<double> v(std::size_t(rows - k));
        for (int r = k; r < rows; ++r) v[std::size_t(r - k)] = at(r, k);
        v[0] -= alpha;
        double vv = 0.0;
        for (double x : v) vv += x * x;
        if (vv == 0.0) continue;
        auto reflect = [&](auto&& element) {
            double s = 0.0;
            for (int r = k; r < rows; ++r) s += v[std::size_t(r - k)] * element(r);
            s *= 2.0 / vv;
            for (int r = k; r < rows; ++r) element(r) -= s * v[std::size_t(r - k)];
        };
        for (int c = k; c < cols; ++c) reflect([&](int r) -> double& { return at(r, c); });
        reflect([&](int r) -> double& { return b[std::size_t(r)]; });
    }
    std::vector<double> x(std::size_t(cols), 0.0);
    for (int k = cols - 1; k >= 0; --k) {
        double s = b[std::size_t(k)];
        for (int c = k + 1; c < cols; ++c) s -= at(k, c) * x[std::size_t(c)];
        if (std::abs(at(k, k)) < 1e-300) throw std::runtime_error("solveLeastSquares: singular");
        x[std::size_t(k)] = s / at(k, k);
    }
    return x;
}

template <std::size_t N>
double polynomial(const std::array<double, N>& c, double x) {
    double s = 0.0;
    for (std::size_t i = N; i-- > 0;) s = s * x + c[i];
    return s;
}

double fitValue(const GlossFit& fit, double x) {
    return polynomial(fit.p, x) / polynomial(fit.q, x);
}

GlossTable buildTable(bool variance) {
    GlossTable table{};
    for (int i = 0; i <= kLast; ++i) {
        GgxLobeStatistics s = ggxLobeStatistics(double(i) / kLast);
        // 1 - 1/A = (A - 1) / A, without cancellation.
        double distance = variance ? s.normalVariance : s.excessArea / (1.0 + s.excessArea);
        table.log2Distance[std::size_t(i)] = std::log2(distance);
    }
    return table;
}

}  // namespace

double ggxAlpha_fromGloss(double gloss) {
    return std::sqrt(2.0 / (1.0 + std::exp2(18.0 * gloss)));
}

double roughness_fromGloss(double gloss) {
    return std::sqrt(ggxAlpha_fromGloss(gloss));
}

GgxLobeStatistics ggxLobeStatistics(double gloss) {
    const double alpha = ggxAlpha_fromGloss(gloss);
    const double logAlpha = std::log(alpha);
    // The lobe's projected measure sech^2(t) / 2 is below 1e-17 outside |t| < 20; on the rough
    // side tan^2 -> 0 as well, and on the smooth side the excess-area integrand is ~2 alpha e^-t
    // beyond tan = 1 (t = -ln alpha), negligible 40 further on.
    const double h = 1.0 / 16.0;
    const int first = -20 * 16;
    const int last = int(std::ceil((40.0 - logAlpha) / h));
    GgxLobeStatistics s{0.0, 0.0};
    for (int j = first; j <= last; ++j) {
        double t = j * h;
        double e = std::exp(-2.0 * std::abs(t));
        double measure = 2.0 * e / ((1.0 + e) * (1.0 + e));  // sech^2(t) / 2
        double tan2 = std::exp(2.0 * (t + logAlpha));        // tan^2(theta_m)
        // 1 / cos(theta_m) - 1 = sqrt(1 + tan^2) - 1 = tan^2 / (sqrt(1 + tan^2) + 1).
        s.excessArea += measure * (tan2 / (std::sqrt(1.0 + tan2) + 1.0));
        s.normalVariance += measure * (tan2 / (1.0 + tan2));  // sin^2(theta_m)
    }
    s.excessArea *= h;
    s.normalVariance *= h;
    return s;
}

const GlossTable& averageNormalLengthTable() {
    static const GlossTable table = buildTable(false);
    return table;
}

const GlossTable& normalVarianceTable() {
    static const GlossTable table = buildTable(true);
    return table;
}

double distance_fromGloss(const GlossTable& table, double gloss) {
    double u = (std::isnan(gloss) ? 0.0 : std::clamp(gloss, 0.0, 1.0)) * kLast;
    int i = std::min(int(u), kLast - 1);
    double f = u - i;
    const auto& y = table.log2Distance;
    return std::exp2(y[std::size_t(i)] + f * (y[std::size_t(i) + 1] - y[std::size_t(i)]));
}

double gloss_fromDistance(const GlossTable& table, double distance) {
    if (std::isnan(distance)) return 0.0;
    if (distance <= 0.0) return 1.0;
    const auto& y = table.log2Distance;
    double target = std::log2(distance);
    if (target >= y.front()) return 0.0;
    if (target <= y.back()) return 1.0;
    // First entry at or below the target (y is decreasing); i >= 1 by the checks above.
    auto below = std::lower_bound(y.begin(), y.end(), target,
                                  [](double entry, double value) { return entry > value; });
    int i = int(below - y.begin()) - 1;
    double f = (y[std::size_t(i)] - target) / (y[std::size_t(i)] - y[std::size_t(i) + 1]);
    return std::clamp((i + f) / kLast, 0.0, 1.0);
}

double averageNormalLength_fromGloss(double gloss) {
    return 1.0 - distance_fromGloss(averageNormalLengthTable(), gloss);
}

double gloss_fromAverageNormalLength(double length) {
    return gloss_fromDistance(averageNormalLengthTable(), 1.0 - length);
}

double normalVariance_fromGloss(double gloss) {
    return distance_fromGloss(normalVarianceTable(), gloss);
}

double gloss_fromNormalVariance(double variance) {
    return gloss_fromDistance(normalVarianceTable(), variance);
}

GlossFit fitGloss(const GlossTable& table) {
    constexpr int np = GlossFit::kNumeratorTerms, nq = GlossFit::kDenominatorTerms;
    constexpr int cols = np + nq - 1;
    GlossFit fit;
    fit.xMin = -table.log2Distance.front();
    fit.xMax = -table.log2Distance.back();
    std::vector<double> xs(GlossTable::kEntries), gs(GlossTable::kEntries);
    for (int i = 0; i <= kLast; ++i) {
        xs[std::size_t(i)] =
            (-table.log2Distance[std::size_t(i)] - fit.xMin) / (fit.xMax - fit.xMin);
        gs[std::size_t(i)] = double(i) / kLast;
    }
    // g Q(x) = P(x) is linear in the coefficients: P(x) - g (q1 x + q2 x^2) = g. Dividing each
    // row by the previous iterate's Q(x) makes the residual (P - g Q) / Q = fit - g.
    fit.q[0] = 1.0;
    for (int iteration = 0; iteration < 12; ++iteration) {
        std::vector<double> A(std::size_t(GlossTable::kEntries * cols)), b(GlossTable::kEntries);
        for (int i = 0; i <= kLast; ++i) {
            double x = xs[std::size_t(i)], g = gs[std::size_t(i)];
            double w = 1.0 / polynomial(fit.q, x);
            double* row = &A[std::size_t(i * cols)];
            double power = 1.0;
            for (int k = 0; k < np; ++k, power *= x) row[k] = w * power;
            power = x;
            for (int k = 1; k < nq; ++k, power *= x) row[np + k - 1] = -w * g * power;
            b[std::size_t(i)] = w * g;
        }
        std::vector<double> c = solveLeastSquares(A, b, GlossTable::kEntries, cols);
        for (int k = 0; k < np; ++k) fit.p[std::size_t(k)] = c[std::size_t(k)];
        for (int k = 1; k < nq; ++k) fit.q[std::size_t(k)] = c[std::size_t(np + k - 1)];
    }
    double sum2 = 0.0;
    for (int i = 0; i <= kLast; ++i) {
        double e = std::abs(fitValue(fit, xs[std::size_t(i)]) - gs[std::size_t(i)]);
        fit.maxGlossError = std::max(fit.maxGlossError, e);
        sum2 += e * e;
    }
    fit.rmsGlossError = std::sqrt(sum2 / GlossTable::kEntries);
    return fit;
}

const GlossFit& averageNormalLengthFit() {
    static const GlossFit fit = fitGloss(averageNormalLengthTable());
    return fit;
}

const GlossFit& normalVarianceFit() {
    static const GlossFit fit = fitGloss(normalVarianceTable());
    return fit;
}

double gloss_fromDistance(const GlossFit& fit, double distance) {
    if (std::isnan(distance)) return 0.0;
    if (distance <= 0.0) return 1.0;
    double x = std::clamp((-std::log2(distance) - fit.xMin) / (fit.xMax - fit.xMin), 0.0, 1.0);
    return std::clamp(fitValue(fit, x), 0.0, 1.0);
}

}  // namespace onelight::bake
