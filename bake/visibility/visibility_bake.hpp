// The potentially visible set, sampled with rays (world/visibility.hpp has the data; package
// section 37). Method:
//   1. Clusters of static surfaces: the surfaces of a BSP subtree of at most maxClusterTriangles
//      triangles whose bounds are at most maxClusterExtent metres on a side; in a larger leaf,
//      its surfaces whose centres share a cube of that size.
//   2. View cells: cubes over the static bounds (grown by half a cell), cellsPerAxis along the
//      longest axis, at least minCellSize metres.
//   3. From pointsPerCell stratified points of each cell, sweepRays closest-hit rays over the
//      sphere mark every cluster they hit (only from open points: at most a tenth of whose first
//      hits are the back of a one-sided surface; a cell with no open point culls nothing); then,
//      for every cluster still unmarked, raysPerPair segments from the cell's points to points
//      spread over the cluster's triangles (by area) mark it when one is unoccluded. A cluster
//      whose bounds reach into the cell or its neighbours is always marked. Alpha-masked and
//      blended triangles occlude nothing.
//   4. Each cell's set is the union of its own and its 26 neighbours' (a camera between sample
//      points sees what the samples around it see).
// Conservativeness: sampled, so not exact. A cluster visible only through a gap narrower than
// the spacing of both the sweep and the segments from every sample point of 27 cells can be
// missed, and so can slivers seen only from within a few centimetres of a wall. The tests
// compare the sets against dense from-point rays at open points at least 0.2 m from every
// surface (where a player's collision keeps its camera).
// Deterministic: every sample comes from a hash of its cell, cluster and index.
#pragma once

#include <cstdint>
#include <vector>

#include "bake/embree/bake_scene.hpp"
#include "world/compiled_level.hpp"
#include "world/imported_visibility.hpp"
#include "world/visibility.hpp"

namespace onelight::bake {

struct VisibilitySettings {
    uint32_t cellsPerAxis = 32;  // along the longest axis of the static bounds
    float minCellSize = 1.0f;    // metres
    uint32_t maxClusterTriangles = 512;
    float maxClusterExtent = 4.0f;  // metres
    uint32_t pointsPerCell = 8;     // one per octant, jittered
    uint32_t sweepRays = 128;       // per point
    uint32_t raysPerPair = 64;      // segments per (cell, unmarked cluster)
    uint32_t targetsPerCluster = 64;
};

/// What a source's own set (a Quake 3 map's, q3map2 -vis) does to the rays of step 3.
enum class ImportedVisibilityUse {
    // The rays, but segments only towards the clusters the source's set lets the cell see (a
    // cluster it hides is left unmarked without a ray): the source's set is conservative, so
    // this is the rays' set for a fraction of their segments.
    kBoundsTheRays,
    kReplacesTheRays,  // the source's set itself, no ray: looser
};

struct VisibilityStats {
    RayCounts rays;
    uint32_t cells = 0, openCells = 0, clusters = 0, rows = 0;
    double meanVisibleFraction = 0.0;  // clusters in an open cell's set over all clusters, mean
};

/// The visibility of `level`, whose static triangles `scene` holds in the level's own order
/// (BakeScene(device, level)). Empty for a level without static triangles. With parts > 1, part
/// `part` of a sharded bake: only every parts-th cell from `part` is sampled (interleaved, so
/// that solid and open cells spread evenly), and the result holds those cells' own sets (step
/// 3, rows deduplicated; kNoIndex for every other cell) for mergeVisibilityParts. With
/// `imported` (the source's own set, not empty: a Quake 3 map's), a cell's source set is the
/// union of the rows of the source's clusters whose leaves it reaches, and one of our clusters
/// is in it when a source cluster its bounds reach is; a cell that reaches only solid leaves
/// has none (culls nothing). `use` says whether that set bounds step 3's segments or replaces
/// step 3. Steps 1, 2 and 4 are the same.
[[nodiscard]] world::Visibility bakeVisibility(
    const BakeScene& scene, const world::CompiledLevel& level, const VisibilitySettings& settings,
    bool showProgress, VisibilityStats* stats = nullptr, uint32_t part = 0, uint32_t parts = 1,
    const world::ImportedVisibility* imported = nullptr,
    ImportedVisibilityUse use = ImportedVisibilityUse::kBoundsTheRays);

/// Step 4 over the cells' own sets (`raw`, wordsPerRow words per cell; `openCell` per cell):
/// each open cell's set is the union of its own and its 26 neighbours', rows deduplicated.
[[nodiscard]] world::Visibility finishVisibility(world::Visibility v,
                                                 const std::vector<uint32_t>& raw,
                                                 const std::vector<uint8_t>& openCell,
                                                 VisibilityStats* stats);

/// The parts of a sharded bake's visibility, in shard order (parts[i] from bakeVisibility with
/// part i of parts.size()), joined and finished exactly as a whole bake finishes its own.
[[nodiscard]] world::Visibility mergeVisibilityParts(
    const std::vector<const world::Visibility*>& parts);

}  // namespace onelight::bake
