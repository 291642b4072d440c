// onelight-lab env-fit: fits the environment "Fresnel" of the runtime model (ggx_smith) as a
// least-squares fit on a physical basis and writes it as GLSL (shaders/env_brdf_fit.glsl).
#include <cmath>
#include <cstdio>
#include <fstream>
#include <stdexcept>

#include "commands.hpp"
#include "env_brdf.hpp"
#include "grids.hpp"
#include "world/file_write.hpp"

namespace onelight::lab {

int envFit(const std::string& path) {
    const SpecularModel& model = findModel(kRuntimeModel);
    std::fprintf(stderr, "env-fit: integrating the %s albedo on the fit grid...\n",
                 std::string(model.name).c_str());
    std::vector<EnvSample> fitSamples = envTruth(model, fitGridMu(), fitGridGloss());
    std::vector<EnvSample> checkSamples = envTruth(model, checkGridMu(), checkGridGloss());
    EnvFit fit = fitEnv(fitSamples);
    EnvError err = envError(checkSamples, [&](double mu, double g) { return fit.evaluate(mu, g); });
    char provenance[512];
    std::snprintf(provenance, sizeof provenance,
                  "// Fit of the %s albedo (f0 * scale + bias) on %zu points; on a %zu-point\n"
                  "// check grid the albedo error for f0 in {0.04, 1} is max %.2e, RMS %.2e.\n",
                  std::string(model.name).c_str(), fitSamples.size(), checkSamples.size(), err.max,
                  err.rms);
    std::string glsl = envFitGlsl(fit, provenance);
    std::fprintf(stderr, "env-fit: max error %.3e, RMS %.3e\n", err.max, err.rms);
    if (path.empty()) {
        std::fputs(glsl.c_str(), stdout);
        return 0;
    }
    world::writeFileAtomically(path, glsl);
    std::fprintf(stderr, "env-fit: wrote %s\n", path.c_str());
    return 0;
}

}  // namespace onelight::lab
