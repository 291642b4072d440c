// The larger onelight-lab commands, one file each.
#pragma once

#include <string>

namespace onelight::lab {

// brdf-report: writes DIR/README.md, CSVs and PNG plots (report.cpp). `quick` uses coarse grids.
[[nodiscard]] int brdfReport(const std::string& dir, bool quick);

// env-fit: fits the environment "Fresnel" (env_brdf.hpp) and writes it as GLSL to `path`
// (default: stdout) (env_fit_command.cpp).
[[nodiscard]] int envFit(const std::string& path);

}  // namespace onelight::lab
