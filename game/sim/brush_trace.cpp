#include "brush_trace.hpp"

#include <limits>

namespace onelight::game {

BrushWorld makeBrushWorld(const world::LevelCollision& collision, size_t moverCount) {
    BrushWorld w;
    w.collision = &collision;
    w.moverPoses.resize(moverCount);
    const float inf = std::numeric_limits<float>::infinity();
    for (const world::CollisionBrush& b : collision.brushes) {
        glm::vec3 lo(-inf), hi(inf);
        for (uint32_t s = 0; s < b.sideCount; ++s) {
            const world::CollisionPlane& p =
                collision.planes[collision.sidePlanes[b.firstSide + s]];
            for (int k = 0; k < 3; ++k) {
                if (p.normal[k] == 1.0f) hi[k] = std::min(hi[k], p.distance);
                if (p.normal[k] == -1.0f) lo[k] = std::max(lo[k], -p.distance);
            }
        }
        w.brushMin.push_back(lo);
        w.brushMax.push_back(hi);
    }
    return w;
}

namespace {

// Quake 3's CM_TraceThroughBrush for a box (cm_trace.c), in doubles.
void traceThroughBrush(const world::LevelCollision& c, const world::CollisionBrush& brush,
                       glm::dvec3 start, glm::dvec3 end, glm::dvec3 mins, glm::dvec3 maxs,
                       double epsilon, BoxTrace& trace, double& fraction) {
    double enterFrac = -1.0, leaveFrac = 1.0;
    glm::dvec3 clipNormal(0.0);
    bool getOut = false, startOut = false;
    for (uint32_t s = 0; s < brush.sideCount; ++s) {
        const world::CollisionPlane& p = c.planes[c.sidePlanes[brush.firstSide + s]];
        const glm::dvec3 n(p.normal);
        // The box's corner deepest behind the plane (Quake's offsets[signbits]).
        const glm::dvec3 corner(n.x < 0.0 ? maxs.x : mins.x, n.y < 0.0 ? maxs.y : mins.y,
                                n.z < 0.0 ? maxs.z : mins.z);
        const double dist = double(p.distance) - glm::dot(corner, n);
        const double d1 = glm::dot(start, n) - dist;
        const double d2 = glm::dot(end, n) - dist;
        if (d2 > 0.0) getOut = true;  // the end is not in the brush
        if (d1 > 0.0) startOut = true;
        // Wholly in front of this face: no contact with the brush.
        if (d1 > 0.0 && (d2 >= epsilon || d2 >= d1)) return;
        if (d1 <= 0.0 && d2 <= 0.0) continue;  // does not cross this plane
        if (d1 > d2) {                         // enters
            const double f = std::max(0.0, (d1 - epsilon) / (d1 - d2));
            if (f > enterFrac) enterFrac = f, clipNormal = n;
        } else {  // leaves
            const double f = std::min(1.0, (d1 + epsilon) / (d1 - d2));
            if (f < leaveFrac) leaveFrac = f;
        }
    }
    if (!startOut) {
        trace.startSolid = true;
        if (!getOut) {
            trace.allSolid = true;
            fraction = 0.0;
        }
        return;
    }
    if (enterFrac < leaveFrac && enterFrac > -1.0 && enterFrac < fraction) {
        fraction = std::max(0.0, enterFrac);
        trace.normal = glm::vec3(clipNormal);
    }
}

}  // namespace

BoxTrace traceBox(const BrushWorld& w, glm::vec3 start, glm::vec3 end, glm::vec3 mins,
                  glm::vec3 maxs, float epsilon, TraceFilter filter) {
    BoxTrace trace;
    double fraction = 1.0;
    if (w.collision) {
        const world::LevelCollision& c = *w.collision;
        const glm::vec3 margin(epsilon);
        // The sweep in the space of the brushes met last (the world's, or one mover's).
        uint32_t space = world::kNoIndex;
        glm::vec3 from = start, to = end, lo = mins, hi = maxs;
        glm::quat toWorld(1.0f, 0.0f, 0.0f, 0.0f);
        glm::vec3 reachMin = glm::min(from, to) + lo - margin;
        glm::vec3 reachMax = glm::max(from, to) + hi + margin;
        for (size_t b = 0; b < c.brushes.size() && !trace.allSolid; ++b) {
            const uint32_t mover = c.brushes[b].mover;
            if (filter.brushes == TraceBrushes::kOneMover && mover != filter.mover) continue;
            if (filter.brushes == TraceBrushes::kButMover && mover == filter.mover) continue;
            if (!(c.brushes[b].contents & filter.contents)) continue;
            if (mover != space) {
                space = mover;
                from = start, to = end, lo = mins, hi = maxs;
                toWorld = glm::quat(1.0f, 0.0f, 0.0f, 0.0f);
                if (mover != world::kNoIndex && mover < w.moverPoses.size()) {
                    const BrushPose& pose = w.moverPoses[mover];
                    toWorld = pose.rotation;
                    const glm::quat toObject = glm::inverse(pose.rotation);
                    from = toObject * (start - pose.origin);
                    to = toObject * (end - pose.origin);
                    // The box's bounds in the object's space: its centre turned, its half sizes
                    // by the turn's absolute matrix.
                    const glm::vec3 centre = 0.5f * (mins + maxs), half = 0.5f * (maxs - mins);
                    const glm::mat3 r = glm::mat3_cast(toObject);
                    const glm::vec3 turnedHalf =
                        glm::abs(r[0]) * half.x + glm::abs(r[1]) * half.y + glm::abs(r[2]) * half.z;
                    const glm::vec3 turnedCentre = toObject * centre;
                    from += turnedCentre, to += turnedCentre;
                    lo = -turnedHalf, hi = turnedHalf;
                }
                reachMin = glm::min(from, to) + lo - margin;
                reachMax = glm::max(from, to) + hi + margin;
            }
            if (glm::any(glm::greaterThan(reachMin, w.brushMax[b])) ||
                glm::any(glm::lessThan(reachMax, w.brushMin[b])))
                continue;
            const double before = fraction;
            const bool wasStartSolid = trace.startSolid;
            traceThroughBrush(c, c.brushes[b], glm::dvec3(from), glm::dvec3(to), glm::dvec3(lo),
                              glm::dvec3(hi), double(epsilon), trace, fraction);
            if (fraction < before) {
                trace.normal = toWorld * trace.normal;
                trace.mover = mover;
            } else if (trace.startSolid && !wasStartSolid) {
                trace.mover = mover;
            }
        }
    }
    trace.fraction = float(fraction);
    trace.end = trace.fraction == 1.0f
                    ? end
                    : glm::vec3(glm::dvec3(start) + fraction * glm::dvec3(end - start));
    return trace;
}

}  // namespace onelight::game
