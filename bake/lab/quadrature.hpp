// Globally adaptive Gauss-Kronrod (7/15) quadrature for vector-valued integrands: the lab's
// numerical integrator. Deterministic: the same integrand and tolerances give the same bits.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace onelight::lab {

template <int N>
using Vec = std::array<double, N>;

struct QuadratureTolerance {
    double absolute = 1e-10;
    double relative = 1e-9;
    int maxIntervals = 1000;
};

namespace detail {

// Kronrod 15-point nodes (positive half, last is 0) and weights; Gauss 7-point weights on the
// odd Kronrod nodes. Piessens et al. 1983, QUADPACK (qk15).
constexpr double kNodes[8] = {
    0.991455371120812639206854697526329, 0.949107912342758524526189684047851,
    0.864864423359769072789712788640926, 0.741531185599394439863864773280788,
    0.586087235467691130294144845693013, 0.405845151377397166906606412076961,
    0.207784955007898467600689403773245, 0.0};
constexpr double kKronrodWeights[8] = {
    0.022935322010529224963732008058970, 0.063092092629978553290700663189204,
    0.104790010322250183839876322541518, 0.140653259715525918745189590510238,
    0.169004726639267902826583426598550, 0.190350578064785409913256402421014,
    0.204432940075298892414161999234649, 0.209482141084727828012999174891714};
constexpr double kGaussWeights[4] = {
    0.129484966168869693270611432679082, 0.279705391489276667901467771423780,
    0.381830050505118944950369775488975, 0.417959183673469387755102040816327};

template <int N>
struct Interval {
    double a, b;
    Vec<N> value;
    double error;  // max over components of |Kronrod - Gauss|
};

template <int N, class F>
[[nodiscard]] Interval<N> gaussKronrod(const F& f, double a, double b) {
    double center = 0.5 * (a + b), half = 0.5 * (b - a);
    Vec<N> kronrod{}, gauss{};
    for (int i = 0; i < 8; ++i) {
        int samples = (i == 7) ? 1 : 2;
        for (int s = 0; s < samples; ++s) {
            double x = center + (s == 0 ? half : -half) * kNodes[i];
            Vec<N> y = f(x);
            for (int c = 0; c < N; ++c) {
                kronrod[c] += kKronrodWeights[i] * y[c];
                if (i % 2 == 1) gauss[c] += kGaussWeights[i / 2] * y[c];
            }
        }
    }
    Interval<N> r{a, b, {}, 0.0};
    for (int c = 0; c < N; ++c) {
        r.value[c] = kronrod[c] * half;
        r.error = std::max(r.error, std::abs((kronrod[c] - gauss[c]) * half));
    }
    return r;
}

}  // namespace detail

// Integral of f over [a, b]; f maps double -> Vec<N>. Bisects the interval of largest error
// until the summed error is within max(absolute, relative * |integral|) (max over components).
template <int N, class F>
[[nodiscard]] Vec<N> integrate(const F& f, double a, double b, QuadratureTolerance tol = {}) {
    using detail::Interval;
    std::vector<Interval<N>> intervals{detail::gaussKronrod<N>(f, a, b)};
    auto worse = [](const Interval<N>& x, const Interval<N>& y) { return x.error < y.error; };
    while (true) {
        Vec<N> total{};
        double error = 0.0, magnitude = 0.0;
        for (const Interval<N>& i : intervals) {
            for (int c = 0; c < N; ++c) total[c] += i.value[c];
            error += i.error;
        }
        for (int c = 0; c < N; ++c) magnitude = std::max(magnitude, std::abs(total[c]));
        if (error <= std::max(tol.absolute, tol.relative * magnitude) ||
            int(intervals.size()) >= tol.maxIntervals)
            return total;
        std::pop_heap(intervals.begin(), intervals.end(), worse);
        Interval<N> w = intervals.back();
        intervals.pop_back();
        double mid = 0.5 * (w.a + w.b);
        intervals.push_back(detail::gaussKronrod<N>(f, w.a, mid));
        std::push_heap(intervals.begin(), intervals.end(), worse);
        intervals.push_back(detail::gaussKronrod<N>(f, mid, w.b));
        std::push_heap(intervals.begin(), intervals.end(), worse);
    }
}

}  // namespace onelight::lab
