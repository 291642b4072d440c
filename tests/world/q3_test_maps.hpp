// Hand-made Quake 3 files for the import tests: a BSP written record by record, pk3s written with
// libzip, uncompressed TGAs and plain files.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <glm/vec3.hpp>

#include "world/import/q3/bsp_file.hpp"
#include "world/import/q3/q3_import.hpp"

namespace onelight::test {

using Bytes = std::vector<uint8_t>;

/// A BSP written record by record: one shader, a square `side` units wide (4 vertices, 2
/// triangles) in the plane z = 0 facing +z on lightmap page 0 (coordinates 0, no page written),
/// and the entity text given. Tests change the records before `bytes()`.
struct Quake3BspBuilder {
    std::string entities = "{\n\"classname\" \"worldspawn\"\n}\n";
    std::vector<world::q3::BspShader> shaders;
    std::vector<world::q3::BspVertex> vertices;
    std::vector<int32_t> indices;
    std::vector<world::q3::BspSurface> surfaces;
    std::vector<uint8_t> lightmaps;  // whole pages, or empty
    std::vector<world::q3::BspBrushPlane> planes;
    std::vector<world::q3::BspModel> models;
    std::vector<world::q3::BspBrush> brushes;
    std::vector<world::q3::BspBrushSide> brushSides;
    std::vector<world::q3::BspNode> nodes;
    std::vector<world::q3::BspLeaf> leafs;
    std::vector<uint8_t> visibility;  // the lump whole (header and rows), or empty

    explicit Quake3BspBuilder(float side = 64.0f, std::string_view shader = "textures/test/wall");

    /// Appends brush model `models.size()` of axis-aligned boxes (map units, [lo, hi]) with
    /// shader `shader`: a solid brush and six outward quads per box (lightmap page none), its
    /// surfaces and brushes contiguous, its bounds theirs. Model 0 is the world: call this first
    /// with the world's boxes (the square of the constructor is then dropped). A box's
    /// coordinates are as stored: relative to its entity's origin for an origin-brush model.
    /// Returns the model's number.
    int32_t addBoxModel(const std::vector<std::pair<glm::vec3, glm::vec3>>& boxes,
                        int32_t shader = 0);

    [[nodiscard]] Bytes bytes() const;
    [[nodiscard]] std::string text() const;
    /// Writes NAME.bsp into the fresh folder `folder` (test::freshFolder) and returns its path.
    std::string write(const std::string& folder, const std::string& name) const;
};

/// A 256-unit floor square with shader textures/test/floor whose lightmap coordinates span one
/// page, every byte of it `lightmapValue` (0: no page, the surface vertex lit).
Quake3BspBuilder floorSquare(uint8_t lightmapValue);

/// Import options whose one game folder is `folder` (its pk3s and loose files).
world::Quake3Options quake3GameIn(const std::filesystem::path& folder);

/// The bytes of the file at `path` as a string (empty when it cannot be read).
std::string readFileText(const std::filesystem::path& path);

/// Writes `bytes` to `path`, making its folder.
void writeFile(const std::filesystem::path& path, std::string_view bytes);
void writeFile(const std::filesystem::path& path, const Bytes& bytes);

/// A pk3 (a zip archive, deflated as the game's are, or `stored` uncompressed) holding `files`
/// (name, bytes); a gtest failure if libzip refuses.
void writePk3(const std::filesystem::path& path,
              const std::vector<std::pair<std::string, std::string>>& files, bool stored = false);

/// An uncompressed 24-bit TGA, `width` x (texels / width), rows top to bottom.
std::string tgaImage(uint32_t width, const std::vector<glm::u8vec3>& texels);
/// An uncompressed 24-bit TGA `size` texels square, every texel `rgb`.
std::string tga(uint32_t size, glm::u8vec3 rgb);

}  // namespace onelight::test
