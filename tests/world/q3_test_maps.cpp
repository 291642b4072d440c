#include "tests/world/q3_test_maps.hpp"

#include <gtest/gtest.h>
#include <zip.h>

#include <algorithm>
#include <cstring>
#include <fstream>
#include <iterator>

#include "tests/world/world_test_support.hpp"

namespace onelight::test {

using namespace world::q3;

Quake3BspBuilder::Quake3BspBuilder(float side, std::string_view shader) {
    BspShader s{};
    shader.copy(s.name, std::min(shader.size(), sizeof s.name - 1));
    shaders.push_back(s);
    for (const auto& p : {std::pair{0.0f, 0.0f}, {1.0f, 0.0f}, {1.0f, 1.0f}, {0.0f, 1.0f}}) {
        BspVertex v{};
        v.position[0] = p.first * side;
        v.position[1] = p.second * side;
        v.normal[2] = 1.0f;
        vertices.push_back(v);
    }
    indices = {0, 1, 2, 0, 2, 3};
    BspSurface f{};
    f.type = kSurfacePlanar;
    f.vertexCount = 4;
    f.indexCount = 6;
    f.fog = -1;
    surfaces.push_back(f);
}

int32_t Quake3BspBuilder::addBoxModel(const std::vector<std::pair<glm::vec3, glm::vec3>>& boxes,
                                      int32_t shader) {
    if (models.empty()) {  // the world: the constructor's square goes
        vertices.clear();
        indices.clear();
        surfaces.clear();
    }
    BspModel model{};
    model.firstSurface = int32_t(surfaces.size());
    model.firstBrush = int32_t(brushes.size());
    glm::vec3 lo(1e30f), hi(-1e30f);
    for (const auto& [a, b] : boxes) {
        lo = glm::min(lo, a);
        hi = glm::max(hi, b);
        BspBrush brush{int32_t(brushSides.size()), 6, shader};
        brushes.push_back(brush);
        for (int axis = 0; axis < 3; ++axis)
            for (int sign : {1, -1}) {
                BspBrushPlane plane{};
                plane.normal[axis] = float(sign);
                plane.dist = sign > 0 ? b[axis] : -a[axis];
                brushSides.push_back({int32_t(planes.size()), shader});
                planes.push_back(plane);
                // The face: four corners on the plane, wound so the normal faces out.
                const int u = (axis + 1) % 3, v = (axis + 2) % 3;
                BspSurface f{};
                f.shader = shader;
                f.fog = -1;
                f.type = kSurfacePlanar;
                f.firstVertex = int32_t(vertices.size());
                f.vertexCount = 4;
                f.firstIndex = int32_t(indices.size());
                f.indexCount = 6;
                f.lightmap = -1;
                for (const auto& [su, sv] : {std::pair{0, 0}, {1, 0}, {1, 1}, {0, 1}}) {
                    BspVertex vertex{};
                    vertex.position[axis] = sign > 0 ? b[axis] : a[axis];
                    vertex.position[u] = su ? b[u] : a[u];
                    vertex.position[v] = sv ? b[v] : a[v];
                    vertex.texcoord[0] = vertex.position[u] / 64.0f;
                    vertex.texcoord[1] = vertex.position[v] / 64.0f;
                    vertex.normal[axis] = float(sign);
                    vertices.push_back(vertex);
                }
                // (u, v) is right-handed about +axis: counter-clockwise seen from +axis.
                if (sign > 0)
                    indices.insert(indices.end(), {0, 1, 2, 0, 2, 3});
                else
                    indices.insert(indices.end(), {0, 2, 1, 0, 3, 2});
                surfaces.push_back(f);
            }
    }
    model.surfaceCount = int32_t(surfaces.size()) - model.firstSurface;
    model.brushCount = int32_t(brushes.size()) - model.firstBrush;
    for (int k = 0; k < 3; ++k) {
        model.mins[k] = lo[k];
        model.maxs[k] = hi[k];
    }
    models.push_back(model);
    return int32_t(models.size()) - 1;
}

Quake3BspBuilder floorSquare(uint8_t lightmapValue) {
    Quake3BspBuilder b(256.0f, "textures/test/floor");
    for (BspVertex& v : b.vertices) {
        v.lightmap[0] = v.position[0] / 256.0f;
        v.lightmap[1] = v.position[1] / 256.0f;
    }
    b.surfaces[0].lightmap = lightmapValue ? 0 : -1;
    if (lightmapValue) b.lightmaps.assign(kLightmapPageBytes, lightmapValue);
    return b;
}

Bytes Quake3BspBuilder::bytes() const {
    BspHeader h{};
    std::memcpy(h.magic, kBspMagic, 4);
    h.version = kBspVersion;
    Bytes body;  // the lumps, after the header
    const auto lump = [&](Lump l, const void* data, size_t size) {
        h.lumps[l] = {int32_t(sizeof(BspHeader) + body.size()), int32_t(size)};
        const auto* b = static_cast<const uint8_t*>(data);
        body.insert(body.end(), b, b + size);
        body.resize((body.size() + 3) / 4 * 4, 0);
    };
    lump(kLumpEntities, entities.c_str(), entities.size() + 1);
    lump(kLumpShaders, shaders.data(), shaders.size() * sizeof(BspShader));
    lump(kLumpDrawVerts, vertices.data(), vertices.size() * sizeof(BspVertex));
    lump(kLumpDrawIndexes, indices.data(), indices.size() * sizeof(int32_t));
    lump(kLumpSurfaces, surfaces.data(), surfaces.size() * sizeof(BspSurface));
    lump(kLumpLightmaps, lightmaps.data(), lightmaps.size());
    lump(kLumpPlanes, planes.data(), planes.size() * sizeof(BspBrushPlane));
    lump(kLumpModels, models.data(), models.size() * sizeof(BspModel));
    lump(kLumpBrushes, brushes.data(), brushes.size() * sizeof(BspBrush));
    lump(kLumpBrushSides, brushSides.data(), brushSides.size() * sizeof(BspBrushSide));
    lump(kLumpNodes, nodes.data(), nodes.size() * sizeof(BspNode));
    lump(kLumpLeafs, leafs.data(), leafs.size() * sizeof(BspLeaf));
    lump(kLumpVisibility, visibility.data(), visibility.size());
    Bytes out(sizeof h + body.size());
    std::memcpy(out.data(), &h, sizeof h);
    if (!body.empty()) std::memcpy(out.data() + sizeof h, body.data(), body.size());
    return out;
}

std::string Quake3BspBuilder::text() const {
    const Bytes b = bytes();
    return std::string(b.begin(), b.end());
}

std::string Quake3BspBuilder::write(const std::string& folder, const std::string& name) const {
    const std::filesystem::path path = freshFolder(folder) / (name + ".bsp");
    writeFile(path, bytes());
    return path.string();
}

void writeFile(const std::filesystem::path& path, std::string_view bytes) {
    if (path.has_parent_path()) std::filesystem::create_directories(path.parent_path());
    std::ofstream(path, std::ios::binary).write(bytes.data(), std::streamsize(bytes.size()));
}

void writeFile(const std::filesystem::path& path, const Bytes& bytes) {
    writeFile(path, std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()));
}

void writePk3(const std::filesystem::path& path,
              const std::vector<std::pair<std::string, std::string>>& files, bool stored) {
    if (path.has_parent_path()) std::filesystem::create_directories(path.parent_path());
    int error = 0;
    zip_t* zip = zip_open(path.c_str(), ZIP_CREATE | ZIP_TRUNCATE, &error);
    ASSERT_NE(zip, nullptr) << path;
    for (const auto& [name, data] : files) {
        zip_source_t* source = zip_source_buffer(zip, data.data(), data.size(), 0);
        ASSERT_NE(source, nullptr) << name;
        const zip_int64_t index = zip_file_add(zip, name.c_str(), source, ZIP_FL_OVERWRITE);
        ASSERT_GE(index, 0) << name;
        if (stored) {
            ASSERT_EQ(zip_set_file_compression(zip, zip_uint64_t(index), ZIP_CM_STORE, 0), 0);
        }
    }
    ASSERT_EQ(zip_close(zip), 0) << path;  // `files` outlive the close, which reads them
}

world::Quake3Options quake3GameIn(const std::filesystem::path& folder) {
    world::Quake3Options options;
    options.gameFolders = {folder.string()};
    return options;
}

std::string readFileText(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

std::string tgaImage(uint32_t width, const std::vector<glm::u8vec3>& texels) {
    const uint32_t height = width ? uint32_t(texels.size() / width) : 0;
    std::string out(18, '\0');
    out[2] = 2;  // uncompressed true colour
    out[12] = char(width & 255);
    out[13] = char(width >> 8);
    out[14] = char(height & 255);
    out[15] = char(height >> 8);
    out[16] = 24;
    out[17] = 0x20;  // top-left origin: rows top to bottom
    for (const glm::u8vec3& t : texels) out += {char(t.b), char(t.g), char(t.r)};  // BGR
    return out;
}

std::string tga(uint32_t size, glm::u8vec3 rgb) {
    return tgaImage(size, std::vector<glm::u8vec3>(size_t(size) * size, rgb));
}

}  // namespace onelight::test
