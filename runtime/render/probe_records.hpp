// The environment probes as the forward shader reads them: one GpuProbe record per probe and
// one cube of the probes' cube array per record, both in the order the shader's blending walks
// (shaders/probe.glsl, "Influence"): from the smallest influence volume to the largest.
#pragma once

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "render/gpu_types.hpp"
#include "world/baked_lighting.hpp"

namespace onelight::render {

/// A probe with a box (min < max on every axis) is box-projected and influences its box, with a
/// blend band of 10% of the box's smallest extent, at most kMaxProbeBand. A probe without one
/// influences the cube centred on its capture point whose half-extent R is the distance to the
/// nearest other probe (at least kMinProbeRadius), with a band of R: a tent that reaches 0 at
/// the neighbour, so neighbouring probes cross-fade. A lone probe without a box influences the
/// whole level (R reaches its farthest bounds corner).
inline constexpr float kMaxProbeBand = 1.0f;    // metres
inline constexpr float kMinProbeRadius = 0.5f;  // metres

struct ProbeRecords {
    std::vector<GpuProbe> records;  // records[i] is probes[order[i]], cube-array cube i
    std::vector<uint32_t> order;
};

/// Records of `probes` in blending order (influence volume ascending, index on ties).
[[nodiscard]] ProbeRecords makeProbeRecords(const std::vector<world::EnvironmentProbe>& probes,
                                            glm::vec3 levelMin, glm::vec3 levelMax);

/// The probes' cell grid, so that a pixel walks only the records that can matter to it rather
/// than all of them (gpu_interface.glsl GpuProbeGrid has the layout). A cell lists, in blending
/// order, every record whose influence box overlaps the cell grown by a small margin (so a point
/// rounded into a neighbouring cell still finds its records), then every record that can be
/// the nearest capture point to some point of the cell: those no farther at their closest than
/// the best record's farthest. Walking a cell's lists therefore picks exactly what walking every
/// record picks. The grid covers the level's bounds in cubes of 1/kProbeCellsPerAxis of the
/// longest extent; a point outside it walks every record. Levels with at most
/// kProbeGridMinRecords records get no grid.
inline constexpr uint32_t kProbeCellsPerAxis = 32;
inline constexpr uint32_t kProbeGridMinRecords = 4;

struct ProbeCells {
    GpuProbeGrid grid{};          // dims.w 0: no grid
    std::vector<uint32_t> words;  // probeCells[]: 2 words per cell, then the lists (>= 1 word)
};

[[nodiscard]] ProbeCells makeProbeCells(const std::vector<GpuProbe>& records, glm::vec3 levelMin,
                                        glm::vec3 levelMax);

/// The cell index of p as the shader computes it, or kNoIndex outside the grid (or no grid).
[[nodiscard]] uint32_t probeCellOf(const GpuProbeGrid& grid, glm::vec3 p);

/// One record that influences everything, for the neutral placeholder cube.
[[nodiscard]] GpuProbe placeholderProbeRecord();

}  // namespace onelight::render
