// Automatic environment-probe placement: a lattice over the level's static bounds, its points
// that are not inside solid geometry, grouped into connected regions by unoccluded segments.
#pragma once

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "bake/embree/bake_scene.hpp"
#include "probe_capture.hpp"
#include "world/compiled_level.hpp"

namespace onelight::bake {

struct ProbePlacementSettings {
    float spacing = 8.0f;         // metres, lattice step requested when the level sets none; > 0
    bool overridesLevel = false;  // true: `spacing` wins over the level's (--probe-spacing)
};

/// Lattice points at most; a finer lattice grows its spacing until it fits. 256 bounds what
/// automatic probes cost: 33.6 MB of texels and about 6 minutes of capture and prefiltering at
/// default quality (131 KB, 1.5 s each), and 1536 cube-array layers at runtime, under the 2048
/// layers Vulkan implementations commonly allow (maxImageArrayLayers; lavapipe's too).
inline constexpr uint32_t kMaxProbeLatticePoints = 256;
/// Probes a level may bake, authored or automatic: 341 cubes fill 2046 cube-array layers, under
/// the 2048 that Vulkan implementations commonly allow (the runtime refuses more). The baker
/// checks it, with the probes' memory, before capturing any.
inline constexpr uint32_t kMaxBakedProbes = 341;
/// The lattice spans at least this much above the bounds' bottom (y is up): a flat level's
/// probes float half of it above the floor instead of lying in it.
inline constexpr float kProbeMinLatticeHeight = 2.0f;  // metres
/// Directions cast from a point to tell whether it is inside solid (a Fibonacci sphere set).
inline constexpr uint32_t kProbeSolidRays = 64;
/// Inside solid when more than this fraction of the rays that hit something hit a back face.
inline constexpr float kProbeSolidFraction = 0.5f;

/// Box fitting: rays per side of each of the six cube faces around a probe, and the share of a
/// face's rays that must hit geometry for the face to close the box.
inline constexpr uint32_t kBoxFitRays = 5;
inline constexpr float kBoxFitHitFraction = 0.8f;

/// Specular triangles (at most about this many, evenly through them) whose reflection rays
/// decide whether the level has anything to reflect.
inline constexpr uint32_t kReflectorPoints = 4096;

/// What placement found, for tests and the bake report.
struct ProbePlacementStats {
    float spacing = 0.0f;           // metres, the step used (requested, or grown by the cap)
    glm::uvec3 lattice{0u};         // points per axis (0 when no lattice was laid)
    uint32_t latticePoints = 0;     // lattice.x * lattice.y * lattice.z
    uint32_t openPoints = 0;        // lattice points not inside solid: one probe each
    uint32_t components = 0;        // connected regions of open points
    uint32_t cameraProbes = 0;      // probes added at authored cameras
    bool fallback = false;          // nothing open: one probe at the least solid lattice point
    bool nothingToReflect = false;  // no specular surface sees geometry: no probe placed
    uint32_t boxed = 0;             // placed probes that got a fitted box
    RayCounts rays;                 // solid tests in `probe`, segments in `shadow`
};

/// Throws world::Error, before any probe is captured, when `probeCount` probes of `faceSize`
/// exceed kMaxBakedProbes; the message gives their count, bytes in the package and the limit.
void checkProbeBudget(size_t probeCount, uint32_t faceSize);

// The probes of a level whose static world is `scene` (built from the same level).
//
// Authored probes win: when any entity is flagged kEntityProbe, exactly those, in entity
// order, each with its box when the box is non-empty, flagged insideSolid by the solid test
// below (the bake warns: such a probe's reflections come out dark). Otherwise none
// unless the level has specular materials (kFeatureProbes). Then, with no box and entity kNoIndex:
//
// - Nothing to reflect (a lone floor under a uniform sky): none when, from the centres of the
//   specular triangles (about kReflectorPoints of them at most), no ray of kProbeSolidRays
//   directions over their front hemispheres (both sides when double-sided) hits geometry, and
//   the sky is not an image: their reflections hold only the uniform sky, which the runtime's
//   probe-less path reproduces (docs/lighting.md "Secondary specular").
//   stats->nothingToReflect says so.
// - Empty level (no static triangle): one probe at the centre of the bounds.
// - Lattice: the spacing is level.settings.probe_spacing when the level sets it (> 0), else
//   settings.spacing. Over the static bounds (level.settings.boundsMin/max), per axis
//   n = max(1, ceil(extent / spacing)) cells of extent / n metres (<= spacing), a point at each
//   cell centre (at boundsMin on an axis of zero extent), as the light grid lays its cells;
//   the top is raised to at least boundsMin.y + kProbeMinLatticeHeight.
//   Over kMaxProbeLatticePoints points in all, the spacing grows by
//   max(1.01, cbrt(points / kMaxProbeLatticePoints)) until it fits.
// - Open: a point is inside solid when, of kProbeSolidRays fixed directions (a Fibonacci sphere
//   set, the same for every point), more than kProbeSolidFraction of the rays that hit
//   something hit a back face. This mirrors the light grid's inside-solid rule (bake/grid,
//   back-face first hits over GridSettings::insideFraction = 0.5, not exposed as a function)
//   with one difference: the grid divides by all its rays, this by the rays that hit. In a
//   closed room every ray hits and the two agree; in the void outside a level's closed shell
//   rays escape or hit the outside (back) of walls, which the grid's rule can call open and
//   this one calls solid. A point with no geometry around it (no ray hits) is open, so a
//   point of that void far enough from every wall that all its rays escape is still open.
// - Connected: two open 6-neighbours are connected when the segment between them is
//   unoccluded (one Embree occlusion ray from the lower index). Components by union-find; a
//   component is numbered by its lowest lattice index.
// - Probes: one at every open lattice point, by component (lowest lattice index first), then
//   by lattice index (x fastest, then y, then z). So each component has at least one probe
//   and probes are `spacing` apart. A region that holds no lattice point (a room smaller than
//   the spacing, between points) gets none and is not seen: lower the spacing for it.
// - Cameras (where the player looks): then one probe at each authored camera, in order, that
//   is not inside solid (the rule above) and not within spacing / 2 of any probe before it.
// - Boxes: each probe placed so far gets a box-projection box fitted to the walls around it
//   (kBoxFitRays^2 rays through each face of a cube around it; each face at the farthest hit
//   along its axis), or none when a face is open (fewer than kBoxFitHitFraction of its rays
//   hit): rooms are box-projected, open areas are not. stats->boxed counts them.
// - Fallback: when that leaves no probe (every point inside solid, no camera kept), one at the
//   lattice point with the smallest back-face fraction (lowest index on ties), so a level with
//   specular materials always has a probe; stats->fallback says so.
//
// The same level and scene give the same probes in the same order on any thread count.
[[nodiscard]] std::vector<ProbePlacement> placeProbes(const world::CompiledLevel& level,
                                                      const BakeScene& scene,
                                                      const ProbePlacementSettings& settings,
                                                      ProbePlacementStats* stats = nullptr);

}  // namespace onelight::bake
