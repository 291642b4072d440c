#include "world/package/collision_section.hpp"

#include <cmath>
#include <cstring>

#include "world/error.hpp"
#include "world/package/format.hpp"

namespace onelight::package {
namespace {

template <typename T>
void append(std::vector<uint8_t>& out, const T& value) {
    const size_t at = out.size();
    out.resize(at + sizeof(T));
    std::memcpy(out.data() + at, &value, sizeof(T));
}

template <typename T>
T readAt(const std::vector<uint8_t>& bytes, size_t offset) {
    T value;
    std::memcpy(&value, bytes.data() + offset, sizeof(T));
    return value;
}

bool finite3(const float v[3]) {
    return std::isfinite(v[0]) && std::isfinite(v[1]) && std::isfinite(v[2]);
}

void checkCount(const std::string& at, const char* what, uint32_t count, uint32_t limit) {
    if (count > limit)
        throw world::Error(at + what + " " + std::to_string(count) + "; expected at most " +
                           std::to_string(limit));
}

}  // namespace

std::vector<RawSection> encodeCollisionSections(const world::LevelCollision& c) {
    std::vector<RawSection> out;
    if (c.empty()) return out;
    RawSection brushes;
    brushes.id = kSectionCollision;
    brushes.elementSize = 1;
    append(brushes.bytes,
           DiskCollisionHeader{uint32_t(c.planes.size()), uint32_t(c.sidePlanes.size()),
                               uint32_t(c.brushes.size()), 0});
    for (const world::CollisionPlane& p : c.planes)
        append(brushes.bytes, DiskCollisionPlane{{p.normal.x, p.normal.y, p.normal.z}, p.distance});
    for (uint32_t plane : c.sidePlanes) append(brushes.bytes, plane);
    for (const world::CollisionBrush& b : c.brushes)
        append(brushes.bytes, DiskCollisionBrush{b.firstSide, b.sideCount, b.contents, b.mover});
    brushes.count = uint32_t(brushes.bytes.size());
    out.push_back(std::move(brushes));

    RawSection triggers;
    triggers.id = kSectionTriggers;
    triggers.elementSize = sizeof(DiskTrigger);
    for (const world::Trigger& t : c.triggers)
        append(triggers.bytes, DiskTrigger{uint32_t(t.kind),
                                           {t.boundsMin.x, t.boundsMin.y, t.boundsMin.z},
                                           {t.boundsMax.x, t.boundsMax.y, t.boundsMax.z},
                                           {t.target.x, t.target.y, t.target.z},
                                           t.targetYaw,
                                           t.mover});
    triggers.count = uint32_t(c.triggers.size());
    out.push_back(std::move(triggers));
    return out;
}

world::LevelCollision decodeCollisionSections(const RawSection* brushes, const RawSection* triggers,
                                              uint32_t moverCount, const std::string& name) {
    world::LevelCollision c;
    if (brushes) {
        const std::string at = name + ": section collision: ";
        const std::vector<uint8_t>& bytes = brushes->bytes;
        if (brushes->elementSize != 1 || bytes.size() != brushes->count ||
            bytes.size() < sizeof(DiskCollisionHeader))
            throw world::Error(at + std::to_string(bytes.size()) + " bytes; expected a header of " +
                               std::to_string(sizeof(DiskCollisionHeader)) +
                               " bytes and its arrays");
        const auto h = readAt<DiskCollisionHeader>(bytes, 0);
        checkCount(at, "planeCount", h.planeCount, kMaxCollisionPlanes);
        checkCount(at, "sideCount", h.sideCount, kMaxCollisionSides);
        checkCount(at, "brushCount", h.brushCount, kMaxCollisionBrushes);
        if (h.reserved != 0) throw world::Error(at + "reserved is not 0");
        const uint64_t expected = sizeof(DiskCollisionHeader) +
                                  uint64_t(h.planeCount) * sizeof(DiskCollisionPlane) +
                                  uint64_t(h.sideCount) * sizeof(uint32_t) +
                                  uint64_t(h.brushCount) * sizeof(DiskCollisionBrush);
        if (bytes.size() != expected)
            throw world::Error(at + std::to_string(bytes.size()) + " bytes; expected " +
                               std::to_string(expected) + " for its header's counts");
        size_t offset = sizeof(DiskCollisionHeader);
        c.planes.reserve(h.planeCount);
        for (uint32_t i = 0; i < h.planeCount; ++i, offset += sizeof(DiskCollisionPlane)) {
            const auto p = readAt<DiskCollisionPlane>(bytes, offset);
            if (!finite3(p.normal) || !std::isfinite(p.distance))
                throw world::Error(at + "plane " + std::to_string(i) +
                                   " is NaN or Inf; expected finite numbers");
            const glm::vec3 n(p.normal[0], p.normal[1], p.normal[2]);
            if (!(std::fabs(glm::length(n) - 1.0f) <= 1e-3f))
                throw world::Error(at + "plane " + std::to_string(i) + " has a normal of length " +
                                   std::to_string(glm::length(n)) + "; expected 1");
            c.planes.push_back({n, p.distance});
        }
        c.sidePlanes.reserve(h.sideCount);
        for (uint32_t i = 0; i < h.sideCount; ++i, offset += sizeof(uint32_t)) {
            const auto plane = readAt<uint32_t>(bytes, offset);
            if (plane >= h.planeCount)
                throw world::Error(at + "side " + std::to_string(i) + " has plane " +
                                   std::to_string(plane) + "; expected < " +
                                   std::to_string(h.planeCount));
            c.sidePlanes.push_back(plane);
        }
        c.brushes.reserve(h.brushCount);
        for (uint32_t i = 0; i < h.brushCount; ++i, offset += sizeof(DiskCollisionBrush)) {
            const auto b = readAt<DiskCollisionBrush>(bytes, offset);
            const std::string brush = at + "brush " + std::to_string(i);
            if (b.sideCount < 1 || b.firstSide > h.sideCount ||
                b.sideCount > h.sideCount - b.firstSide)
                throw world::Error(brush + " has sides " + std::to_string(b.firstSide) + " + " +
                                   std::to_string(b.sideCount) +
                                   "; expected at least one, inside " + "the " +
                                   std::to_string(h.sideCount) + " side planes");
            if (b.contents == 0 || (b.contents & ~world::kPlayerSolidContents) != 0)
                throw world::Error(brush + " has contents " + std::to_string(b.contents) +
                                   "; expected solid (1), player clip (65536) or both");
            if (b.mover != world::kNoIndex && b.mover >= moverCount)
                throw world::Error(brush + " has mover " + std::to_string(b.mover) +
                                   "; expected one of the level's " + std::to_string(moverCount) +
                                   " movers, or none");
            c.brushes.push_back({b.firstSide, b.sideCount, b.contents, b.mover});
        }
    }
    if (triggers) {
        const std::string at = name + ": section triggers: ";
        if (triggers->elementSize != sizeof(DiskTrigger) ||
            uint64_t(triggers->count) * sizeof(DiskTrigger) != triggers->bytes.size())
            throw world::Error(at + "records of " + std::to_string(triggers->elementSize) +
                               " bytes; expected " + std::to_string(sizeof(DiskTrigger)));
        checkCount(at, "count", triggers->count, kMaxTriggers);
        for (uint32_t i = 0; i < triggers->count; ++i) {
            const auto t = readAt<DiskTrigger>(triggers->bytes, size_t(i) * sizeof(DiskTrigger));
            const std::string trigger = at + "trigger " + std::to_string(i);
            if (t.kind < uint32_t(world::TriggerKind::kPush) || t.kind > world::kTriggerKindLast)
                throw world::Error(trigger + " has kind " + std::to_string(t.kind) +
                                   "; expected 1 (push), 2 (teleport), 3 (hurt), 4 (use a mover) "
                                   "or 5 (raise a plat)");
            if (!finite3(t.boundsMin) || !finite3(t.boundsMax) || !finite3(t.target) ||
                !std::isfinite(t.targetYaw))
                throw world::Error(trigger + " is NaN or Inf; expected finite numbers");
            for (int k = 0; k < 3; ++k)
                if (!(t.boundsMin[k] <= t.boundsMax[k]))
                    throw world::Error(trigger + " has boundsMin[" + std::to_string(k) +
                                       "] above boundsMax; expected min <= max");
            const bool usesMover = t.kind >= uint32_t(world::TriggerKind::kUseMover);
            if (usesMover ? t.mover >= moverCount : t.mover != world::kNoIndex)
                throw world::Error(trigger + " has mover " + std::to_string(t.mover) +
                                   (usesMover ? "; expected one of the level's " +
                                                    std::to_string(moverCount) + " movers"
                                              : "; expected none for its kind"));
            world::Trigger out;
            out.kind = world::TriggerKind(t.kind);
            out.boundsMin = glm::vec3(t.boundsMin[0], t.boundsMin[1], t.boundsMin[2]);
            out.boundsMax = glm::vec3(t.boundsMax[0], t.boundsMax[1], t.boundsMax[2]);
            out.target = glm::vec3(t.target[0], t.target[1], t.target[2]);
            out.targetYaw = t.targetYaw;
            out.mover = t.mover;
            c.triggers.push_back(out);
        }
    }
    return c;
}

}  // namespace onelight::package
