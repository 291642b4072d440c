// The sample grids and error measures the lab's tables are computed on, in one place so that
// the report, the fit and the tests speak of the same numbers.
#pragma once

#include <cmath>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "albedo.hpp"
#include "env_brdf.hpp"

namespace onelight::lab {

// The runtime's specular model, as justified by the report's speed-against-error table.
constexpr std::string_view kRuntimeModel = "ggx_smith";

// n values spread over (0, 1], denser near 0 (grazing), ending at 1.
[[nodiscard]] inline std::vector<double> muGrid(int n) {
    std::vector<double> v;
    for (int i = 1; i <= n; ++i) v.push_back(std::pow(double(i) / n, 1.5));
    return v;
}
// n + 1 values over [0, 1].
[[nodiscard]] inline std::vector<double> glossGrid(int n) {
    std::vector<double> v;
    for (int i = 0; i <= n; ++i) v.push_back(double(i) / n);
    return v;
}
[[nodiscard]] inline std::vector<double> fitGridMu() {
    return muGrid(32);
}
[[nodiscard]] inline std::vector<double> fitGridGloss() {
    return glossGrid(32);
}
// Off the fit grid and off table texel centres: the check is not fooled by interpolation.
[[nodiscard]] inline std::vector<double> checkGridMu() {
    std::vector<double> v;
    for (int i = 0; i < 47; ++i) v.push_back(0.005 + 0.995 * (i + 0.37) / 47.0);
    return v;
}
[[nodiscard]] inline std::vector<double> checkGridGloss() {
    std::vector<double> v;
    for (int i = 0; i < 41; ++i) v.push_back((i + 0.29) / 41.0);
    return v;
}

// Error of an environment-Fresnel candidate on the albedo f0 * scale + bias, for f0 in
// {0.04, 1} (a dielectric and a white metal), over the samples.
struct EnvError {
    double max = 0.0, rms = 0.0;
};
[[nodiscard]] inline EnvError envError(const std::vector<EnvSample>& samples,
                                       const std::function<ScaleBias(double, double)>& candidate) {
    EnvError e;
    double sum = 0.0;
    int count = 0;
    for (const EnvSample& s : samples) {
        ScaleBias c = candidate(s.mu, s.gloss);
        for (double f0 : {0.04, 1.0}) {
            double d = std::abs(c.albedo(f0) - s.truth.albedo(f0));
            e.max = std::max(e.max, d);
            sum += d * d;
            ++count;
        }
    }
    e.rms = std::sqrt(sum / count);
    return e;
}

}  // namespace onelight::lab
