// A Quake 3 BSP read from its bytes and checked: every lump inside the file and a whole number
// of records, every surface's shader, vertex and index ranges inside their lumps, every index
// inside its surface, patch grids odd-sized and complete, positions finite; every brush's
// side range, shader and planes, every model's brush range, planes and bounds finite; the
// world's BSP tree (every node's plane, every child a node later in the lump or a leaf, so that a
// walk ends) and every leaf's cluster inside the visibility lump's, whose rows fit it. Fields
// q3map2 leaves unset (NaN lightmap coordinates on a surface without a lightmap page, anything on
// a vertex no surface reads, NaN normals) are replaced, never refused (bsp_file.cpp
// checkVertices). Only the
// lumps the importer uses are kept (bsp_format.hpp).
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "world/import/q3/bsp_format.hpp"

namespace onelight::world::q3 {

struct BspFile {
    std::string entities;  // the entity lump's text
    std::vector<BspShader> shaders;
    std::vector<BspVertex> vertices;
    std::vector<int32_t> indices;  // relative to their surface's firstVertex
    std::vector<BspSurface> surfaces;
    std::vector<uint8_t> lightmaps;        // whole pages (bsp_format.hpp kLightmapPageBytes each)
    std::vector<BspBrushPlane> planes;     // finite
    std::vector<BspModel> models;          // brush ranges inside brushes, bounds finite
    std::vector<BspBrush> brushes;         // side ranges inside brushSides, shaders valid
    std::vector<BspBrushSide> brushSides;  // planes and shaders valid
    std::vector<BspNode> nodes;            // planes valid; children deeper in the lump (a tree)
    std::vector<BspLeaf> leafs;            // clusters -1 or < clusterCount
    int32_t clusterCount = 0;              // 0: the map has no visibility lump
    int32_t bytesPerCluster = 0;           // >= (clusterCount + 7) / 8
    std::vector<uint8_t> visibility;       // clusterCount rows of bytesPerCluster bytes
    std::vector<std::string> notes;        // what was replaced and how, one line each
};

/// Throws world::Error naming `where` (the file), the lump or surface, and what was expected.
[[nodiscard]] BspFile parseBsp(std::span<const uint8_t> bytes, const std::string& where);

/// A shader's name as a string (the record's NUL-padded 64 bytes).
[[nodiscard]] std::string shaderName(const BspShader& shader);

}  // namespace onelight::world::q3
