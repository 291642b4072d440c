// Primary-light regions: every static triangle gets exactly one primary. Where the dominant
// primary changes inside a mesh, the mesh is split along the change with OpenMesh (edges are
// cut where a bisection finds the switch), so no triangle straddles two primaries; fragments
// smaller than a threshold are merged into the neighbour they share the longest border with.
#pragma once

#include <cstdint>
#include <vector>

#include "world/regions/primary_illuminance.hpp"
#include "world/static_geometry.hpp"

namespace onelight::world {

struct RegionOptions {
    double minFragmentArea = 0.05;    // m^2: smaller same-primary fragments are merged
    double boundaryTolerance = 1e-3;  // metres: bisection stops below this; edges shorter
                                      // than twice this are not cut
    double sampleSpacing = 1.0;       // metres between interior samples of a big triangle whose
                                      // corners agree (finds a region inside it)
    uint32_t maxSamplesPerEdge = 16;
};

struct RegionStats {
    uint32_t edgesCut = 0;          // edges split where the primary changes
    uint32_t facesCentreSplit = 0;  // triangles split at their centre (a region inside one)
    uint32_t fragmentsMerged = 0;   // fragments relabelled into a neighbour
    uint32_t trianglesAdded = 0;    // triangles after minus triangles before
};

/// Sets StaticTriangle::primary on every triangle (kNoIndex only when primaryCount == 0),
/// splitting triangles as needed; a prop's (StaticGeometry::instanceIsProp) are not split and
/// all take the primary dominant at its lighting origin. Total area is preserved.
RegionStats assignPrimaryRegions(StaticGeometry& geometry, uint32_t primaryCount,
                                 const PrimaryIlluminanceFn& illuminance,
                                 const RegionOptions& options);

/// Primaries other than `own` with non-zero illuminance at any corner of the given triangles:
/// the lights this surface gives up, baked as secondary. Sorted ascending.
[[nodiscard]] std::vector<uint32_t> givenUpPrimaries(const StaticGeometry& geometry,
                                                     std::span<const StaticTriangle> triangles,
                                                     uint32_t own, uint32_t primaryCount,
                                                     const PrimaryIlluminanceFn& illuminance);

}  // namespace onelight::world
