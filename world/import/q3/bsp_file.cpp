#include "world/import/q3/bsp_file.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "world/error.hpp"

namespace onelight::world::q3 {
namespace {

const char* const kLumpNames[kLumpCount] = {
    "entities",     "shaders",  "planes",    "nodes",       "leafs",     "leaf surfaces",
    "leaf brushes", "models",   "brushes",   "brush sides", "vertices",  "indices",
    "fogs",         "surfaces", "lightmaps", "light grid",  "visibility"};

template <typename Record>
std::vector<Record> readLump(std::span<const uint8_t> bytes, const BspHeader& header, Lump lump,
                             const std::string& where) {
    const BspLump& l = header.lumps[lump];
    const std::string name =
        std::string("lump ") + std::to_string(int(lump)) + " (" + kLumpNames[lump] + ")";
    if (l.offset < 0 || l.length < 0 || uint64_t(l.offset) + uint64_t(l.length) > bytes.size())
        throw Error(where + ": " + name + " at offset " + std::to_string(l.offset) + ", " +
                    std::to_string(l.length) + " bytes, is outside the file's " +
                    std::to_string(bytes.size()) + " bytes");
    if (l.length % int32_t(sizeof(Record)) != 0)
        throw Error(where + ": " + name + " holds " + std::to_string(l.length) +
                    " bytes; expected a multiple of its " + std::to_string(sizeof(Record)) +
                    "-byte records");
    std::vector<Record> out(size_t(l.length) / sizeof(Record));
    if (!out.empty()) std::memcpy(out.data(), bytes.data() + l.offset, size_t(l.length));
    return out;
}

std::string surfaceWhere(const std::string& where, size_t s) {
    return where + ": surface " + std::to_string(s);
}

void checkRange(const std::string& place, const char* what, int32_t first, int32_t count,
                size_t size, const char* lump) {
    if (first < 0 || count < 0 || uint64_t(first) + uint64_t(count) > size)
        throw Error(place + ": " + what + " " + std::to_string(first) + " + " +
                    std::to_string(count) + " is outside the " + std::to_string(size) + " " + lump +
                    "; expected a range inside them");
}

void checkSurface(const BspFile& bsp, size_t s, const std::string& where) {
    const BspSurface& f = bsp.surfaces[s];
    const std::string place = surfaceWhere(where, s);
    if (f.type < kSurfacePlanar || f.type > kSurfaceFlare)
        throw Error(place + ": type " + std::to_string(f.type) +
                    "; expected 1 (planar), 2 (patch), 3 (triangles) or 4 (flare)");
    if (f.shader < 0 || size_t(f.shader) >= bsp.shaders.size())
        throw Error(place + ": shader " + std::to_string(f.shader) + " of " +
                    std::to_string(bsp.shaders.size()) + "; expected an index into the shaders");
    if (f.type == kSurfaceFlare) return;  // drawn as a billboard; never read
    const size_t pages = bsp.lightmaps.size() / kLightmapPageBytes;
    // No lightmap lump: none, or external lightmap images (q3map2 -lightmapsize); the importer
    // then reads the vertex light.
    if (pages > 0 && f.lightmap >= 0 && size_t(f.lightmap) >= pages)
        throw Error(place + ": lightmap page " + std::to_string(f.lightmap) + " of " +
                    std::to_string(pages) + "; expected an index into the lightmap lump or < 0");
    checkRange(place, "vertices", f.firstVertex, f.vertexCount, bsp.vertices.size(), "vertices");
    if (f.type == kSurfacePatch) {
        if (f.patchWidth < 3 || f.patchHeight < 3 || f.patchWidth % 2 == 0 ||
            f.patchHeight % 2 == 0 || int64_t(f.patchWidth) * f.patchHeight != f.vertexCount)
            throw Error(place + ": a patch of " + std::to_string(f.patchWidth) + " x " +
                        std::to_string(f.patchHeight) + " controls with " +
                        std::to_string(f.vertexCount) +
                        " vertices; expected odd sizes >= 3 whose product is the vertex count");
        return;
    }
    checkRange(place, "indices", f.firstIndex, f.indexCount, bsp.indices.size(), "indices");
    if (f.indexCount % 3 != 0)
        throw Error(place + ": " + std::to_string(f.indexCount) +
                    " indices; expected whole triangles (a multiple of 3)");
    for (int32_t i = 0; i < f.indexCount; ++i) {
        const int32_t index = bsp.indices[size_t(f.firstIndex + i)];
        if (index < 0 || index >= f.vertexCount)
            throw Error(place + ": index " + std::to_string(f.firstIndex + i) + " is " +
                        std::to_string(index) + "; expected 0 .. " +
                        std::to_string(f.vertexCount - 1) + " (its vertices)");
    }
}

void checkIndex(const std::string& place, const char* what, int32_t index, size_t size,
                const char* lump) {
    if (index < 0 || size_t(index) >= size)
        throw Error(place + ": " + what + " " + std::to_string(index) + " of " +
                    std::to_string(size) + "; expected an index into the " + lump);
}

// The collision lumps: planes finite, every brush side's plane and shader, every brush's side
// range and shader, every model's brush range and bounds.
void checkBrushes(const BspFile& bsp, const std::string& where) {
    for (size_t p = 0; p < bsp.planes.size(); ++p) {
        const BspBrushPlane& plane = bsp.planes[p];
        for (float c : {plane.normal[0], plane.normal[1], plane.normal[2], plane.dist})
            if (!std::isfinite(c))
                throw Error(where + ": plane " + std::to_string(p) +
                            " is NaN or Inf; expected finite numbers");
    }
    for (size_t s = 0; s < bsp.brushSides.size(); ++s) {
        const std::string place = where + ": brush side " + std::to_string(s);
        checkIndex(place, "plane", bsp.brushSides[s].plane, bsp.planes.size(), "planes");
        checkIndex(place, "shader", bsp.brushSides[s].shader, bsp.shaders.size(), "shaders");
    }
    for (size_t b = 0; b < bsp.brushes.size(); ++b) {
        const std::string place = where + ": brush " + std::to_string(b);
        checkRange(place, "sides", bsp.brushes[b].firstSide, bsp.brushes[b].sideCount,
                   bsp.brushSides.size(), "brush sides");
        checkIndex(place, "shader", bsp.brushes[b].shader, bsp.shaders.size(), "shaders");
    }
    for (size_t m = 0; m < bsp.models.size(); ++m) {
        const BspModel& model = bsp.models[m];
        const std::string place = where + ": model " + std::to_string(m);
        checkRange(place, "brushes", model.firstBrush, model.brushCount, bsp.brushes.size(),
                   "brushes");
        for (int k = 0; k < 3; ++k)
            if (!std::isfinite(model.mins[k]) || !std::isfinite(model.maxs[k]))
                throw Error(place + ": bounds are NaN or Inf; expected finite numbers");
    }
}

// The world's BSP tree and the potentially visible set: every node's plane, its children a node
// later in the lump (so that every walk down the tree ends) or a leaf; every leaf's cluster -1
// (solid) or inside the visibility lump's; the lump's rows inside it and wide enough.
void checkTree(BspFile& bsp, std::span<const uint8_t> vis, const std::string& where) {
    if (!vis.empty()) {
        BspVisibilityHeader h;
        if (vis.size() < sizeof h)
            throw Error(where + ": lump 16 (visibility) holds " + std::to_string(vis.size()) +
                        " bytes; expected at least its 8-byte header");
        std::memcpy(&h, vis.data(), sizeof h);
        const uint64_t rowBytes = (uint64_t(std::max(h.clusterCount, 0)) + 7) / 8;
        if (h.clusterCount < 0 || h.bytesPerCluster < 0 || uint64_t(h.bytesPerCluster) < rowBytes ||
            uint64_t(h.clusterCount) * uint64_t(h.bytesPerCluster) > vis.size() - sizeof h)
            throw Error(where + ": lump 16 (visibility): " + std::to_string(h.clusterCount) +
                        " clusters of " + std::to_string(h.bytesPerCluster) + " bytes in " +
                        std::to_string(vis.size() - sizeof h) +
                        " bytes; expected rows of at least one bit a cluster inside the lump");
        bsp.clusterCount = h.clusterCount;
        bsp.bytesPerCluster = h.bytesPerCluster;
        bsp.visibility.assign(
            vis.begin() + sizeof h,
            vis.begin() + sizeof h + size_t(h.clusterCount) * size_t(h.bytesPerCluster));
    }
    for (size_t n = 0; n < bsp.nodes.size(); ++n) {
        const BspNode& node = bsp.nodes[n];
        const std::string place = where + ": node " + std::to_string(n);
        checkIndex(place, "plane", node.plane, bsp.planes.size(), "planes");
        for (int32_t child : node.children) {
            const bool laterNode =
                child >= 0 && size_t(child) > n && size_t(child) < bsp.nodes.size();
            const bool leaf = child < 0 && int64_t(-1) - child < int64_t(bsp.leafs.size());
            if (!laterNode && !leaf)
                throw Error(place + ": child " + std::to_string(child) +
                            "; expected a node after it (of " + std::to_string(bsp.nodes.size()) +
                            ") or a leaf -(l + 1) of " + std::to_string(bsp.leafs.size()));
        }
    }
    for (size_t l = 0; l < bsp.leafs.size(); ++l) {
        // Without a visibility lump (q3map2 without -vis) the clusters are never looked up.
        const int32_t cluster = bsp.leafs[l].cluster;
        if (cluster < -1 || (bsp.clusterCount > 0 && cluster >= bsp.clusterCount))
            throw Error(where + ": leaf " + std::to_string(l) + ": cluster " +
                        std::to_string(cluster) + " of " + std::to_string(bsp.clusterCount) +
                        "; expected -1 (solid) or a cluster of the visibility lump");
    }
}

bool finite(const float* x, int n) {
    for (int i = 0; i < n; ++i)
        if (!std::isfinite(x[i])) return false;
    return true;
}

// Positions must be finite. q3map2 leaves fields it does not use unset, NaN at times: lightmap
// coordinates on surfaces without a lightmap page (the game never reads them), anything on a
// vertex no drawn surface reads, normals of some models. Those are replaced (0, or a zero normal
// the importer replaces); a field a surface does read is an error naming the vertex.
void checkVertices(BspFile& bsp, const std::string& where) {
    constexpr int32_t kUnread = -1;
    std::vector<int32_t> readBy(bsp.vertices.size(), kUnread);   // a surface reading it
    std::vector<int32_t> pagedBy(bsp.vertices.size(), kUnread);  // one reading its lightmap uv
    for (size_t s = 0; s < bsp.surfaces.size(); ++s) {
        const BspSurface& f = bsp.surfaces[s];
        if (f.type == kSurfaceFlare) continue;
        for (int32_t v = f.firstVertex; v < f.firstVertex + f.vertexCount; ++v) {
            readBy[size_t(v)] = int32_t(s);
            if (f.lightmap >= 0) pagedBy[size_t(v)] = int32_t(s);
        }
    }
    uint32_t normals = 0;
    for (size_t v = 0; v < bsp.vertices.size(); ++v) {
        BspVertex& x = bsp.vertices[v];
        const auto fault = [&](const char* field, int32_t surface, const std::string& how) {
            return Error(where + ": lump 10 (vertices): vertex " + std::to_string(v) +
                         " is NaN or Inf in its " + field +
                         (surface == kUnread ? std::string()
                                             : ", which surface " + std::to_string(surface) + how) +
                         "; expected finite numbers");
        };
        if (!finite(x.position, 3)) throw fault("position", readBy[v], " reads");
        if (!finite(x.texcoord, 2)) {
            if (readBy[v] != kUnread) throw fault("texture coordinates", readBy[v], " reads");
            x.texcoord[0] = x.texcoord[1] = 0.0f;
        }
        if (!finite(x.lightmap, 2)) {
            if (pagedBy[v] != kUnread)
                throw fault("lightmap coordinates", pagedBy[v],
                            " reads on lightmap page " +
                                std::to_string(bsp.surfaces[size_t(pagedBy[v])].lightmap));
            x.lightmap[0] = x.lightmap[1] = 0.0f;  // no page: never read
        }
        if (!finite(x.normal, 3)) {
            normals += readBy[v] != kUnread;
            const float* plane =
                readBy[v] == kUnread ? nullptr : bsp.surfaces[size_t(readBy[v])].lightmapVectors[2];
            for (int c = 0; c < 3; ++c)
                x.normal[c] = plane && bsp.surfaces[size_t(readBy[v])].type == kSurfacePlanar &&
                                      finite(plane, 3)
                                  ? plane[c]
                                  : 0.0f;  // the importer's default, up
        }
    }
    if (normals > 0)
        bsp.notes.push_back(
            where + ": " + std::to_string(normals) +
            " vertex normal(s) NaN or Inf, replaced by their plane's normal (up off planes)");
}

}  // namespace

std::string shaderName(const BspShader& shader) {
    return std::string(shader.name, strnlen(shader.name, sizeof shader.name));
}

BspFile parseBsp(std::span<const uint8_t> bytes, const std::string& where) {
    if (bytes.size() < sizeof(BspHeader))
        throw Error(where + ": " + std::to_string(bytes.size()) +
                    " bytes; expected a Quake 3 BSP (a " + std::to_string(sizeof(BspHeader)) +
                    "-byte header and its lumps)");
    BspHeader header;
    std::memcpy(&header, bytes.data(), sizeof header);
    if (std::memcmp(header.magic, kBspMagic, 4) != 0)
        throw Error(where + ": not a Quake 3 BSP (no IBSP magic)");
    if (header.version != kBspVersion)
        throw Error(where + ": IBSP version " + std::to_string(header.version) + "; expected " +
                    std::to_string(kBspVersion) + " (Quake 3, OpenArena)");
    BspFile bsp;
    const std::vector<char> text = readLump<char>(bytes, header, kLumpEntities, where);
    bsp.entities.assign(text.begin(), std::find(text.begin(), text.end(), '\0'));
    bsp.shaders = readLump<BspShader>(bytes, header, kLumpShaders, where);
    bsp.vertices = readLump<BspVertex>(bytes, header, kLumpDrawVerts, where);
    bsp.indices = readLump<int32_t>(bytes, header, kLumpDrawIndexes, where);
    bsp.surfaces = readLump<BspSurface>(bytes, header, kLumpSurfaces, where);
    bsp.lightmaps = readLump<uint8_t>(bytes, header, kLumpLightmaps, where);
    bsp.planes = readLump<BspBrushPlane>(bytes, header, kLumpPlanes, where);
    bsp.models = readLump<BspModel>(bytes, header, kLumpModels, where);
    bsp.brushes = readLump<BspBrush>(bytes, header, kLumpBrushes, where);
    bsp.brushSides = readLump<BspBrushSide>(bytes, header, kLumpBrushSides, where);
    bsp.nodes = readLump<BspNode>(bytes, header, kLumpNodes, where);
    bsp.leafs = readLump<BspLeaf>(bytes, header, kLumpLeafs, where);
    const std::vector<uint8_t> vis = readLump<uint8_t>(bytes, header, kLumpVisibility, where);
    if (bsp.lightmaps.size() % kLightmapPageBytes != 0)
        throw Error(where + ": lump 14 (lightmaps) holds " + std::to_string(bsp.lightmaps.size()) +
                    " bytes; expected whole pages of " + std::to_string(kLightmapPageBytes) +
                    " bytes");
    for (size_t s = 0; s < bsp.surfaces.size(); ++s) checkSurface(bsp, s, where);
    checkBrushes(bsp, where);
    checkTree(bsp, vis, where);
    checkVertices(bsp, where);
    return bsp;
}

}  // namespace onelight::world::q3
