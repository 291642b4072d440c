#include "bake/lightmap/direct_edges.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <tbb/enumerable_thread_specific.h>

#include "bake/lighting/direct_light.hpp"
#include "bake/parallel_for.hpp"
#include "world/baked_lighting.hpp"

namespace onelight::bake {

float directVisibilityAt(const BakeScene& scene, const BakeLights& lights, uint32_t ownPrimary,
                         const glm::vec3& origin, const glm::vec3& n, uint32_t shadowSamples,
                         Rng& rng, RayCounts& rays) {
    std::vector<LightTerm> terms;
    for (const uint32_t l : lightsNear(lights, origin)) {
        const BakeLight& light = lights.lights[l];
        if (light.levelIndex == ownPrimary) continue;
        const LightIncidence incidence = lightIncidence(light, origin);
        const float cosine = glm::dot(n, incidence.direction);
        if (cosine <= 0.0f || incidence.irradiance == glm::vec3(0.0f)) continue;
        terms.push_back({l, incidence, luminance(incidence.irradiance) * cosine, false});
    }
    if (terms.empty()) return 1.0f;
    estimateVisibilities(scene, lights, terms, origin, shadowSamples, rng, rays);
    double open = 0.0, seen = 0.0;
    for (const LightTerm& t : terms) {
        open += double(t.importance);
        seen += double(t.importance) * double(t.visibility);
    }
    return open > 0.0 ? static_cast<float>(std::clamp(seen / open, 0.0, 1.0)) : 1.0f;
}

namespace {

/// The random stream of the edge lattice of texel (atlas, x, y) (lightmap_bake.cpp's passes use
/// 1 + pass).
constexpr uint32_t kEdgePass = 1000;

/// The least change of visibility across a texel's neighbourhood that is an edge to draw.
constexpr float kEdgeContrast = 0.25f;

/// How far the field may draw a sharp texel's own centre from the visibility its rays measured.
constexpr float kEdgeCentreTolerance = 0.1f;
/// An edge is drawn only where one of its levels is within this of none or all of the light.
constexpr float kEdgeEndLevel = 0.1f;

/// Halvings of a lattice step that place a crossing, and the half step of the visibility's
/// gradient there, texels (step 3 below).
constexpr uint32_t kEdgeBisections = 3;
constexpr float kEdgeGradientStep = 1.0f / 16.0f;

/// The crossings a texel's edge line is fitted through: within this many texels of the nearest,
/// and off their line by at most kEdgeFitSpread texels (standard deviation).
constexpr float kEdgeFitRadius = 0.75f;
constexpr float kEdgeFitSpread = 0.05f;

/*
   The distance field (Green 2007, "Improved alpha-tested magnification for vector textures and
   special effects", applied to a shadow as in Unreal's distance-field shadow maps), for an edge
   between two levels of visibility: none and all of one light, or, where other lights reach
   both sides, V_low and V_high.
   1. A texel straddles an edge when the visibility V at its centre and at its eight neighbours'
      (same surface) spans at least kEdgeContrast: V_low and V_high are their least and greatest,
      and the edge is where V crosses their mean, tau.
   2. Each straddling texel samples V on a lattice kEdgeLattice times finer over its footprint
      (points on its plane, between its neighbours' centres; a side towards no neighbour, or one
      moved out of a solid, is left out), with the texel's own shadow rays per point. Its levels
      widen to the lattice's least and greatest.
   3. Where two neighbouring lattice points (or a point and the next texel's lattice, or that
      texel's centre when it has none) lie on both sides of tau, the edge crosses between them:
      kEdgeBisections halvings of the segment (a visibility each) and the linear interpolation's
      tau in the last half place it to 1 / (kEdgeLattice 2^kEdgeBisections) of a texel. (The
      lattice alone left a sharp edge anywhere within its step: a 20 cm texel's edge wandered
      1.4 cm about its line.) The penumbra there is w = (V_high - V_low) / |grad V|, the gradient
      by central differences over +-kEdgeGradientStep texels along x and y (four visibilities):
      no narrower than 2 kEdgeGradientStep where the light changes within it. (The lattice's own
      step drew a sun's 4.5 cm penumbra 8.4 cm wide.)
   4. A texel within kDirectEdgeReach of a crossing keeps the distance to the edge's line through
      the crossings around the nearest one (fitEdgeLine), signed by its own side of tau, their
      width and levels. The runtime draws V = mix(V_low, V_high, clamp(0.5 + s / w)) there when
      w is within kDirectEdgeMaxWidth, one level is within kEdgeEndLevel of none or all of the
      light, and, where the texel's centre is beyond the penumbra, the level drawn there is
      within kEdgeCentreTolerance of its visibility. Otherwise (a soft edge; a third level:
      beside one light's sharp edge, texels lit by part of another were drawn at the levels'
      ends, and a real map's ceiling read 4.1% off its reference instead of 3.4%; or neither
      level at an end: several lamps partly seen on both sides, whose mix changes within the
      texels, and the field drew an edge across a real map's wall that the reference has not)
      the texel keeps its bilinear visibility: V_low = V_high = V, sharpness 0, and still the
      distance and width of a sharp edge's line (the field filtered between it and a drawn
      neighbour then crosses zero on the line, not between them). A texel near a crossing but
      beyond the line's reach is signed by its side of the nearest crossing's tau.
   Distances are in texels: a chart's texels are squares on its surface (uniform density).

   Texels under a solid (a floor's under a wall standing on it) trace their light from a point
   moved out of it (lightmap_bake.cpp moveOutOfGeometry), often the wall's other side: where that
   light differs from a neighbour's by the contrast, the bilinear filter carried it past the
   wall's foot (a sunlit wall's shadow side read 25 times its shadow along the foot, a sawtooth
   at the texels' pitch). For the field such a texel's visibility is the one at its own place on
   the plane (inside the solid: none), and the lattices sample points under solids like any
   other: the edge then falls at the solid's face, and the field draws the foot as dark as the
   shadow beside it. The texel keeps its own light and visibility.
*/
struct Crossing {
    glm::vec2 at{0.0f};  // texel coordinates in the atlas (texel centres at integers)
    float width = 0.0f;  // texels
    float low = 0.0f;    // the visibility on its dark side...
    float high = 1.0f;   // ...and on its lit side
    bool sharp = false;  // width within kDirectEdgeMaxWidth
};

struct Neighbourhood {
    const std::vector<TexelSample>& samples;
    const world::CompiledLevel& level;

    /// The sample of the texel (dx, dy) from sample i on the same surface; -1 when none.
    int64_t at(size_t i, int dx, int dy) const {
        const int64_t j = sampleAtOffset(level, samples, i, dx, dy);
        return j >= 0 && samples[size_t(j)].surface == samples[i].surface ? j : -1;
    }

    /// The same in the same chart, whichever of its surfaces: the texels the runtime filters
    /// together.
    int64_t atInChart(size_t i, int dx, int dy) const {
        const int64_t j = sampleAtOffset(level, samples, i, dx, dy);
        return j >= 0 && level.surfaces[samples[size_t(j)].surface].chart ==
                             level.surfaces[samples[i].surface].chart
                   ? j
                   : -1;
    }
};

/// The edge's line near a crossing: through the crossings within kEdgeFitRadius of it.
struct EdgeLine {
    bool fitted = false;  // enough crossings on a line; else the nearest crossing's distance
    glm::vec2 point{0.0f}, normal{0.0f};
    float width = 0.0f, low = 0.0f, high = 0.0f;  // their means
    bool sharp = false;                           // all of them
};

/*
   A texel's distance to the edge is to this line, not to the nearest crossing: the crossings are
   points a fraction of a texel apart along the edge, and the distance to the nearest overstates
   the distance to the edge by up to sqrt(h^2 + (gap / 2)^2) - h (0.06 texel at h = 0.5 with
   0.5-texel gaps): the edge drawn from such distances bulged between its crossings (a wander of
   0.52 cm about a 20 cm texel's line, 0.16 cm with the line). The line is the principal axis of
   the crossings around the nearest (a 2x2 covariance); where they do not lie on one (a corner:
   the smaller axis's spread above kEdgeFitSpread) the nearest's distance stays.
*/
EdgeLine fitEdgeLine(const std::vector<const Crossing*>& crossings, glm::vec2 around) {
    EdgeLine line;
    glm::vec2 mean(0.0f);
    float widths = 0.0f, lows = 0.0f, highs = 0.0f;
    bool sharp = true;
    uint32_t count = 0;
    for (const Crossing* c : crossings)
        if (glm::length(c->at - around) <= kEdgeFitRadius) {
            mean += c->at;
            widths += c->width;
            lows += c->low;
            highs += c->high;
            sharp = sharp && c->sharp;
            ++count;
        }
    if (count < 3) return line;
    mean /= float(count);
    float xx = 0.0f, xy = 0.0f, yy = 0.0f;
    for (const Crossing* c : crossings)
        if (glm::length(c->at - around) <= kEdgeFitRadius) {
            const glm::vec2 d = c->at - mean;
            xx += d.x * d.x;
            xy += d.x * d.y;
            yy += d.y * d.y;
        }
    xx /= float(count);
    xy /= float(count);
    yy /= float(count);
    const float angle = 0.5f * std::atan2(2.0f * xy, xx - yy);  // the larger axis
    const glm::vec2 along(std::cos(angle), std::sin(angle));
    const glm::vec2 normal(-along.y, along.x);
    const float spread =
        glm::dot(normal, glm::vec2(xx * normal.x + xy * normal.y, xy * normal.x + yy * normal.y));
    if (spread > kEdgeFitSpread * kEdgeFitSpread) return line;
    line.fitted = true;
    line.point = mean;
    line.normal = normal;
    line.width = widths / float(count);
    line.low = lows / float(count);
    line.high = highs / float(count);
    line.sharp = sharp;
    return line;
}

}  // namespace

std::vector<DirectEdge> directEdges(const BakeScene& scene, const BakeLights& lights,
                                    const world::CompiledLevel& level,
                                    const std::vector<TexelSample>& samples,
                                    const std::vector<TexelEstimate>& estimates,
                                    const std::vector<uint32_t>& wanted, uint32_t shadowSamples,
                                    RayCounts& rays) {
    const size_t n = samples.size();
    const Neighbourhood near{samples, level};
    const int reach = static_cast<int>(world::kDirectEdgeReach) + 1;  // texels searched
    std::vector<float> visibility(n);
    for (size_t i = 0; i < n; ++i) visibility[i] = directVisibility(estimates[i]);
    const auto usable = [&](int64_t j) { return j >= 0 && samples[size_t(j)].centreInside; };
    // 0. Texels moved out of a solid whose light differs from a neighbour's: their field's
    // visibility is their own place's.
    tbb::enumerable_thread_specific<RayCounts> localRays;
    const std::vector<float> stored = visibility;
    bake::parallelFor(tbb::blocked_range<size_t>(0, n, 64), [&](const auto& r) {
        RayCounts& counts = localRays.local();
        for (size_t i = r.begin(); i != r.end(); ++i) {
            if (!estimates[i].moved || !samples[i].centreInside) continue;
            bool differs = false;
            for (int dy = -1; dy <= 1 && !differs; ++dy)
                for (int dx = -1; dx <= 1 && !differs; ++dx) {
                    const int64_t j = near.at(i, dx, dy);
                    differs = j >= 0 && !estimates[size_t(j)].moved &&
                              std::abs(stored[size_t(j)] - stored[i]) >= kEdgeContrast;
                }
            if (!differs) continue;
            const TexelSample& s = samples[i];
            Rng rng{seedFrom(s.atlas, s.x, s.y, kEdgePass + 2)};
            visibility[i] = directVisibilityAt(
                scene, lights, level.surfaces[s.surface].primaryLight,
                s.centre + s.normal * scene.rayOffset(), s.normal, shadowSamples, rng, counts);
        }
    });
    // The least and greatest visibility of the texel centres around sample i (itself included).
    const auto levelsAround = [&](size_t i) {
        glm::vec2 levels(visibility[i]);
        for (int dy = -1; dy <= 1; ++dy)
            for (int dx = -1; dx <= 1; ++dx)
                if (const int64_t j = near.at(i, dx, dy); j >= 0)
                    levels = glm::vec2(std::min(levels.x, visibility[size_t(j)]),
                                       std::max(levels.y, visibility[size_t(j)]));
        return levels;
    };

    // 1. The straddling texels within `reach` of a wanted one.
    std::vector<uint8_t> isWanted(n, 0);
    for (const uint32_t i : wanted) isWanted[i] = 1;
    std::vector<uint8_t> straddles(n, 0);
    bake::parallelFor(tbb::blocked_range<size_t>(0, n, 256), [&](const auto& r) {
        for (size_t i = r.begin(); i != r.end(); ++i) {
            if (!usable(int64_t(i))) continue;
            const glm::vec2 levels = levelsAround(i);
            if (levels.y - levels.x < kEdgeContrast) continue;
            bool nearWanted = false;
            for (int dy = -reach; dy <= reach && !nearWanted; ++dy)
                for (int dx = -reach; dx <= reach && !nearWanted; ++dx) {
                    const int64_t j = near.atInChart(i, dx, dy);
                    nearWanted = j >= 0 && isWanted[size_t(j)];
                }
            straddles[i] = nearWanted ? 1 : 0;
        }
    });
    std::vector<uint32_t> straddling;
    std::vector<int32_t> rank(n, -1);
    for (size_t i = 0; i < n; ++i)
        if (straddles[i]) {
            rank[i] = int32_t(straddling.size());
            straddling.push_back(uint32_t(i));
        }

    // 2. Their lattices: kEdgeLattice^2 visibilities each, NaN where left out.
    constexpr uint32_t k = kEdgeLattice;
    const float step = 1.0f / float(k);
    std::vector<float> lattice(straddling.size() * k * k, std::numeric_limits<float>::quiet_NaN());
    // Each straddling texel's plane: metres per texel along x and y (none: no lattice).
    std::vector<std::pair<glm::vec3, glm::vec3>> frames(straddling.size());
    bake::parallelFor(tbb::blocked_range<size_t>(0, straddling.size(), 4), [&](const auto& r) {
        RayCounts& counts = localRays.local();
        for (size_t c = r.begin(); c != r.end(); ++c) {
            const size_t i = straddling[c];
            const TexelSample& s = samples[i];
            const int64_t right = near.at(i, 1, 0), left = near.at(i, -1, 0);
            const int64_t down = near.at(i, 0, 1), up = near.at(i, 0, -1);
            const auto axis = [&](int64_t after, int64_t before, glm::vec3& d) {
                if (after >= 0)
                    d = samples[size_t(after)].centre - s.centre;
                else if (before >= 0)
                    d = s.centre - samples[size_t(before)].centre;
                else
                    return false;
                return true;
            };
            glm::vec3 dPdx(0.0f), dPdy(0.0f);
            if (!axis(right, left, dPdx) || !axis(down, up, dPdy)) continue;
            frames[c] = {dPdx, dPdy};
            Rng rng{seedFrom(s.atlas, s.x, s.y, kEdgePass)};
            const uint32_t own = level.surfaces[s.surface].primaryLight;
            for (uint32_t b = 0; b < k; ++b)
                for (uint32_t a = 0; a < k; ++a) {
                    const float ox = (float(a) + 0.5f) * step - 0.5f;
                    const float oy = (float(b) + 0.5f) * step - 0.5f;
                    if ((ox > 0.0f && !usable(right)) || (ox < 0.0f && !usable(left)) ||
                        (oy > 0.0f && !usable(down)) || (oy < 0.0f && !usable(up)))
                        continue;
                    const glm::vec3 origin =
                        s.centre + ox * dPdx + oy * dPdy + s.normal * scene.rayOffset();
                    lattice[(c * k + b) * k + a] = directVisibilityAt(
                        scene, lights, own, origin, s.normal, shadowSamples, rng, counts);
                }
        }
    });

    // 3. The crossings in and around each lattice.
    std::vector<std::vector<Crossing>> crossings(straddling.size());
    bake::parallelFor(tbb::blocked_range<size_t>(0, straddling.size(), 4), [&](const auto& r) {
        RayCounts& counts = localRays.local();
        for (size_t c = r.begin(); c != r.end(); ++c) {
            const size_t i = straddling[c];
            const TexelSample& s = samples[i];
            Rng rng{seedFrom(s.atlas, s.x, s.y, kEdgePass + 1)};
            const uint32_t ownPrimary = level.surfaces[s.surface].primaryLight;
            // The visibility at texel coordinates q on this texel's plane.
            const auto visibilityAt = [&](glm::vec2 q) {
                const glm::vec2 o = q - glm::vec2(float(s.x), float(s.y));
                const glm::vec3 origin = s.centre + o.x * frames[c].first + o.y * frames[c].second +
                                         s.normal * scene.rayOffset();
                return directVisibilityAt(scene, lights, ownPrimary, origin, s.normal,
                                          shadowSamples, rng, counts);
            };
            const float* own = &lattice[c * k * k];
            glm::vec2 levels = levelsAround(i);
            for (uint32_t q = 0; q < k * k; ++q)
                if (!std::isnan(own[q]))
                    levels = glm::vec2(std::min(levels.x, own[q]), std::max(levels.y, own[q]));
            const float tau = 0.5f * (levels.x + levels.y);
            const glm::vec2 centre(float(s.x), float(s.y));
            const auto point = [&](uint32_t a, uint32_t b) {
                return centre + (glm::vec2(float(a), float(b)) + 0.5f) * step - 0.5f;
            };
            const auto cross = [&](float va, glm::vec2 pa, float vb, glm::vec2 pb) {
                if (std::isnan(va) || std::isnan(vb) || (va < tau) == (vb < tau)) return;
                for (uint32_t h = 0; h < kEdgeBisections; ++h) {
                    const glm::vec2 pm = 0.5f * (pa + pb);
                    const float vm = visibilityAt(pm);
                    if ((vm < tau) == (va < tau)) {
                        pa = pm;
                        va = vm;
                    } else {
                        pb = pm;
                        vb = vm;
                    }
                }
                const float t = std::clamp((tau - va) / (vb - va), 0.0f, 1.0f);
                const glm::vec2 at = pa + t * (pb - pa);
                const glm::vec2 dx(kEdgeGradientStep, 0.0f), dy(0.0f, kEdgeGradientStep);
                const glm::vec2 gradient =
                    glm::vec2(visibilityAt(at + dx) - visibilityAt(at - dx),
                              visibilityAt(at + dy) - visibilityAt(at - dy)) /
                    (2.0f * kEdgeGradientStep);
                // The distance over which V goes from one level to the other.
                const float g = glm::length(gradient) / (levels.y - levels.x);
                const bool sharp = g > 1.0f / world::kDirectEdgeMaxWidth;
                crossings[c].push_back(
                    {at, sharp ? 1.0f / g : world::kDirectEdgeMaxWidth, levels.x, levels.y, sharp});
            };
            // The value of the lattice point (a, b) of the texel beside this one at (dx, dy):
            // its own lattice's, else its centre's visibility.
            const auto beside = [&](int dx, int dy, uint32_t a, uint32_t b) {
                const int64_t j = near.at(i, dx, dy);
                if (j < 0 || !usable(j)) return std::numeric_limits<float>::quiet_NaN();
                const int32_t other = rank[size_t(j)];
                return other >= 0 ? lattice[(size_t(other) * k + b) * k + a]
                                  : visibility[size_t(j)];
            };
            for (uint32_t b = 0; b < k; ++b)
                for (uint32_t a = 0; a < k; ++a) {
                    const float v = own[b * k + a];
                    if (a + 1 < k) cross(v, point(a, b), own[b * k + a + 1], point(a + 1, b));
                    if (b + 1 < k) cross(v, point(a, b), own[(b + 1) * k + a], point(a, b + 1));
                }
            for (uint32_t q = 0; q < k; ++q) {
                const glm::vec2 x(1.0f, 0.0f), y(0.0f, 1.0f);
                cross(own[q * k + k - 1], point(k - 1, q), beside(1, 0, 0, q),
                      point(k - 1, q) + x * step);
                cross(own[q * k], point(0, q), beside(-1, 0, k - 1, q), point(0, q) - x * step);
                cross(own[(k - 1) * k + q], point(q, k - 1), beside(0, 1, q, 0),
                      point(q, k - 1) + y * step);
                cross(own[q], point(q, 0), beside(0, -1, q, k - 1), point(q, 0) - y * step);
            }
        }
    });
    for (const RayCounts& r : localRays) rays += r;

    // 4. Each wanted texel's distance to the edge: to the line fitted through the crossings
    // around the nearest one.
    std::vector<DirectEdge> out(wanted.size());
    bake::parallelFor(tbb::blocked_range<size_t>(0, wanted.size(), 64), [&](const auto& r) {
        std::vector<const Crossing*> found;
        for (size_t w = r.begin(); w != r.end(); ++w) {
            const size_t i = wanted[w];
            const float v = visibility[i];
            DirectEdge e;
            e.distance = v >= 0.5f ? world::kDirectEdgeReach : -world::kDirectEdgeReach;
            e.low = e.high = v;
            const glm::vec2 centre(float(samples[i].x), float(samples[i].y));
            found.clear();
            const Crossing* nearest = nullptr;
            float best = std::numeric_limits<float>::infinity();
            for (int dy = -reach; dy <= reach; ++dy)
                for (int dx = -reach; dx <= reach; ++dx) {
                    // The chart's crossings, whichever surface found them: the runtime filters
                    // the chart's texels together, so a texel of the next surface must be signed
                    // by the same edge.
                    const int64_t j = near.atInChart(i, dx, dy);
                    if (j < 0 || rank[size_t(j)] < 0) continue;
                    for (const Crossing& x : crossings[size_t(rank[size_t(j)])]) {
                        found.push_back(&x);
                        const float d = glm::length(x.at - centre);
                        if (d < best || (d == best && x.width < nearest->width)) {
                            best = d;
                            nearest = &x;
                        }
                    }
                }
            // A texel the field does not draw still enters its neighbours' filtered distance: it
            // is signed by its side of the nearest edge's levels' mean, not of 0.5. (Beside an
            // edge from 0.17 to 0.54, texels at 0.45-0.49 were signed dark, and where the filter
            // crossed zero between them and the edge's lit texels the runtime drew a second,
            // false edge: blotches with sharp outlines on a real map's wall.)
            if (nearest)
                e.distance = v >= 0.5f * (nearest->low + nearest->high) ? world::kDirectEdgeReach
                                                                        : -world::kDirectEdgeReach;
            if (nearest && best <= world::kDirectEdgeReach + kEdgeFitRadius) {
                EdgeLine line = fitEdgeLine(found, nearest->at);
                if (!line.fitted) {
                    line.width = nearest->width;
                    line.low = nearest->low;
                    line.high = nearest->high;
                    line.sharp = nearest->sharp;
                }
                const bool lit = v >= 0.5f * (line.low + line.high);
                const float d =
                    line.fitted ? std::abs(glm::dot(centre - line.point, line.normal)) : best;
                const float distance = std::min(d, world::kDirectEdgeReach) * (lit ? 1.0f : -1.0f);
                // The field must also draw the texel's own centre as its rays saw it, where it
                // draws a level (beyond the penumbra: inside it, the ramp's shape and the rays'
                // noise part them more).
                const bool onRamp = std::abs(distance) < 0.5f * line.width;
                const float drawn = distance > 0.0f ? line.high : line.low;
                if (line.sharp) {  // its distance on the field's own scale, drawn or not
                    e.distance = distance;
                    e.width = line.width;
                }
                const bool oneEnd = line.low <= kEdgeEndLevel || line.high >= 1.0f - kEdgeEndLevel;
                if (line.sharp && oneEnd &&
                    (onRamp || std::abs(drawn - v) <= kEdgeCentreTolerance)) {
                    e.low = line.low;
                    e.high = line.high;
                    e.sharpness = 1.0f;
                }
            }
            out[w] = e;
        }
    });
    return out;
}

}  // namespace onelight::bake
