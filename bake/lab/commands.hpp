// The larger onelight-lab commands, one file each.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace onelight::lab {

// brdf-report: writes DIR/README.md, CSVs and PNG plots (report.cpp). `quick` uses coarse grids.
[[nodiscard]] int brdfReport(const std::string& dir, bool quick);

// env-fit: fits the environment "Fresnel" (env_brdf.hpp) and writes it as GLSL to `path`
// (default: stdout) (env_fit_command.cpp).
[[nodiscard]] int envFit(const std::string& path);

// env-table: integrates the split-sum table (shaders/lighting.glsl) and writes its numbers to
// `path` (default: stdout) (env_table_command.cpp).
[[nodiscard]] int envTable(const std::string& path);

// horizon-cut: the mean specular albedo of a normal-mapped floor's texels with and without the
// floor's plane cutting their lobes, as CSV on stdout; `steps` cells of cos theta per texel
// (horizon_cut_command.cpp).
[[nodiscard]] int horizonCut(int steps);

// sheet: EXRs side by side, `columns` to a row (0: all in one), each row through its exposure
// (one EV100 for all rows, or one per row) and the filmic curve into the PNG `output`; with a
// rectangle (x, y, width, height) each image's mean there (sheet_command.cpp).
[[nodiscard]] int sheet(const std::string& output, const std::vector<float>& ev100,
                        const std::vector<std::string>& images, const std::vector<uint32_t>& rect,
                        uint32_t columns);

}  // namespace onelight::lab
