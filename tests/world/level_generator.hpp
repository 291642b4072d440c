// A generated level for tests and the compile benchmark: a ground grid, box buildings of
// subdivided faces, primary/baked/effect lights, dynamic movers, a spawn, a probe, grid bounds
// and a camera. Deterministic for a given options value.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>

namespace onelight::test {

struct GeneratedLevelOptions {
    int groundCells = 160;  // ground is groundCells^2 quads
    int buildings = 80;
    int buildingCells = 16;  // quads per side of each building face (5 faces, open bottom)
    int dynamicCrates = 8;
    bool lights = true;
    uint32_t seed = 1;
};

/// Options whose static triangle count is close to `triangles` (about 80% buildings).
GeneratedLevelOptions optionsForTriangles(uint64_t triangles);

/// Static triangles the options produce (before the compile's splits).
uint64_t generatedTriangleCount(const GeneratedLevelOptions& options);

/// Writes NAME.gltf and NAME.bin into `folder`; returns the .gltf path.
std::string writeGeneratedLevel(const std::filesystem::path& folder, const std::string& name,
                                const GeneratedLevelOptions& options);

}  // namespace onelight::test
