// Forward pass (the body of forward.frag and forward_masked.frag): one primary light with its
// shadow, the effect lights, baked secondary lighting, per pixel, for one material class
// (specialization constant). All lighting math is shared with C++ (shaders/lighting.glsl,
// material.glsl, brdf.glsl); this file only fetches and sums.
#include "frame_interface.glsl"
#include "lighting.glsl"
#include "material.glsl"
#include "env_brdf_fit.glsl"

layout(constant_id = SPEC_MATERIAL_CLASS) const int MATERIAL_CLASS = MATERIAL_FULL;
layout(constant_id = SPEC_ALPHA_MODE) const int ALPHA_MODE = ALPHA_MODE_OPAQUE;
layout(constant_id = SPEC_FLAT_SHADING) const int FLAT_SHADING = 0;  // 1: constant colour
// 1: the level supplies baked lighting (lightmaps, shadow masks, grid samples per object; or
// their placeholders in tests); 0: the neutral placeholder (a constant ambient of frame.baked.x
// lux, no baked shadow, a uniform environment of normalised radiance 1 / pi) without any fetch.
layout(constant_id = SPEC_BAKED_LIGHTING) const int BAKED_LIGHTING = 1;
layout(constant_id = SPEC_DIFFUSE_MODEL) const int DIFFUSE_MODEL = DIFFUSE_LAMBERT;
// 0: the frame as it was before the material pipeline (docs/materials.md), for its cost in
// onelight-bench-render only: no fold of the filter's spread into gloss, no cavity fetch, no
// energy-conservation weight on the direct lights.
layout(constant_id = SPEC_MATERIAL_PIPELINE) const int MATERIAL_PIPELINE = 1;
// 0: no probe in use (the package has none, e.g. an error budget dropped them, or --no-probes):
// the uniform environment of normalised radiance 1 / pi without walking or fetching anything.
layout(constant_id = SPEC_PROBES) const int PROBES = 1;
// The draws' needs (gpu_interface.glsl): each default keeps the choice at run time, from the
// material record and the draw's push; a value the draws all share compiles the rest out, the
// same displayed pixels with fewer fetches (RendererOptions::specializeDraws).
layout(constant_id = SPEC_TEXTURES) const int TEXTURES = ALL_TEXTURES;
layout(constant_id = SPEC_PRIMARY) const int PRIMARY = PRIMARY_ANY;
layout(constant_id = SPEC_SECONDARY) const int SECONDARY = SECONDARY_ANY;
// Per frame: the renderer draws with the pipelines without effect lights when the frame has none
// (llvmpipe runs a loop's body once even for no iteration, and both sides of every branch).
layout(constant_id = SPEC_EFFECT_LIGHTS) const int EFFECT_LIGHTS = 1;
layout(constant_id = SPEC_FEATURES_OFF) const int FEATURES_OFF = 0;  // benchmarks only
layout(constant_id = SPEC_PRIMARY_SHADOW) const int PRIMARY_SHADOW = 1;
layout(constant_id = SPEC_PRIMARY_FADE) const int PRIMARY_FADE = 1;
layout(constant_id = SPEC_DIRECT_EDGES) const int DIRECT_EDGES = 1;
bool featureOn(int feature) { return (FEATURES_OFF & feature) == 0; }

// Whether material m fills texture slot `slot` and the pipeline's materials may.
bool materialHas(GpuMaterial m, int slot) {
    return (TEXTURES & (1 << slot)) != 0 && hasTexture(m, slot);
}
// The primary light's type: the pipeline's when its draws share one, else the record's.
int primaryType(GpuLight light) {
    return PRIMARY >= PRIMARY_DIRECTIONAL ? PRIMARY - PRIMARY_DIRECTIONAL : int(light.info.x);
}
bool drawHasLightmap() {
    return SECONDARY == SECONDARY_LIGHTMAP || (SECONDARY == SECONDARY_ANY && draw.lightmapAtlas != NO_INDEX);
}
bool drawHasObjectLighting() {
    return SECONDARY == SECONDARY_OBJECT || (SECONDARY == SECONDARY_ANY && draw.objectLighting != NO_INDEX);
}

layout(location = 0) in vec3 inWorldPosition;
layout(location = 1) in vec3 inNormal;
layout(location = 2) in vec4 inTangent;
layout(location = 3) in vec2 inUv0;
layout(location = 4) in vec2 inUv1;

layout(location = 0) out vec4 outColor;

// Percentage-closer filtering in shadow view `view`: 2x2 taps, half a texel apart, of the
// hardware 2x2 bilinear comparison: a 3x3-texel tent for four fetches; 1 outside the view. The
// receiver is looked up 1.5 texels off its surface along the normal n, scaled by the sine of the
// light's angle to it (NoL): a surface the light grazes needs the whole offset against acne, one
// facing it hardly any, and a full offset there moves the point towards the light, past a thin
// wall's depth, so that a floor under a high sun was lit along the foot of every wall in front of
// it.
float shadowViewLookup(uint view, GpuLight light, vec3 p, vec3 n, float NoL) {
    GpuShadowView sv = shadowViews[view];
    float texelWorld = sv.params.x;
    if (sv.params.y > 0.5) texelWorld *= length(p - light.positionRange.xyz);
    float offset = 1.5 * texelWorld * clamp(sqrt(1.0 - NoL * NoL), 0.1, 1.0);
    vec4 clip = sv.viewProj * vec4(p + n * offset, 1.0);
    if (clip.w <= 0.0) return 1.0;
    vec3 ndc = clip.xyz / clip.w;
    vec2 uv = ndc.xy * 0.5 + 0.5;
    if (any(lessThan(uv, vec2(0.0))) || any(greaterThan(uv, vec2(1.0))) || ndc.z > 1.0) return 1.0;
    float texel = frame.shadowParams.z;
    float sum = 0.0;
    for (int y = 0; y < 2; ++y)
        for (int x = 0; x < 2; ++x)
            sum += texture(shadowMaps, vec4(uv + (vec2(x, y) - 0.5) * texel, float(view), ndc.z));
    return sum * 0.25;
}

// The primary's runtime shadow at p (l towards the light): an omni's cube face, a spot's view,
// or the sun's cascade, the nearest whose far distance reaches the point's view distance. Over
// the last tenth of a cascade's range the lookup blends into the next cascade's, so that a shadow
// edge crossing a split sharpens or softens gradually, not at a line. Loops, so that a CPU
// rasterizer stops once no pixel of its block needs another step (the second lookup is paid only
// in the bands).
float runtimeShadow(GpuLight light, int type, vec3 p, vec3 n, vec3 l, float viewDistance) {
    uint view = light.info.y;
    if (view == NO_INDEX) return 1.0;
    float NoL = clamp(dot(n, l), 0.0, 1.0);
    if (type == LIGHT_POINT) view += uint(cubeFace(p - light.positionRange.xyz));
    if (type != LIGHT_DIRECTIONAL) return shadowViewLookup(view, light, p, n, NoL);
    uint last = view + light.info.z - 1u;
    while (view < last && viewDistance > shadowViews[view].params.z) ++view;
    float split = shadowViews[view].params.z;
    float t = view < last ? clamp((viewDistance - 0.9 * split) / (0.1 * split), 0.0, 1.0) : 0.0;
    int lookups = t > 0.0 ? 2 : 1;
    float shadow = 0.0;
    for (int i = 0; i < lookups; ++i)
        shadow += (i == 0 ? 1.0 - t : t) * shadowViewLookup(view + uint(i), light, p, n, NoL);
    return shadow;
}

// Where a pixel lies in its dynamic object's lattice of grid samples (GpuObjectLighting): the
// first of the eight samples around it, the index steps to the next along each edge (0 along
// an edge of one sample) and its weights towards them. `single`: the object has one sample (the
// draw takes the one-load path; llvmpipe pays for every load a pixel makes).
struct ObjectLattice {
    uint first;
    uvec3 step;
    vec3 t;
    bool single;
};
ObjectLattice objectLattice(uint record) {
    ObjectLattice k = ObjectLattice(0u, uvec3(0u), vec3(0.0), true);
    uint stride = 1u;
    for (int a = 0; a < 3; ++a) {
        vec4 axis = objectLighting[record].axes[a];
        uint n = max(uint(axis.w), 1u);
        if (n > 1u) {
            float x = clamp(dot(inWorldPosition - objectLighting[record].from.xyz, axis.xyz), 0.0, 1.0) * float(n - 1u);
            uint s = min(uint(x), n - 2u);
            k.first += s * stride;
            k.step[a] = stride;
            k.t[a] = x - float(s);
            k.single = false;
        }
        stride *= n;
    }
    return k;
}

// The pixel's place in its dynamic object's lattice, found once at the start of main() (the
// secondary light and every primary's baked shadow read it).
ObjectLattice pixelLattice;

// Face `face` of the object's ambient cube where the pixel lies: its lattice samples' faces,
// trilinearly (rgb lux; w the primary's baked visibility for face 0). A corner past an edge of
// one sample has weight 0 and reads the first sample.
vec4 objectCubeFace(uint record, ObjectLattice k, uint face) {
    if (k.single) return objectLighting[record].ambientCube[face];
    vec4 sum = vec4(0.0);
    for (uint c = 0u; c < 8u; ++c) {
        uvec3 bit = uvec3(c & 1u, (c >> 1u) & 1u, (c >> 2u) & 1u);
        vec3 w3 = mix(1.0 - k.t, k.t, vec3(bit));
        uint s = k.first + bit.x * k.step.x + bit.y * k.step.y + bit.z * k.step.z;
        sum += (w3.x * w3.y * w3.z) * objectLighting[record].ambientCube[6u * s + face];
    }
    return sum;
}

// The pixel's lightmap texel: per channel the coefficients of irradianceLinear.
struct LightmapTexel {
    vec4 r, g, b;
};
LightmapTexel lightmapTexel() {
    vec2 uv = inUv1 * draw.lightmapScale.xy;
    float base = float(draw.lightmapAtlas * LIGHTMAP_LAYERS);
    return LightmapTexel(texture(lightmap, vec3(uv, base)), texture(lightmap, vec3(uv, base + 1.0)),
                         texture(lightmap, vec3(uv, base + 2.0)));
}
bool drawUsesLightmap() {
    return BAKED_LIGHTING != 0 && drawHasLightmap() && featureOn(FEATURE_LIGHTMAP);
}

// The baked direct light's shadow edge at this pixel (directEdgeFactor, lighting.glsl; set once
// per pixel by bakedDirectEdge): the factor on the texels' filtered direct light, and what that
// adds to the lightmap's diffuse (lux facing edgeLight; negative where the edge takes light).
float edgeFactor = 1.0;
vec3 edgeExtra = vec3(0.0);
vec3 edgeLight = vec3(0.0);
void bakedDirectEdge() {
    vec2 uv = inUv1 * draw.lightmapScale.xy;
    vec4 mask = texture(shadowMask, vec3(uv, float(draw.lightmapAtlas)));
    float ramps = (mask.g * 2.0 - 1.0) * DIRECT_EDGE_RAMPS;  // penumbra widths, + lit
    float rampsPerPixel = fwidth(ramps);  // in uniform control flow: before the branch below
    if (mask.a <= mask.b) return;         // no edge drawn here: one level
    float base = float(draw.lightmapAtlas * LIGHTMAP_LAYERS);
    vec4 d = textureLod(lightmap, vec3(uv, base + float(LIGHTMAP_LAYER_DIRECT)), 0.0);
    edgeFactor = directEdgeFactor(d.a, ramps, rampsPerPixel, mask.b, mask.a);
    if (edgeFactor == 1.0) return;
    vec4 l = textureLod(lightmap, vec3(uv, base + float(LIGHTMAP_LAYER_DIRECT_LIGHT)), 0.0);
    float length_l = length(l.xyz);  // shorter where the bilinear filter mixes directions
    edgeLight = length_l > 1e-4 ? l.xyz / length_l : vec3(0.0);
    edgeExtra = d.rgb * (frame.baked.y * (edgeFactor - 1.0));
}

vec3 lightmapIrradiance(LightmapTexel t, vec3 n) {
    vec3 e = vec3(irradianceLinear(t.r, n), irradianceLinear(t.g, n), irradianceLinear(t.b, n)) *
             frame.baked.y;
    return max(e + edgeExtra * max(dot(n, edgeLight), 0.0), vec3(0.0));
}

// The pixel's two parts of its lightmap texel that the specular needs apart (world::LightmapTexel,
// docs/lighting.md "Normalisation"): the baked punctual lights' direct light as one light
// (irradiance facing it, lux, and its direction; 0 where none reaches) and the rest at the
// surface normal (lux), the pixel's side of the probes' statistic.
struct LightmapSpecular {
    vec3 directIrradiance;
    vec3 directLight;
    vec3 indirectIrradiance;
};
LightmapSpecular lightmapSpecular() {
    vec2 uv = inUv1 * draw.lightmapScale.xy;
    float base = float(draw.lightmapAtlas * LIGHTMAP_LAYERS);
    LightmapSpecular s;
    s.directIrradiance = texture(lightmap, vec3(uv, base + float(LIGHTMAP_LAYER_DIRECT))).rgb *
                         (frame.baked.y * edgeFactor);
    vec3 l = texture(lightmap, vec3(uv, base + float(LIGHTMAP_LAYER_DIRECT_LIGHT))).xyz;
    float length_l = length(l);  // shorter where the bilinear filter mixes directions
    s.directLight = length_l > 1e-4 ? l / length_l : vec3(0.0);
    s.indirectIrradiance =
        texture(lightmap, vec3(uv, base + float(LIGHTMAP_LAYER_INDIRECT))).rgb * frame.baked.y;
    return s;
}

// Secondary diffuse irradiance (lux per channel) for normal n: a static surface's lightmap
// (bilinear), a dynamic object's ambient cube from the light grid, else the constant ambient.
vec3 secondaryIrradiance(vec3 n) {
    if (BAKED_LIGHTING == 0) return vec3(frame.baked.x);
    if (drawUsesLightmap()) return lightmapIrradiance(lightmapTexel(), n);
    if (drawHasObjectLighting()) {
        // Only the three faces n looks towards weigh (irradianceAmbientCube picks them).
        vec3 cx = objectCubeFace(draw.objectLighting, pixelLattice, n.x >= 0.0 ? 0u : 1u).rgb;
        vec3 cy = objectCubeFace(draw.objectLighting, pixelLattice, n.y >= 0.0 ? 2u : 3u).rgb;
        vec3 cz = objectCubeFace(draw.objectLighting, pixelLattice, n.z >= 0.0 ? 4u : 5u).rgb;
        return irradianceAmbientCube(cx, cx, cy, cy, cz, cz, n);
    }
    return vec3(frame.baked.x);
}

// A pixel's footprint of a normal map (shaders/material.glsl, "A footprint's bumps"): the share
// of its lobe that is the normals' spread, the shape of its facets, and its normals (the ring,
// then the mean normal) with their weights and energy split at the texels' own gloss.
// bumpShare 0: one texel, shaded as such (the rest unset).
struct Footprint {
    float bumpShare;
    float facetGaussianShare;                   // footprintReflectanceShaped's
    vec3 normals[FOOTPRINT_RING_COUNT];         // the ring, bent as the pixel's normal is
    vec3 diffuseWeights[FOOTPRINT_RING_COUNT];  // diffuseEnergyWeight at each
    float ringWeight;                           // each ring normal's weight
    vec3 centre;                                // the pixel's (mean) normal
    float centreWeight;                         // 1 - FOOTPRINT_RING_COUNT ringWeight
    vec3 centreDiffuseWeight;                   // diffuseEnergyWeight there (0 at weight 0)
    vec2 env;  // the mean (scale, bias) of their lobes, less what the surface's plane cuts
    // Whether the facets are read from the normal map's facet table (1) or the mixture (0); the
    // tangent frame the table is in (t, b along the map's x and y, n the surface's normal); the
    // tile's mean slope in that frame; and per part of the footprint (footprintParts) its
    // mean slope and the table's scale (facetTableLookup, shaders/material.glsl).
    float tableShare;
    vec3 tableT, tableB, tableN;
    vec2 tileMean;
    vec2 tableMeans[FOOTPRINT_PARTS + 1];  // per part (footprintParts), then the footprint's own
    float tableScales[FOOTPRINT_PARTS + 1];
    float partWeight;  // each part's weight (0: no parts, their entries unset); the footprint's
                       // own lobe has the rest
};

// Below this share the footprint is one texel: the ring's normals would be the pixel's own.
const float MIN_BUMP_SHARE = 1e-3;

// The footprint of a pixel of normal n (bent; ns the surface's normal), view v, lobe `gloss`,
// texels' own lobes `baseGloss` and slopes' kurtosis `kurtosis` (0: not known, a ring of
// Beckmann facets as before the texture stage stored it).
Footprint footprintOf(vec3 n, vec3 ns, vec3 v, float gloss, float baseGloss, float kurtosis,
                      vec3 f0) {
    Footprint f;
    f.bumpShare = bumpShare(gloss, baseGloss);
    f.env = vec2(0.0);
    f.tableShare = 0.0;
    vec3 t = v - n * dot(n, v);
    float tl = length(t);
    if (f.bumpShare < MIN_BUMP_SHARE || tl < 1e-6) {
        f.bumpShare = 0.0;
        return f;
    }
    t /= tl;
    vec3 b = cross(n, t);
    float s2 = bumpSlopeVariance(gloss, baseGloss);
    float baseAlpha = ggxAlpha_fromGloss(baseGloss);
    float known = kurtosis > 0.0 ? kurtosis : 1.0;
    f.facetGaussianShare =
        kurtosis > 0.0 ? facetGaussianShare_fromKurtosis(kurtosis, s2, baseAlpha * baseAlpha) : 1.0;
    float radius = footprintRingRadius(sqrt(s2), known);
    float centre = footprintCentreWeight(known);
    // The ring in loops of FOOTPRINT_RING_COUNT and the mean normal beside them: lavapipe unrolls
    // the loops and keeps the arrays in registers (seven normals in the loops put them in memory,
    // x1.25 on a frame of such a floor).
    f.ringWeight = (1.0 - centre) / float(FOOTPRINT_RING_COUNT);
    for (int k = 0; k < FOOTPRINT_RING_COUNT; ++k) {
        vec3 nk = normal_withValidReflection(footprintRingNormal(n, t, b, radius, k), ns, v);
        // The fit, not the table: six texture fetches cost lavapipe more than its polynomial.
        vec2 e = EnvBRDF_Fit(clamp(dot(nk, v), MIN_NOV, 1.0), baseGloss);
        f.normals[k] = nk;
        f.diffuseWeights[k] = diffuseEnergyWeight(MATERIAL_CLASS, f0, e);
        f.env += e * specularShareAboveSurface(nk, ns, v, baseAlpha);
    }
    f.env *= f.ringWeight;
    f.centre = n;
    f.centreWeight = centre;
    f.centreDiffuseWeight = vec3(0.0);
    if (centre > 0.0) {  // evaluated only where it has weight
        vec2 e = EnvBRDF_Fit(clamp(dot(n, v), MIN_NOV, 1.0), baseGloss);
        f.centreDiffuseWeight = diffuseEnergyWeight(MATERIAL_CLASS, f0, e);
        f.env += e * (specularShareAboveSurface(n, ns, v, baseAlpha) * centre);
    }
    return f;
}

// The diffuse's energy weight for light l (NoL at the pixel's normal > 0): the footprint's mean
// of each normal's weight times its cosine, over the pixel's cosine. A texel that faces the
// light and the view takes more of it; one that faces away from either, less.
vec3 footprintDiffuseWeight(Footprint f, vec3 l, float NoL) {
    vec3 sum = vec3(0.0);
    for (int k = 0; k < FOOTPRINT_RING_COUNT; ++k)
        sum += f.diffuseWeights[k] * max(dot(f.normals[k], l), 0.0);
    sum = sum * f.ringWeight + f.centreDiffuseWeight * (f.centreWeight * max(dot(f.centre, l), 0.0));
    return sum / max(NoL, 1e-6);
}

// The same for the secondary irradiance E(n) (irradiance: at the pixel's normal): the mean of
// each normal's weight times E there, over E at the pixel's normal.
vec3 footprintSecondaryWeight(Footprint f, vec3 irradiance) {
    vec3 sum = vec3(0.0), weights = vec3(0.0);
    bool lightmapped = drawUsesLightmap();
    LightmapTexel texel;
    if (lightmapped) texel = lightmapTexel();
    for (int k = 0; k < FOOTPRINT_RING_COUNT; ++k) {
        vec3 e = lightmapped ? lightmapIrradiance(texel, f.normals[k]) : secondaryIrradiance(f.normals[k]);
        sum += f.diffuseWeights[k] * e;
        weights += f.diffuseWeights[k];
    }
    sum *= f.ringWeight;
    weights *= f.ringWeight;
    if (f.centreWeight > 0.0) {  // the pixel's own irradiance, at its normal
        sum += f.centreDiffuseWeight * (f.centreWeight * irradiance);
        weights += f.centreDiffuseWeight * f.centreWeight;
    }
    return mix(weights, sum / max(irradiance, vec3(1e-12)), greaterThan(irradiance, vec3(1e-12)));
}

// The baked visibility of the draw's primary: a static surface's shadow mask, a dynamic object's
// visibility from the light grid; 1 without baked lighting.
float bakedShadow() {
    if (BAKED_LIGHTING == 0) return 1.0;
    if (drawHasLightmap())
        return texture(shadowMask, vec3(inUv1 * draw.lightmapScale.xy, float(draw.lightmapAtlas))).r;
    if (drawHasObjectLighting()) return objectCubeFace(draw.objectLighting, pixelLattice, 0u).w;
    return 1.0;
}

// One probe's radiance for the reflection ray (p, r) over its capture's statistic (shaders/
// probe.glsl, "Normalization"): the mean of its irradiance over normals, or with probesPerNormal
// its irradiance at the pixel's normal n. Box-projected when the probe has a box, at the mip of
// the gloss.
vec3 sampleProbe(uint i, vec3 p, vec3 r, vec3 n, float lod) {
    GpuProbe g = probeRecords[i];
    vec3 dir = g.boxMin.w > 0.5 ? boxProjectedDirection(p, r, g.boxMin.xyz, g.boxMax.xyz, g.position.xyz) : r;
    vec3 sampled = textureLod(probes, vec4(dir, float(i)), lod).rgb;
    if (frame.probeParams.y < 0.5) return sampled;  // the capture's mean: the texels as stored
    vec3 relative = irradianceAmbientCube(g.relativeIrradiance[0].rgb, g.relativeIrradiance[1].rgb,
                                          g.relativeIrradiance[2].rgb, g.relativeIrradiance[3].rgb,
                                          g.relativeIrradiance[4].rgb, g.relativeIrradiance[5].rgb, n);
    return probeAtNormal(sampled, relative);
}

// The secondary specular's radiance over its capture's statistic (sampleProbe; the pixel
// multiplies by its own): the first two records, in order, whose influence reaches p, weighted
// c1 = w1, c2 = (1 - w1) w2 and
// normalised; outside every influence volume, the probe captured nearest to p. Inside the probe
// grid only p's cell's lists are walked (runtime/render/probe_records.hpp), which pick the same.
vec3 probeRadiance(vec3 p, vec3 r, vec3 n, float gloss) {
    if (BAKED_LIGHTING == 0) return vec3(INV_PI);
    float lod = probeMipOfGloss(gloss, int(frame.probeParams.x));
    uint listed = 0u, influenceCount = frame.counts.z, nearestCount = frame.counts.z;
    vec3 f = floor((p - probeGrid.origin.xyz) / probeGrid.cellSize.xyz);
    if (probeGrid.dims.w != 0u && all(greaterThanEqual(f, vec3(0.0))) &&
        all(lessThan(f, vec3(probeGrid.dims.xyz)))) {
        uvec3 c = uvec3(f);
        uint cell = c.x + probeGrid.dims.x * (c.y + probeGrid.dims.y * c.z);
        listed = probeCells[2u * cell];
        influenceCount = probeCells[2u * cell + 1u] & 0xFFFFu;
        nearestCount = probeCells[2u * cell + 1u] >> 16u;
    }
    vec3 sum = vec3(0.0);
    float weight = 0.0;
    uint taken = 0u;
    for (uint k = 0u; k < influenceCount && taken < 2u && weight < 1.0; ++k) {
        uint i = listed != 0u ? probeCells[listed + k] : k;
        GpuProbe g = probeRecords[i];
        float w = probeInfluenceWeight(p, g.influenceMin.xyz, g.influenceMax.xyz, g.influenceMin.w) *
                  (1.0 - weight);
        if (w <= 0.0) continue;
        sum += w * sampleProbe(i, p, r, n, lod);
        weight += w;
        ++taken;
    }
    if (weight > 0.0) return sum / weight;
    uint nearest = 0u;
    float best = 1e30;
    for (uint k = 0u; k < nearestCount; ++k) {
        uint i = listed != 0u ? probeCells[listed + influenceCount + k] : k;
        vec3 d = p - probeRecords[i].position.xyz;
        if (dot(d, d) < best) {
            best = dot(d, d);
            nearest = i;
        }
    }
    return sampleProbe(nearest, p, r, n, lod);
}

// A light record of type `type` seen from p, by the shared light model (its colour holds the
// intensity).
LightSample evaluateGpuLight(GpuLight light, int type, vec3 p) {
    return evaluatePunctualLight(type, light.color.rgb, 1.0, light.positionRange.w,
                                 light.positionRange.xyz, light.direction.xyz, light.cones.x,
                                 light.cones.y, p);
}

// f(v, l) NoL of a direct light from l: surfaceReflectance, or footprintReflectance where the
// pixel covers a normal map's bumps.
vec3 directReflectance(vec3 albedo, vec3 f0, float gloss, vec2 directEnv, Footprint footprint,
                       float cavity, vec3 l, BrdfDots d) {
    if (footprint.bumpShare == 0.0)
        return surfaceReflectance(MATERIAL_CLASS, DIFFUSE_MODEL, albedo, f0, gloss, directEnv, cavity, d);
    float tableFacets = 0.0;
    if (footprint.tableShare > 0.0) {
        vec3 h = normalize(l + normalize(frame.cameraPosition.xyz - inWorldPosition));
        vec3 ht = vec3(dot(h, footprint.tableT), dot(h, footprint.tableB),
                       dot(h, footprint.tableN));
        if (ht.z > 1e-4) {
            // The facets' density: the footprint's own lobe's, blended with its parts'
            // (footprintParts) where it has them.
            vec3 c = facetTableLookup(ht, footprint.tableMeans[FOOTPRINT_PARTS], footprint.tileMean,
                                      footprint.tableScales[FOOTPRINT_PARTS]);
            float D = textureLod(facetTexture, c.xy * 0.5 + 0.5, 0.0).r * c.z;
            if (footprint.partWeight > 0.0) {
                float parts = 0.0;
                for (int i = 0; i < FOOTPRINT_PARTS; ++i) {
                    c = facetTableLookup(ht, footprint.tableMeans[i], footprint.tileMean,
                                         footprint.tableScales[i]);
                    parts += textureLod(facetTexture, c.xy * 0.5 + 0.5, 0.0).r * c.z;
                }
                D += (parts - float(FOOTPRINT_PARTS) * D) * footprint.partWeight;
            }
            tableFacets = specularFacets_Table(D, ht.z, d.LoH);
        }
    }
    return footprintReflectanceShaped(MATERIAL_CLASS, DIFFUSE_MODEL, albedo,
                                      footprintDiffuseWeight(footprint, l, d.NoL), f0, gloss,
                                      footprint.bumpShare, footprint.facetGaussianShare,
                                      footprint.tableShare, tableFacets, cavity, d);
}

// The radiance primary light `light` (of type `type`) reflects at p, times its shadow.
vec3 primaryRadiance(GpuLight light, int type, vec3 p, vec3 n, vec3 v, vec3 geometricNormal,
                     float viewDistance, vec3 albedo, vec3 f0, float gloss, vec2 directEnv,
                     Footprint footprint, float cavity) {
    LightSample s = evaluateGpuLight(light, type, p);
    BrdfDots d = brdfDots(n, v, s.l);
    if (!(dot(geometricNormal, s.l) > 0.0 && d.NoL > 0.0)) return vec3(0.0);
    float radius = frame.shadowParams.x;
    float shadow = 1.0;
    if (PRIMARY_SHADOW == 1) {
        float runtime = featureOn(FEATURE_RUNTIME_SHADOW) && viewDistance < radius
                            ? runtimeShadow(light, type, p, geometricNormal, s.l, viewDistance) : 1.0;
        bool inBand = viewDistance > radius - frame.shadowParams.y;
        bool staticLit = runtime > 0.0 && drawHasLightmap();
        float baked = featureOn(FEATURE_BAKED_SHADOW) && (inBand || staticLit) ? bakedShadow() : 1.0;
        // A static surface's mask is traced against the static casters at its texels: where it
        // is umbra over its whole bilinear footprint, no static caster lets the light through,
        // and a runtime lookup that does is a leak. The map's filter reaches past the foot of a
        // single-sided wall, where the map holds nothing, and lit a line along it (dynamic
        // casters only take light away, so the mask's umbra stands for them too).
        if (staticLit && baked < 0.5 / 255.0) runtime = 0.0;
        shadow = blendShadow(runtime, baked, viewDistance, frame.shadowParams.x, frame.shadowParams.y);
    }
    return directReflectance(albedo, f0, gloss, directEnv, footprint, cavity, s.l, d) *
           s.illuminance * shadow;
}

void main() {
    if (FLAT_SHADING == 1) {
        outColor = vec4(0.18, 0.18, 0.18, 1.0);
        return;
    }
    if (BAKED_LIGHTING != 0 && drawHasObjectLighting()) pixelLattice = objectLattice(draw.objectLighting);
    if (DIRECT_EDGES == 1 && drawUsesLightmap() && featureOn(FEATURE_DIRECT_EDGE)) bakedDirectEdge();
    GpuMaterial m = materialRecords[draw.material];
    // The texture coordinates' derivatives, taken before any branch or discard.
    vec2 uvDx = dFdx(inUv0), uvDy = dFdy(inUv0);

    vec4 base = m.baseColor;
    if (materialHas(m, TEXTURE_BASE_COLOR) && featureOn(FEATURE_BASE_TEXTURE))
        base *= texture(baseColorTexture, inUv0);
    if (ALPHA_MODE == ALPHA_MODE_MASK && base.a < m.emissive.a) discard;

    // Material parameters per texel (shaders/material.glsl), by class.
    vec2 mr = vec2(m.params.x, m.params.y);
    float baseRoughness = -1.0;  // the normal map's texels' own, where the texture holds it
    if (materialHas(m, TEXTURE_METALLIC_ROUGHNESS)) {
        vec4 mrTexel = texture(metallicRoughnessTexture, inUv0);
        mr = metallicRoughness_fromTexel(MATERIAL_CLASS, mr.x, mr.y, mrTexel);
        if (hasMaterialFlag(m, MATERIAL_FLAG_BASE_ROUGHNESS)) baseRoughness = m.params.y * mrTexel.a;
    }
    MaterialPoint point = materialPoint(MATERIAL_CLASS, base.rgb, mr.x, mr.y, m.f0Gloss.x);
    vec3 albedo = point.albedo;
    vec3 f0 = point.f0;
    float gloss = point.gloss;
    float baseGloss = baseRoughness >= 0.0 ? max(gloss_fromRoughness(baseRoughness), gloss) : gloss;

    vec3 p = inWorldPosition;
    vec3 geometricNormal = normalize(inNormal);
    if (!gl_FrontFacing) geometricNormal = -geometricNormal;
    vec3 toCamera = frame.cameraPosition.xyz - p;
    float viewDistance = length(toCamera);
    vec3 v = toCamera / max(viewDistance, 1e-6);
    vec3 n = geometricNormal;
    float slopeKurtosis = 0.0;  // the normal map's slopes under this pixel, where it holds them
    vec3 mapT = vec3(0.0), mapB = vec3(0.0);  // the normal map's tangent frame (0: none)
    if (materialHas(m, TEXTURE_NORMAL)) {
        vec3 t = inTangent.xyz - geometricNormal * dot(geometricNormal, inTangent.xyz);
        float tl = length(t);
        if (tl > 1e-6) {
            mapT = t / tl;
            mapB = cross(geometricNormal, mapT) * inTangent.w;
        }
        vec4 normalTexel = texture(normalTexture, inUv0);
        vec3 texel = normalTexel.rgb;
        if (hasMaterialFlag(m, MATERIAL_FLAG_SLOPE_KURTOSIS)) slopeKurtosis = 1.0 + 2.0 * normalTexel.a;
        if (tl > 1e-6) n = normal_fromTangentSpace(texel, m.params.z, geometricNormal, t / tl, inTangent.w);
        n = normal_withValidReflection(n, geometricNormal, v);
        // The filter's spread of the normals under this pixel folds into its gloss.
        if (MATERIAL_PIPELINE == 1 && MATERIAL_CLASS != MATERIAL_LAMBERT)
            gloss = gloss_withFilteredNormal(gloss, texel * 2.0 - 1.0);
    }

    vec3 radiance = vec3(0.0);

    // The specular lobe's directional albedo (split-sum table): the probes' environment
    // "Fresnel", and the diffuse's energy-conservation weight (lighting.glsl).
    float NoV = clamp(dot(n, v), MIN_NOV, 1.0);
    vec2 env = vec2(0.0);
    if (MATERIAL_CLASS != MATERIAL_LAMBERT) env = texture(envBrdfTable, envBrdfTableCoord(NoV, gloss)).rg;
    float cavity = MATERIAL_PIPELINE == 1 && materialHas(m, TEXTURE_CAVITY) ? texture(cavityTexture, inUv0).r : 1.0;
    vec2 directEnv = MATERIAL_PIPELINE == 1 ? env : vec2(0.0);  // the direct lights' energy weight
    // Far away, a pixel covers many texels of a normal map: the bumps' share of the lobe shades
    // as facets, and the energy split is the footprint's (shaders/material.glsl).
    Footprint footprint;
    footprint.bumpShare = 0.0;
    if (MATERIAL_PIPELINE == 1 && MATERIAL_CLASS != MATERIAL_LAMBERT && materialHas(m, TEXTURE_NORMAL))
        footprint = footprintOf(n, geometricNormal, v, gloss, baseGloss, slopeKurtosis, f0);
    // The footprint's facets take the shape of the whole tile's, the normal map's facet table,
    // at the footprint's mean slope and lobe (facetTableLookup, shaders/material.glsl): the tile's
    // lobe and mean normal are its coarsest mip's.
    if (MATERIAL_PIPELINE == 1 && footprint.bumpShare > 0.0 && materialHas(m, TEXTURE_FACETS) &&
        mapT != vec3(0.0)) {
        vec4 tileTexel = textureLod(metallicRoughnessTexture, inUv0, 16.0);
        vec2 tileMr =
            metallicRoughness_fromTexel(MATERIAL_CLASS, m.params.x, m.params.y, tileTexel);
        float tileGloss =
            materialPoint(MATERIAL_CLASS, base.rgb, tileMr.x, tileMr.y, m.f0Gloss.x).gloss;
        vec3 tileNormal =
            normal_fromTangentSpace(textureLod(normalTexture, inUv0, 16.0).rgb, m.params.z,
                                    vec3(0.0, 0.0, 1.0), vec3(1.0, 0.0, 0.0), 1.0);
        vec3 mean = vec3(dot(n, mapT), dot(n, mapB), dot(n, geometricNormal));
        float tileBaseGloss = max(gloss_fromRoughness(m.params.y * tileTexel.a), tileGloss);
        float tileS2 = bumpSlopeVariance(tileGloss, tileBaseGloss);
        float whole = facetTableWhole(bumpSlopeVariance(gloss, baseGloss), tileS2);
        footprint.tableShare = 1.0;
        footprint.tableT = mapT;
        footprint.tableB = mapB;
        footprint.tableN = geometricNormal;
        footprint.tileMean = tileNormal.xy / max(tileNormal.z, 0.01);
        // Its parts (footprintParts), until the tile is taken whole, blended with its own lobe
        // as `whole` grows so that no edge shows where the parts stop.
        FootprintParts parts = footprintParts(uvDx, uvDy, vec2(textureSize(normalTexture, 0)));
        bool split = parts.split && whole < 1.0;
        float mrLodBias = log2(float(textureSize(metallicRoughnessTexture, 0).x) /
                               float(textureSize(normalTexture, 0).x));
        float tileAlpha = ggxAlpha_fromGloss(tileGloss);
        footprint.tableMeans[FOOTPRINT_PARTS] =
            mix(mean.xy / max(mean.z, 0.01), footprint.tileMean, whole);
        footprint.tableScales[FOOTPRINT_PARTS] =
            mix(tileAlpha / ggxAlpha_fromGloss(gloss), 1.0, whole);
        footprint.partWeight = split ? (1.0 - whole) / float(FOOTPRINT_PARTS) : 0.0;
        for (int i = 0; split && i < FOOTPRINT_PARTS; ++i) {  // each part's own mip texels
            vec2 uv = inUv0 + parts.offsets[i];
            vec3 texel = textureLod(normalTexture, uv, parts.lod).rgb;
            vec2 mr = metallicRoughness_fromTexel(
                MATERIAL_CLASS, m.params.x, m.params.y,
                textureLod(metallicRoughnessTexture, uv, parts.lod + mrLodBias));
            float partGloss = gloss_withFilteredNormal(
                materialPoint(MATERIAL_CLASS, base.rgb, mr.x, mr.y, m.f0Gloss.x).gloss,
                texel * 2.0 - 1.0);
            vec3 pn = normal_fromTangentSpace(texel, m.params.z, vec3(0.0, 0.0, 1.0),
                                              vec3(1.0, 0.0, 0.0), 1.0);
            float partWhole = facetTableWhole(bumpSlopeVariance(partGloss, baseGloss), tileS2);
            footprint.tableMeans[i] = mix(pn.xy / max(pn.z, 0.01), footprint.tileMean, partWhole);
            footprint.tableScales[i] =
                mix(tileAlpha / ggxAlpha_fromGloss(partGloss), 1.0, partWhole);
        }
    }

    // The one primary light, times its shadow; a dynamic object's two while its switch
    // cross-fades (draw.fadeLight at 1 - draw.primaryWeight; PRIMARY_FADE pipelines only, so
    // that the others pay nothing for it).
    if (PRIMARY != PRIMARY_NONE && featureOn(FEATURE_PRIMARY) && draw.primaryLight != NO_INDEX) {
        GpuLight light = primaryLights[draw.primaryLight];
        float share = PRIMARY_FADE == 1 && draw.fadeLight != NO_INDEX ? draw.primaryWeight : 1.0;
        radiance += primaryRadiance(light, primaryType(light), p, n, v, geometricNormal, viewDistance,
                                    albedo, f0, gloss, directEnv, footprint, cavity) * share;
        if (PRIMARY_FADE == 1 && draw.fadeLight != NO_INDEX) {
            GpuLight old = primaryLights[draw.fadeLight];
            radiance += primaryRadiance(old, int(old.info.x), p, n, v, geometricNormal, viewDistance,
                                        albedo, f0, gloss, directEnv, footprint, cavity) * (1.0 - share);
        }
    }

    // Effect lights: up to 4 diffuse-only omnis (gun flashes) and the flashlight spot.
    if (EFFECT_LIGHTS == 1 && MATERIAL_CLASS != MATERIAL_METAL) {
        for (uint i = 0u; i < frame.counts.x; ++i) {
            LightSample s = evaluateGpuLight(frame.effectOmnis[i], LIGHT_POINT, p);
            BrdfDots d = brdfDots(n, v, s.l);
            vec3 weight = footprint.bumpShare == 0.0 ? diffuseEnergyWeight(MATERIAL_CLASS, f0, directEnv)
                                                     : footprintDiffuseWeight(footprint, s.l, d.NoL);
            radiance += footprintDiffuse(DIFFUSE_MODEL, albedo, weight, gloss, cavity, d) * s.illuminance;
        }
    }
    if (EFFECT_LIGHTS == 1 && frame.counts.y != 0u) {
        LightSample s = evaluateGpuLight(frame.effectSpot, LIGHT_SPOT, p);
        radiance += directReflectance(albedo, f0, gloss, directEnv, footprint, cavity, s.l,
                                      brdfDots(n, v, s.l)) * s.illuminance;
    }

    // Baked secondary lighting: diffuse from the lightmap or grid; specular from the probes,
    // de-normalised by the pixel's value of the statistic they were normalised by
    // (shaders/probe.glsl, "Normalization"), and on a static surface from the lightmap's baked
    // direct light, by a lobe of its own: the probes hold none of it.
    // The statistic's normal: a texel's is the surface's, a dynamic object's grid the pixel's.
    vec3 irradiance = secondaryIrradiance(n);
    vec3 probeIrradiance = irradiance;
    vec3 statisticNormal = n;
    if (MATERIAL_CLASS != MATERIAL_LAMBERT && drawUsesLightmap()) {
        LightmapSpecular baked = lightmapSpecular();
        probeIrradiance = baked.indirectIrradiance;
        statisticNormal = geometricNormal;
        BrdfDots d = brdfDots(n, v, baked.directLight);
        if (dot(geometricNormal, baked.directLight) > 0.0 && d.NoL > 0.0)
            radiance += directReflectance(vec3(0.0), f0, gloss, directEnv, footprint, cavity,
                                          baked.directLight, d) * baked.directIrradiance;
    }
    float ao = 1.0;
    if (materialHas(m, TEXTURE_OCCLUSION))
        ao = occlusion_fromTexel(texture(occlusionTexture, inUv0).r, m.params.w);
    vec3 probeSample = vec3(0.0);
    float so = 1.0;
    if (MATERIAL_CLASS != MATERIAL_LAMBERT) {
        probeSample = PROBES == 1 ? probeRadiance(p, reflect(-v, n), statisticNormal, gloss)
                                  : vec3(INV_PI);
        so = specularOcclusion(NoV, ao, ggxAlpha_fromGloss(gloss));
    }
    if (footprint.bumpShare == 0.0) {
        // A mapped normal's lobe less what the surface's plane cuts (shaders/material.glsl).
        vec2 specularEnv = env;
        bool mapped = materialHas(m, TEXTURE_NORMAL);
        if (MATERIAL_PIPELINE == 1 && MATERIAL_CLASS != MATERIAL_LAMBERT && mapped)
            specularEnv *= specularShareAboveSurface(n, geometricNormal, v,
                                                     ggxAlpha_fromGloss(gloss));
        radiance += footprintSecondaryRadiance(MATERIAL_CLASS, albedo,
                                               diffuseEnergyWeight(MATERIAL_CLASS, f0, env), f0,
                                               specularEnv, irradiance, ao, so, probeSample,
                                               probeIrradiance);
    } else
        radiance += footprintSecondaryRadiance(MATERIAL_CLASS, albedo,
                                               footprintSecondaryWeight(footprint, irradiance), f0,
                                               footprint.env, irradiance, ao, so, probeSample,
                                               probeIrradiance);

    // Emission in cd/m^2 like every other radiance (world/import/README.md), then the whole
    // pre-exposed.
    vec3 emissive = m.emissive.rgb;
    if (materialHas(m, TEXTURE_EMISSIVE) && featureOn(FEATURE_EMISSIVE_TEXTURE))
        emissive *= texture(emissiveTexture, inUv0).rgb;
    float exposure = frame.cameraPosition.w;
    vec3 color = (radiance + emissive) * exposure;
    if (any(isnan(color)) || any(isinf(color))) color = vec3(0.0);
    // A blended material's colour goes over what is behind by its alpha (the pipeline's blend:
    // rgb = src.rgb a + dst.rgb (1 - a)), its lit radiance and emission alike.
    float alpha = ALPHA_MODE == ALPHA_MODE_BLEND ? clamp(base.a, 0.0, 1.0) : 1.0;
    outColor = vec4(min(color, vec3(HDR_MAX)), alpha);
}
