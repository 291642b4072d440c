#include "bake/lightmap/lightmap_bake.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <tbb/enumerable_thread_specific.h>

#include "bake/lighting/direct_light.hpp"
#include "bake/lighting/sampling.hpp"
#include "bake/lightmap/direct_edges.hpp"
#include "bake/lightmap/lightmap_denoise.hpp"
#include "bake/parallel_for.hpp"

namespace onelight::bake {
namespace {

/// The random stream of texel (atlas, x, y): `pass` separates streams of later passes.
constexpr uint32_t kLightmapPass = 1;

const BakeLight* ownPrimary(const BakeLights& lights, uint32_t levelIndex) {
    for (const BakeLight& l : lights.lights)
        if (l.levelIndex == levelIndex) return &l;
    return nullptr;
}

/// Moves a sample point out of geometry it lies in: short rays along the surface over the
/// texel's footprint; a back face among them means the point is inside a solid (e.g. a floor
/// texel under a wall standing on it), so the point moves just past the nearest back face
/// whose far side still lies on the texel's own surface (within its bounds, `surfaceMin` and
/// `surfaceMax`). A move off the surface would leave the level: the end wall of a corridor
/// whose sides stand in front of its edges has texels buried in a side wall, and the side
/// wall's underside is nearer to some of them than its inner face, but below it is the
/// outside, where the sky leaked in as bright dots at the corridor's corners.
glm::vec3 moveOutOfGeometry(const BakeScene& scene, const glm::vec3& origin,
                            const glm::vec3& normal, float texelSize, const glm::vec3& surfaceMin,
                            const glm::vec3& surfaceMax, RayCounts& rays, bool& moved) {
    const Frame frame = frameAround(normal);
    const float offset = scene.rayOffset();
    const float reach = 0.7072f * texelSize + 2.0f * offset;
    const glm::vec3 directions[4] = {frame.t, -frame.t, frame.b, -frame.b};
    const glm::vec3 lo = surfaceMin - glm::vec3(offset), hi = surfaceMax + glm::vec3(offset);
    float nearest = reach;
    glm::vec3 result = origin;
    moved = false;
    for (const glm::vec3& d : directions) {
        const SurfaceHit hit = scene.intersect(origin, d, reach, rays.probe);
        if (!hit.found || !hit.backFace) continue;
        moved = true;  // inside a solid, whether or not a way out is found
        const glm::vec3 to = origin + d * (hit.distance + 2.0f * offset);
        const bool onSurface =
            glm::all(glm::greaterThanEqual(to, lo)) && glm::all(glm::lessThanEqual(to, hi));
        if (onSurface && hit.distance < nearest) {
            nearest = hit.distance;
            result = to;
        }
    }
    return result;
}

/*
   Secondary irradiance at a texel (point x, normal n), own primary P:
     E_sec = sum_{l != P} E_l (n . w_l) V_l  +  int_{H(n)} L_ind(x, w) (n . w) dw
   Direct part: E_l and w_l analytic (lights.hpp), V_l by stratified shadow rays shared among
   the lights that reach the texel by their importance Y(E_l (n.w_l)) (direct_light.hpp).
   Indirect part: w_i cosine-distributed on a rotated Hammersley set (pdf (n . w) / pi), so
     int L (n . w) dw ~ (1/N) sum_i L(w_i) (n . w_i) / pdf(w_i) = (pi / N) sum_i L(w_i)
   where L(w_i) = traceRadiance (every bounce of every light, and the sky on escape).
   Emissive surfaces and a sky image: with each w_i one emission sample l_i (an emitter point
   drawn by power or a sky direction drawn by the image, radiance.hpp sampleEmission), the two
   combined by the power heuristic: the sample adds L_e (n . l_i) / p_e(l_i) x w_e(l_i), the
   emission or sky w_i reaches counts with 1 - w_e(w_i).
   The indirect part is then filtered with the texel's neighbours (lightmap_denoise.hpp).
   Direction: d = 1/2 sum (Y(E_k) w_k) / sum Y(E_k) over the same terms (luminance-weighted).
                  +--------------------------------------------------------------------+
                  | E_sec ~ sum_{l != P} E_l (n.w_l) V_l + (pi / N) sum_i L(w_i)        |
                  +--------------------------------------------------------------------+
   Its estimated noise: the sample standard deviation of pi Y(L(w_i)) over sqrt(N).
*/

}  // namespace

/// The texel's origin, its own primary's shadow mask and the other lights' shadowed light.
TexelEstimate estimateTexelDirect(const BakeScene& scene, const BakeLights& lights,
                                  const world::CompiledLevel& level, const TexelSample& sample,
                                  const LightmapSettings& settings, RayCounts& rays) {
    TexelEstimate out;
    Rng rng{seedFrom(sample.atlas, sample.x, sample.y, kLightmapPass)};
    const glm::vec3 n = sample.normal;
    glm::vec3 origin = sample.position + n * scene.rayOffset();
    const world::Surface& surface = level.surfaces[sample.surface];
    origin = moveOutOfGeometry(scene, origin, n, sample.texelSize, surface.boundsMin,
                               surface.boundsMax, rays, out.moved);
    out.origin = origin;

    // Visibility is sampled from `origin` (on the surface); the unshadowed light E_l (n.w_l)
    // at the texel centre, which lies past the triangle's edge for an edge texel: bilinear
    // filtering then reads the edge's own value at a chart border (texel_placement.hpp).
    const glm::vec3 centre = out.moved ? origin : sample.centre + n * scene.rayOffset();

    const BakeLight* own = ownPrimary(lights, surface.primaryLight);
    if (own) {
        const LightIncidence incidence = lightIncidence(*own, origin);
        const float v =
            lightVisibility(scene, *own, incidence, origin, settings.shadowSamples, rng, rays);
        out.mask = static_cast<uint8_t>(std::lround(v * 255.0f));
        const LightIncidence atCentre = lightIncidence(*own, centre);
        out.ownDirect = atCentre.irradiance * (std::max(0.0f, glm::dot(n, atCentre.direction)) * v);
    }
    std::vector<LightTerm> terms;
    std::vector<LightIncidence> atCentre;
    for (const uint32_t l : lightsNear(lights, origin)) {
        const BakeLight& light = lights.lights[l];
        if (&light == own) continue;
        const LightIncidence incidence = lightIncidence(light, origin);
        const LightIncidence centreIncidence = lightIncidence(light, centre);
        const float cosine = glm::dot(n, centreIncidence.direction);
        if (glm::dot(n, incidence.direction) <= 0.0f || cosine <= 0.0f ||
            centreIncidence.irradiance == glm::vec3(0.0f))
            continue;
        terms.push_back({l, incidence, luminance(centreIncidence.irradiance) * cosine,
                         !settings.transport.sampleLights});
        atCentre.push_back(centreIncidence);
    }
    estimateVisibilities(scene, lights, terms, origin, settings.shadowSamples, rng, rays);
    for (size_t t = 0; t < terms.size(); ++t) {
        const glm::vec3 e =
            atCentre[t].irradiance * (glm::dot(n, atCentre[t].direction) * terms[t].visibility);
        out.direct += glm::dvec3(e);
        out.directDirection += double(luminance(e)) * glm::dvec3(atCentre[t].direction);
        out.directLuminance += double(luminance(e));
        out.directOpenLuminance += double(terms[t].importance);
    }
    return out;
}

namespace {

/// The texel's indirect light by `count` gathering directions, each a path (or, with a cache
/// in `transport`, a ray that reads the cache where it lands), seeded for pass `pass`.
void estimateIndirect(const BakeScene& scene, const BakeLights& lights, const TexelSample& sample,
                      uint32_t count, const TransportSettings& transport, uint32_t pass,
                      TexelEstimate& out, RayCounts& rays) {
    out.indirect = glm::dvec3(0.0);
    out.indirectDirection = glm::dvec3(0.0);
    out.indirectLuminance = 0.0;
    out.noise = 0.0;
    if (count == 0) return;
    Rng rng{seedFrom(sample.atlas, sample.x, sample.y, kLightmapPass + 1 + pass)};
    const glm::vec3 n = sample.normal;
    const glm::vec3 origin = out.origin;
    const Frame frame = frameAround(n);
    const float s0 = rng.next(), s1 = rng.next();
    const bool emission = samplesEmission(lights);
    double sumY2 = 0.0, inverseDistances = 0.0;
    for (uint32_t i = 0; i < count; ++i) {
        const glm::vec3 w = glm::normalize(
            frame.toWorld(sampleCosineHemisphere(rotatedHammersley(i, count, s0, s1))));
        const float pdf = glm::dot(n, w) / glsl::PI;
        FirstHit first;
        glm::vec3 e = glsl::PI *
                      traceRadiance(scene, lights, transport, origin, w,
                                    RayCone{sample.texelSize, sampleSpread(2.0f * glsl::PI, count)},
                                    rng, rays, &first, emission ? pdf : 0.0f);
        if (first.found) inverseDistances += 1.0 / std::max(double(first.distance), 1e-6);
        out.indirectDirection += double(luminance(e)) * glm::dvec3(w);
        if (emission) {
            const EmissionEstimate l = sampleEmission(scene, lights, origin, n, rng, rays);
            if (l.pdf > 0.0f) {
                const float cosine = glm::dot(n, l.direction);
                const glm::vec3 el =
                    l.radianceOverPdf * cosine * powerHeuristic(l.pdf, cosine / glsl::PI);
                out.indirectDirection += double(luminance(el)) * glm::dvec3(l.direction);
                e += el;
            }
        }
        const double y = luminance(e);
        out.indirect += glm::dvec3(e);
        out.indirectLuminance += y;
        sumY2 += y * y;
    }
    const double inv = 1.0 / count;
    out.indirect *= inv;
    out.indirectDirection *= inv;
    out.indirectLuminance *= inv;
    const double mean = out.indirectLuminance;
    out.noise = std::sqrt(std::max(0.0, sumY2 * inv - mean * mean) * inv);
    out.harmonicDistance = inverseDistances > 0.0
                               ? static_cast<float>(double(count) / inverseDistances)
                               : std::numeric_limits<float>::infinity();
}

/// Progress units of the final gather per texel: its rays over a cache pass's.
uint64_t finalPassUnits(const LightmapSettings& settings) {
    return settings.bouncePasses > 0
               ? std::max<uint64_t>(1,
                                    settings.indirectSamples / std::max(1u, settings.cacheSamples))
               : 1;
}

// The final gather's near field, in cache points' reaches (TransportSettings::cacheNearField).
constexpr float kFinalGatherNearField = 1.0f;

/*
   Cached bounces (Jacobi iteration over the texels): E_0 = the texels' direct light (every
   light, the own primary included, shadowed); pass k gathers cacheSamples cosine directions
   per texel whose rays read the cache of pass k - 1 where they land (radiance.hpp), so
     E_ind,k(x) = (pi / N) sum_i Lo_{k-1}(y_i),
     Lo_{k-1}(y) = albedo w(y, x) / pi (E_0 + E_ind,k-1)(y)
   holds bounces 1..k (w: the diffuse's energy weight seen from x, 1 - the specular lobe's
   directional albedo, as a traced bounce has it). Every pass draws a texel's directions from the
   same random stream, so the passes apply one fixed operator G (E_ind,k = G (E_0 + E_ind,k-1)) and
   E_k - E_k-1 is exactly G^k E_0, the k-th bounce, free of the passes' independent noise. (With a
   fresh stream per pass the differences were mostly noise: the measured ratio below swung from 0.13
   to the 0.9 clamp, and the tail with it.) The bounces beyond the last pass K are the tail of a
   series whose ratio r is measured over the level: r = sum Y(E_K - E_K-1) / sum Y(E_K-1 - E_K-2),
   clamped to [0, 0.9], and E_ind = E_K + (E_K - E_K-1) r / (1 - r) (exact for an enclosure of
   uniform albedo, where r = albedo). Reusing G costs a bias of order 1 / N where a path returns to
   a texel it left (G_xy G_yx reuses x's directions). The final gather of each texel then reads this
   cache.
*/
RadianceCache bounceCache(const BakeScene& scene, const BakeLights& lights,
                          const std::vector<TexelSample>& samples,
                          const std::vector<TexelEstimate>& direct,
                          const LightmapSettings& settings, Progress* progress,
                          tbb::enumerable_thread_specific<RayCounts>& rays) {
    const size_t n = samples.size();
    // Only texels whose centre lies on their triangle hold light for hits to read. An edge
    // texel traces from the triangle's border (texel_placement.hpp), where a concave corner
    // sees its neighbour wall at grazing angles: a hit beside the border would read that
    // darker corner value instead of the light where it landed, a loss in every pass (a room's
    // bounces then decayed 8% faster than its albedo). Hits near a border read the nearest
    // inner texel, or, when none is in reach, are traced on.
    std::vector<CachePoint> points(n);
    for (size_t i = 0; i < n; ++i)
        points[i] = {direct[i].origin, samples[i].centreInside ? samples[i].texelSize : 0.0f,
                     samples[i].normal};
    RadianceCache cache = makeRadianceCache(std::move(points));
    for (size_t i = 0; i < n; ++i)
        cache.direct[i] = glm::vec3(direct[i].direct) + direct[i].ownDirect;
    TransportSettings transport = settings.transport;
    transport.cache = &cache;
    std::vector<glm::vec3> previous(n, glm::vec3(0.0f)), beforePrevious(n, glm::vec3(0.0f));
    std::vector<glm::vec3> next(n);
    for (uint32_t pass = 0; pass < settings.bouncePasses; ++pass) {
        bake::parallelFor(tbb::blocked_range<size_t>(0, n, 16), [&](const auto& r) {
            RayCounts& local = rays.local();
            for (size_t i = r.begin(); i != r.end(); ++i) {
                if (!samples[i].centreInside) continue;  // never read (above)
                TexelEstimate e;
                e.origin = direct[i].origin;
                estimateIndirect(scene, lights, samples[i], settings.cacheSamples, transport, 0, e,
                                 local);
                next[i] = glm::vec3(e.indirect);
            }
            if (progress) progress->advance(r.size());
        });
        beforePrevious.swap(previous);
        previous = cache.indirect;
        cache.indirect = next;
    }
    if (settings.bouncePasses >= 2) {
        double last = 0.0, before = 0.0;
        for (size_t i = 0; i < n; ++i) {
            last += double(luminance(cache.indirect[i] - previous[i]));
            before += double(luminance(previous[i] - beforePrevious[i]));
        }
        const double r = before > 0.0 ? std::clamp(last / before, 0.0, 0.9) : 0.0;
        const float tail = static_cast<float>(r / (1.0 - r));
        for (size_t i = 0; i < n; ++i)
            cache.indirect[i] = glm::max(
                cache.indirect[i] + (cache.indirect[i] - previous[i]) * tail, glm::vec3(0.0f));
    }
    return cache;
}

/*
   The two parts of a texel the probes' specular needs apart (docs/lighting.md "Normalisation"):
   - The baked punctual lights' direct light E_d = sum_l E_l (n.w_l) V_l as one light from their
     luminance-weighted mean direction w = normalize(sum_l Y(E_l (n.w_l) V_l) w_l), whose
     irradiance facing it, E_d / (n.w), returns E_d at the surface normal. (n.w > 0: every term
     has n.w_l > 0.)
   - The rest (bounces, sky, emitters: the denoised gathering) at the surface normal, the pixel's
     side of the probes' statistic.
*/
void splitForSpecular(const TexelEstimate& e, const DenoisedIndirect& d, glm::vec3 normal,
                      world::LightmapTexel& t) {
    const glm::vec3 direct = glm::max(glm::vec3(e.direct), glm::vec3(0.0f));
    const double length = glm::length(e.directDirection);
    if (direct != glm::vec3(0.0f) && length > 0.0) {
        t.directLight = glm::vec3(e.directDirection / length);
        const float cosine = std::max(glm::dot(normal, t.directLight), 1e-3f);
        t.directIrradiance = direct / cosine;
    }
    t.indirectIrradiance = glm::max(glm::vec3(d.indirect), glm::vec3(0.0f));
}

}  // namespace

uint64_t lightmapWorkUnits(size_t allSamples, size_t ownedSamples,
                           const LightmapSettings& settings) {
    // Cached: the direct pass and the bounce passes over every texel, one unit a texel each.
    // Paths: the direct pass over the owned texels only. Then the final gather of the owned.
    const uint64_t before = settings.bouncePasses > 0
                                ? uint64_t(allSamples) * (1 + settings.bouncePasses)
                                : uint64_t(ownedSamples);
    return before + uint64_t(ownedSamples) * finalPassUnits(settings);
}

LightmapStats bakeLightmapTexels(const BakeScene& scene, const BakeLights& lights,
                                 const world::CompiledLevel& level,
                                 const std::vector<TexelSample>& samples,
                                 const LightmapSettings& settings, uint64_t texelBegin,
                                 uint64_t texelEnd, world::BakedLighting& baked, Progress* progress,
                                 RadianceCache* cacheOut) {
    std::vector<uint32_t> owned;
    for (uint32_t i = 0; i < samples.size(); ++i)
        if (samples[i].texel >= texelBegin && samples[i].texel < texelEnd) owned.push_back(i);
    return bakeLightmapTexels(scene, lights, level, samples, settings, owned, baked, progress,
                              cacheOut);
}

LightmapStats bakeLightmapTexels(const BakeScene& scene, const BakeLights& lights,
                                 const world::CompiledLevel& level,
                                 const std::vector<TexelSample>& samples,
                                 const LightmapSettings& settings,
                                 const std::vector<uint32_t>& ownedSamples,
                                 world::BakedLighting& baked, Progress* progress,
                                 RadianceCache* cacheOut) {
    const size_t n = samples.size();
    std::vector<uint8_t> isOwned(n, 0);
    for (const uint32_t i : ownedSamples) isOwned[i] = 1;
    const auto owned = [&](size_t i) { return isOwned[i] != 0; };
    // The denoiser reads neighbours up to its largest window away, in world space (across
    // seams into other charts): estimate those texels too. Every texel's estimate depends only
    // on its identity, so a neighbour gets the same value in whichever shard computes it.
    const TexelHash hash = makeTexelHash(samples);
    std::vector<uint8_t> needed(n, 0);
    if (settings.denoise.enabled)
        markDenoiseFootprint(hash, samples, ownedSamples, needed);
    else
        needed = isOwned;
    // Direct light: of every texel (the cached bounces read them all, and the shadow edges a
    // few texels around the owned ones; a texel's is cheap beside its gathering).
    const bool cached = settings.bouncePasses > 0;
    std::vector<TexelEstimate> estimates(n);
    tbb::enumerable_thread_specific<RayCounts> rays;
    bake::parallelFor(tbb::blocked_range<size_t>(0, n, 16), [&](const auto& r) {
        RayCounts& local = rays.local();
        uint64_t units = 0;
        for (size_t i = r.begin(); i != r.end(); ++i) {
            estimates[i] = estimateTexelDirect(scene, lights, level, samples[i], settings, local);
            units += cached || owned(i) ? 1 : 0;
        }
        if (progress) progress->advance(units);
    });
    // A moved texel's indirect part is its neighbours', denoised (lightmap_denoise.hpp).
    const std::vector<uint32_t> movedReads =
        movedTexelReads(level, samples, estimates, ownedSamples);
    if (settings.denoise.enabled)
        markDenoiseFootprint(hash, samples, movedReads, needed);
    else
        for (const uint32_t j : movedReads) needed[j] = 1;
    RadianceCache cache;
    TransportSettings finalTransport = settings.transport;
    if (cached) {
        cache = bounceCache(scene, lights, samples, estimates, settings, progress, rays);
        finalTransport.cache = &cache;
        // The final gather reads the cache no nearer than a cache point's reach: nearer, a
        // texel's constant value misses how fast the light it holds changes (a wall's foot
        // beside a sunlit patch read +29%; LightmapDenoise.DenoisedDefault...). The passes
        // read it at any distance: they feed the tail's ratio, which near paths would skew.
        finalTransport.cacheNearField = kFinalGatherNearField;
    }
    const uint64_t finalUnits = finalPassUnits(settings);
    bake::parallelFor(tbb::blocked_range<size_t>(0, n, 16), [&](const auto& r) {
        RayCounts& local = rays.local();
        uint64_t units = 0;
        for (size_t i = r.begin(); i != r.end(); ++i) {
            if (!needed[i]) continue;
            estimateIndirect(scene, lights, samples[i], settings.indirectSamples, finalTransport,
                             settings.bouncePasses, estimates[i], local);
            units += owned(i) ? finalUnits : 0;
        }
        if (progress) progress->advance(units);
    });

    std::vector<DirectEdge> edges(ownedSamples.size());
    if (settings.directEdges)
        edges = directEdges(scene, lights, level, samples, estimates, ownedSamples,
                            settings.shadowSamples, rays.local());
    else
        for (size_t k = 0; k < ownedSamples.size(); ++k) {
            const float v = directVisibility(estimates[ownedSamples[k]]);
            edges[k].distance = v >= 0.5f ? world::kDirectEdgeReach : -world::kDirectEdgeReach;
            edges[k].low = edges[k].high = v;
        }
    std::vector<DenoisedIndirect> movedReadsDenoised(movedReads.size());
    bake::parallelFor(tbb::blocked_range<size_t>(0, movedReads.size(), 64), [&](const auto& r) {
        RayCounts& local = rays.local();
        for (size_t k = r.begin(); k != r.end(); ++k)
            movedReadsDenoised[k] = denoiseTexel(scene, hash, samples, estimates, movedReads[k],
                                                 settings.denoise, local);
    });
    std::vector<double> denoisedNoise(ownedSamples.size(), 0.0);
    bake::parallelFor(tbb::blocked_range<size_t>(0, ownedSamples.size(), 64), [&](const auto& r) {
        RayCounts& local = rays.local();
        for (size_t k = r.begin(); k != r.end(); ++k) {
            const size_t i = ownedSamples[k];
            const TexelSample& s = samples[i];
            const TexelEstimate& e = estimates[i];
            // A moved texel's neighbour was denoised already, above.
            const auto read = std::lower_bound(movedReads.begin(), movedReads.end(), uint32_t(i));
            const DenoisedIndirect d =
                e.moved ? movedTexelIndirect(level, samples, estimates, i, movedReads,
                                             movedReadsDenoised)
                : read != movedReads.end() && *read == i
                    ? movedReadsDenoised[size_t(read - movedReads.begin())]
                    : denoiseTexel(scene, hash, samples, estimates, i, settings.denoise, local);
            denoisedNoise[k] = d.noise;
            world::LightmapTexel t;
            const double luminanceSum = e.directLuminance + d.indirectLuminance;
            t.irradiance = glm::max(glm::vec3(e.direct + d.indirect), glm::vec3(0.0f));
            t.direction =
                luminanceSum > 0.0
                    ? glm::vec3(0.5 * (e.directDirection + d.indirectDirection) / luminanceSum)
                    : glm::vec3(0.0f);
            if (glm::length(t.direction) > 0.5f) t.direction *= 0.5f / glm::length(t.direction);
            t.normalWeight = std::clamp(0.5f + glm::dot(s.normal, t.direction), 0.5f, 1.0f);
            t.flags = world::kLightmapTexelSampled;
            splitForSpecular(e, d, s.normal, t);
            t.directVisibility = directVisibility(e);
            t.directEdgeDistance = edges[k].distance;
            t.directEdgeWidth = edges[k].width;
            t.directEdgeLow = edges[k].low;
            t.directEdgeHigh = edges[k].high;
            t.directEdgeSharpness = edges[k].sharpness;
            if (!std::isfinite(t.irradiance.x + t.irradiance.y + t.irradiance.z) ||
                !std::isfinite(t.direction.x + t.direction.y + t.direction.z) ||
                !std::isfinite(t.directIrradiance.x + t.directIrradiance.y + t.directIrradiance.z +
                               t.indirectIrradiance.x + t.indirectIrradiance.y +
                               t.indirectIrradiance.z))
                t = {};
            baked.texels[s.texel] = t;
            baked.shadowMask[s.texel] = e.mask;
        }
    });
    if (cacheOut) *cacheOut = std::move(cache);
    LightmapStats stats;
    for (const RayCounts& r : rays) stats.rays += r;
    stats.texelsBaked = ownedSamples.size();
    for (const uint8_t flag : needed) stats.texelsGathered += flag;
    double noiseSum = 0.0, denoisedSum = 0.0, valueSum = 0.0;
    for (size_t k = 0; k < ownedSamples.size(); ++k) {
        const TexelEstimate& e = estimates[ownedSamples[k]];
        noiseSum += e.noise;
        denoisedSum += denoisedNoise[k];
        valueSum += e.directLuminance + e.indirectLuminance;
        stats.texelsMoved += e.moved ? 1 : 0;
    }
    stats.meanRelativeNoise = valueSum > 0.0 ? noiseSum / valueSum : 0.0;
    stats.meanRelativeNoiseDenoised = valueSum > 0.0 ? denoisedSum / valueSum : 0.0;
    return stats;
}

void dilateLightmaps(const world::CompiledLevel& level, world::BakedLighting& baked) {
    for (const world::Chart& chart : level.charts) {
        const world::Atlas& atlas = level.atlases[chart.atlas];
        const uint64_t base = world::atlasTexelOffset(level, chart.atlas);
        const auto index = [&](uint32_t x, uint32_t y) {
            return base + uint64_t(y) * atlas.width + x;
        };
        const uint32_t rings = chart.padding + 2;
        for (uint32_t ring = 0; ring < rings; ++ring) {
            std::vector<std::pair<uint64_t, world::LightmapTexel>> fills;
            std::vector<uint8_t> fillMasks;
            for (uint32_t y = chart.y; y < chart.y + chart.height; ++y) {
                for (uint32_t x = chart.x; x < chart.x + chart.width; ++x) {
                    if (baked.texels[index(x, y)].flags != 0) continue;
                    glm::vec3 irradiance(0.0f), direction(0.0f);
                    glm::vec3 directIrradiance(0.0f), directLight(0.0f), indirectIrradiance(0.0f);
                    float weight = 0.0f, visibility = 0.0f, distance = 0.0f, width = 0.0f;
                    float low = 0.0f, high = 0.0f, sharpness = 0.0f;
                    uint32_t mask = 0, count = 0;
                    for (int dy = -1; dy <= 1; ++dy) {
                        for (int dx = -1; dx <= 1; ++dx) {
                            const int nx = int(x) + dx, ny = int(y) + dy;
                            if ((dx == 0 && dy == 0) || nx < int(chart.x) || ny < int(chart.y) ||
                                nx >= int(chart.x + chart.width) ||
                                ny >= int(chart.y + chart.height))
                                continue;
                            const uint64_t k = index(uint32_t(nx), uint32_t(ny));
                            const world::LightmapTexel& t = baked.texels[k];
                            if (t.flags == 0) continue;
                            irradiance += t.irradiance;
                            direction += t.direction;
                            weight += t.normalWeight;
                            directIrradiance += t.directIrradiance;
                            directLight += luminance(t.directIrradiance) * t.directLight;
                            indirectIrradiance += t.indirectIrradiance;
                            visibility += t.directVisibility;
                            distance += t.directEdgeDistance;
                            width += t.directEdgeWidth;
                            low += t.directEdgeLow;
                            high += t.directEdgeHigh;
                            sharpness += t.directEdgeSharpness;
                            mask += baked.shadowMask[k];
                            ++count;
                        }
                    }
                    if (count == 0) continue;
                    world::LightmapTexel t;
                    const float inv = 1.0f / static_cast<float>(count);
                    t.irradiance = irradiance * inv;
                    t.direction = direction * inv;
                    t.normalWeight = std::clamp(weight * inv, 0.5f, 1.0f);
                    t.flags = world::kLightmapTexelDilated;
                    t.indirectIrradiance = indirectIrradiance * inv;
                    t.directVisibility = visibility * inv;
                    t.directEdgeDistance = distance * inv;
                    t.directEdgeWidth = width * inv;
                    t.directEdgeLow = low * inv;
                    t.directEdgeHigh = std::max(high * inv, t.directEdgeLow);
                    t.directEdgeSharpness = sharpness * inv;
                    if (glm::length(directLight) > 0.0f) {
                        t.directLight = glm::normalize(directLight);
                        t.directIrradiance = directIrradiance * inv;
                    }
                    fills.emplace_back(index(x, y), t);
                    fillMasks.push_back(static_cast<uint8_t>((mask + count / 2) / count));
                }
            }
            if (fills.empty()) break;
            for (size_t i = 0; i < fills.size(); ++i) {
                baked.texels[fills[i].first] = fills[i].second;
                baked.shadowMask[fills[i].first] = fillMasks[i];
            }
        }
    }
}

glm::vec3 lightmapTotalIrradiance(const BakeLights& lights, const world::CompiledLevel& level,
                                  const world::BakedLighting& baked, const TexelSample& sample) {
    const world::LightmapTexel& t = baked.texels[sample.texel];
    glm::vec3 e = t.irradiance;
    const world::Surface& surface = level.surfaces[sample.surface];
    if (const BakeLight* own = ownPrimary(lights, surface.primaryLight)) {
        const LightIncidence incidence = lightIncidence(*own, sample.position);
        const float cosine = std::max(0.0f, glm::dot(sample.normal, incidence.direction));
        e += incidence.irradiance * cosine *
             (static_cast<float>(baked.shadowMask[sample.texel]) / 255.0f);
    }
    return e;
}

}  // namespace onelight::bake
