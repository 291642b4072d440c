// MD3 models read and checked (md3_file.hpp).
#include "world/import/q3/md3_file.hpp"

#include <cmath>
#include <cstring>

#include "world/error.hpp"
#include "world/file_read.hpp"
#include "world/import/q3/md3_format.hpp"

namespace onelight::world::q3 {
namespace {

constexpr float kPi = 3.14159265358979f;

// A NUL-padded name of a record, clipped for messages.
template <size_t N>
std::string nameOf(const char (&field)[N]) {
    return std::string(field, strnlen(field, N));
}

template <typename Record>
Record recordAt(std::span<const uint8_t> bytes, uint64_t offset) {
    Record r;
    std::memcpy(&r, bytes.data() + offset, sizeof(Record));
    return r;
}

// Checks that `count` records of `Record` from `offset` lie inside [begin, end) of the file.
template <typename Record>
void checkBlock(const std::string& place, const char* what, int64_t offset, int64_t count,
                uint64_t begin, uint64_t end) {
    const uint64_t bytes = uint64_t(count) * sizeof(Record);
    if (offset < 0 || uint64_t(offset) < begin || uint64_t(offset) > end ||
        bytes > end - uint64_t(offset))
        throw Error(place + ": " + what + " at byte " + std::to_string(offset) + ", " +
                    std::to_string(count) + " of " + std::to_string(sizeof(Record)) +
                    " bytes, reach past bytes " + std::to_string(begin) + ".." +
                    std::to_string(end) + "; expected them inside");
}

void checkCount(const std::string& place, const char* what, int32_t count, int32_t least,
                int32_t most) {
    if (count < least || count > most)
        throw Error(place + ": " + std::to_string(count) + " " + what + "; expected " +
                    std::to_string(least) + ".." + std::to_string(most) + " (the games' limit)");
}

void checkFinite(const std::string& place, const char* what, const float* values, int n) {
    for (int i = 0; i < n; ++i)
        if (!std::isfinite(values[i]))
            throw Error(place + ": " + what + " is NaN or Inf; expected finite numbers");
}

Md3Surface readSurface(std::span<const uint8_t> bytes, uint64_t start, int32_t frameCount,
                       size_t index, const std::string& where) {
    std::string place = where + ": surface " + std::to_string(index);
    checkBlock<Md3SurfaceHeader>(place, "the surface header", int64_t(start), 1, 0, bytes.size());
    const Md3SurfaceHeader h = recordAt<Md3SurfaceHeader>(bytes, start);
    Md3Surface s;
    s.name = nameOf(h.name);
    place += " ('" + clipForMessage(s.name, 60) + "')";
    if (std::memcmp(h.magic, kMd3Magic, 4) != 0)
        throw Error(place + ": does not start with IDP3; expected a surface");
    if (h.frameCount != frameCount)
        throw Error(place + ": " + std::to_string(h.frameCount) + " frames; expected the model's " +
                    std::to_string(frameCount));
    checkCount(place, "shaders", h.shaderCount, 0, kMd3MaxShaders);
    checkCount(place, "vertices", h.vertexCount, 0, kMd3MaxVertices);
    checkCount(place, "triangles", h.triangleCount, 0, kMd3MaxTriangles);
    if (h.endOffset < int32_t(sizeof(Md3SurfaceHeader)) ||
        uint64_t(h.endOffset) > bytes.size() - start)
        throw Error(place + ": ends at byte " + std::to_string(int64_t(start) + h.endOffset) +
                    " of the file's " + std::to_string(bytes.size()) +
                    "; expected its end inside the file, after its header");
    const uint64_t end = start + uint64_t(h.endOffset);
    checkBlock<Md3Shader>(place, "shaders", int64_t(start) + h.shadersOffset, h.shaderCount, start,
                          end);
    checkBlock<Md3Triangle>(place, "triangles", int64_t(start) + h.trianglesOffset, h.triangleCount,
                            start, end);
    checkBlock<Md3TexCoord>(place, "texture coordinates", int64_t(start) + h.texCoordsOffset,
                            h.vertexCount, start, end);
    checkBlock<Md3Vertex>(place, "vertices", int64_t(start) + h.verticesOffset,
                          int64_t(h.vertexCount) * frameCount, start, end);
    for (int32_t k = 0; k < h.shaderCount; ++k)
        s.shaders.push_back(nameOf(recordAt<Md3Shader>(bytes, start + uint64_t(h.shadersOffset) +
                                                                  uint64_t(k) * sizeof(Md3Shader))
                                       .name));
    s.vertexCount = uint32_t(h.vertexCount);
    s.indices.reserve(size_t(h.triangleCount) * 3);
    for (int32_t t = 0; t < h.triangleCount; ++t) {
        const Md3Triangle tri = recordAt<Md3Triangle>(
            bytes, start + uint64_t(h.trianglesOffset) + uint64_t(t) * sizeof(Md3Triangle));
        for (int32_t i : tri.indices) {
            if (i < 0 || i >= h.vertexCount)
                throw Error(place + ": triangle " + std::to_string(t) + " names vertex " +
                            std::to_string(i) + " of " + std::to_string(h.vertexCount) +
                            "; expected an index into the surface's vertices");
            s.indices.push_back(uint32_t(i));
        }
    }
    s.texCoords.reserve(size_t(h.vertexCount));
    for (int32_t v = 0; v < h.vertexCount; ++v) {
        const Md3TexCoord st = recordAt<Md3TexCoord>(
            bytes, start + uint64_t(h.texCoordsOffset) + uint64_t(v) * sizeof(Md3TexCoord));
        checkFinite(place + ": vertex " + std::to_string(v), "its texture coordinate", st.st, 2);
        s.texCoords.emplace_back(st.st[0], st.st[1]);
    }
    const size_t total = size_t(h.vertexCount) * size_t(frameCount);
    s.positions.reserve(total);
    s.normals.reserve(total);
    for (size_t k = 0; k < total; ++k) {
        const Md3Vertex v =
            recordAt<Md3Vertex>(bytes, start + uint64_t(h.verticesOffset) + k * sizeof(Md3Vertex));
        s.positions.emplace_back(float(v.position[0]) * kMd3PositionScale,
                                 float(v.position[1]) * kMd3PositionScale,
                                 float(v.position[2]) * kMd3PositionScale);
        s.normals.push_back(md3Normal(v.normal));
    }
    return s;
}

}  // namespace

glm::vec3 md3Normal(int16_t encoded) {
    const uint16_t bits = uint16_t(encoded);
    const float a = float((bits >> 8) & 0xff) * (2.0f * kPi / 256.0f);
    const float b = float(bits & 0xff) * (2.0f * kPi / 256.0f);
    return {std::cos(a) * std::sin(b), std::sin(a) * std::sin(b), std::cos(b)};
}

Md3Model parseMd3(std::span<const uint8_t> bytes, const std::string& where) {
    if (bytes.size() < sizeof(Md3Header))
        throw Error(where + ": " + std::to_string(bytes.size()) +
                    " bytes; expected an MD3 of at least " + std::to_string(sizeof(Md3Header)) +
                    " (its header)");
    const Md3Header h = recordAt<Md3Header>(bytes, 0);
    if (std::memcmp(h.magic, kMd3Magic, 4) != 0)
        throw Error(where + ": does not start with IDP3; expected a Quake 3 model (MD3)");
    if (h.version != kMd3Version)
        throw Error(where + ": MD3 version " + std::to_string(h.version) + "; expected " +
                    std::to_string(kMd3Version));
    checkCount(where, "frames", h.frameCount, 1, kMd3MaxFrames);
    checkCount(where, "tags", h.tagCount, 0, kMd3MaxTags);
    checkCount(where, "surfaces", h.surfaceCount, 0, kMd3MaxSurfaces);
    checkBlock<Md3Frame>(where, "frames", h.framesOffset, h.frameCount, 0, bytes.size());
    checkBlock<Md3Tag>(where, "tags", h.tagsOffset, int64_t(h.tagCount) * h.frameCount, 0,
                       bytes.size());
    Md3Model m;
    m.name = nameOf(h.name);
    for (int32_t f = 0; f < h.frameCount; ++f) {
        const Md3Frame r =
            recordAt<Md3Frame>(bytes, uint64_t(h.framesOffset) + uint64_t(f) * sizeof(Md3Frame));
        const std::string place = where + ": frame " + std::to_string(f);
        checkFinite(place, "its bounds", r.boundsMin, 3);
        checkFinite(place, "its bounds", r.boundsMax, 3);
        checkFinite(place, "its origin", r.localOrigin, 3);
        checkFinite(place, "its radius", &r.radius, 1);
        Md3FrameInfo info;
        info.name = nameOf(r.name);
        info.boundsMin = {r.boundsMin[0], r.boundsMin[1], r.boundsMin[2]};
        info.boundsMax = {r.boundsMax[0], r.boundsMax[1], r.boundsMax[2]};
        info.localOrigin = {r.localOrigin[0], r.localOrigin[1], r.localOrigin[2]};
        info.radius = r.radius;
        m.frames.push_back(info);
    }
    m.tagCount = uint32_t(h.tagCount);
    for (int64_t t = 0; t < int64_t(h.tagCount) * h.frameCount; ++t) {
        const Md3Tag r =
            recordAt<Md3Tag>(bytes, uint64_t(h.tagsOffset) + uint64_t(t) * sizeof(Md3Tag));
        Md3TagPose pose;
        pose.name = nameOf(r.name);
        const std::string place = where + ": frame " + std::to_string(t / h.tagCount) + " tag '" +
                                  clipForMessage(pose.name, 60) + "'";
        checkFinite(place, "its origin", r.origin, 3);
        checkFinite(place, "its axes", &r.axis[0][0], 9);
        pose.origin = {r.origin[0], r.origin[1], r.origin[2]};
        for (int c = 0; c < 3; ++c) pose.axes[c] = {r.axis[c][0], r.axis[c][1], r.axis[c][2]};
        m.tags.push_back(pose);
    }
    if (h.surfaceCount > 0 && h.surfacesOffset < 0)
        throw Error(where + ": surfaces at byte " + std::to_string(h.surfacesOffset) +
                    "; expected an offset inside the file");
    uint64_t at = uint64_t(std::max(h.surfacesOffset, 0));
    for (int32_t s = 0; s < h.surfaceCount; ++s) {
        m.surfaces.push_back(readSurface(bytes, at, h.frameCount, size_t(s), where));
        at += uint64_t(recordAt<Md3SurfaceHeader>(bytes, at).endOffset);
    }
    return m;
}

uint32_t checkedMd3Frame(const Md3Model& model, int64_t frame, const std::string& where) {
    if (frame < 0 || uint64_t(frame) >= model.frames.size())
        throw Error(where + ": frame " + std::to_string(frame) + " of a model of " +
                    std::to_string(model.frames.size()) + " frames; expected 0.." +
                    std::to_string(model.frames.size() - 1));
    return uint32_t(frame);
}

}  // namespace onelight::world::q3
