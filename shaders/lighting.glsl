// Light evaluation of onelight, written once for GLSL and C++ (see common.glsl for the dialect):
// the runtime specular model, material classes, punctual lights in glTF units, the baked
// secondary terms and the runtime/baked shadow blend. The BRDF itself comes from brdf.glsl.
//
// Units (docs/lighting.md "Units"): metres; directional lights in lux, point and spot
// lights in candela (KHR_lights_punctual). A light's "illuminance" below is what it delivers at
// normal incidence, in lux; reflected radiance = reflectance * illuminance, in cd/m^2.
#ifndef ONELIGHT_LIGHTING_GLSL
#define ONELIGHT_LIGHTING_GLSL

#include "brdf.glsl"
#include "env_brdf_fit.glsl"
#include "probe.glsl"

// ---------------------------------------------------------------------------------------------
// The runtime specular model: ggx_smith, chosen by docs/brdf-report (cheapest exact model).

const int RUNTIME_NDF = NDF_GGX;
const int RUNTIME_VIS = VIS_SMITH_CORRELATED;
const int RUNTIME_FRESNEL = FRESNEL_SCHLICK;

// Material classes (world::MaterialClass): one shader permutation each.
#define MATERIAL_METAL 0       // specular only, coloured f0
#define MATERIAL_DIELECTRIC 1  // Lambert + specular with a grey (scalar) f0
#define MATERIAL_FULL 2        // Lambert + specular with a coloured f0
#define MATERIAL_LAMBERT 3     // Lambert only

// Diffuse models (world::DiffuseModel), one per level: a specialization constant at runtime.
#define DIFFUSE_LAMBERT 0       // Fd_Lambert
#define DIFFUSE_MULTISCATTER 1  // Fd_Chan: Lambertian microfacets with multiple scattering

// Light types (world::LightType).
#define LIGHT_DIRECTIONAL 0
#define LIGHT_POINT 1
#define LIGHT_SPOT 2

const float MIN_LIGHT_DISTANCE2 = 1e-4f;  // (1 cm)^2: a light inside geometry stays finite

// ---------------------------------------------------------------------------------------------
// Punctual lights

// KHR_lights_punctual, "Range Property" (recommended window): saturate(1 - (d / range)^4)^2,
// which reaches 0 at the range with zero slope. range <= 0 means unlimited.
float rangeWindow(float distance2, float range) {
    if (range <= 0.0f) return 1.0f;
    float r2 = distance2 / (range * range);
    return sq(saturate(1.0f - r2 * r2));
}

// Inverse-square law for a light of intensity in candela: E = I / d^2 lux, with d floored at
// 1 cm (Lagarde and de Rousiers 2014, "Moving Frostbite to PBR", sec. 4.2.2).
float inverseSquare(float distance2) { return 1.0f / max(distance2, MIN_LIGHT_DISTANCE2); }

// KHR_lights_punctual, "Spot": linear in cos(angle) from the outer to the inner cone, squared.
// cosAngle = dot(spot direction, light-to-point direction).
float spotCone(float cosAngle, float cosInner, float cosOuter) {
    float scale = 1.0f / max(0.001f, cosInner - cosOuter);
    return sq(saturate((cosAngle - cosOuter) * scale));
}

// A punctual light seen from a surface point.
struct LightSample {
    vec3 l;            // unit vector from the point to the light
    vec3 illuminance;  // lux at normal incidence, coloured
    float distance;    // metres to the light (0 for directional)
};

// Evaluates light `type` at world point p. For a directional light only color, intensity (lux)
// and direction (the way light travels) matter; point and spot lights use position and range,
// and spots their cone cosines.
LightSample evaluatePunctualLight(int type, vec3 color, float intensity, float range, vec3 position,
                                  vec3 direction, float cosInner, float cosOuter, vec3 p) {
    LightSample s;
    if (type == LIGHT_DIRECTIONAL) {
        s.l = -direction;
        s.illuminance = color * intensity;
        s.distance = 0.0f;
        return s;
    }
    vec3 toLight = position - p;
    float d2 = dot(toLight, toLight);
    s.distance = sqrt(d2);
    s.l = toLight * (1.0f / max(s.distance, 1e-6f));
    float attenuation = intensity * inverseSquare(d2) * rangeWindow(d2, range);
    if (type == LIGHT_SPOT) attenuation = attenuation * spotCone(-dot(s.l, direction), cosInner, cosOuter);
    s.illuminance = color * attenuation;
    return s;
}

// ---------------------------------------------------------------------------------------------
// The split-sum table: the runtime lobe's directional albedo as f0 * scale + bias, integrated
// by `onelight-lab env-table` (shaders/env_brdf_table.inc) at sqrt(NoV) = i / (N - 1) and
// gloss = j / (N - 1), so that both ends of each axis are exact and the rows crowd towards
// grazing view, where the albedo bends fastest. The GPU reads it as a texture (bilinear, clamp
// to edge) at envBrdfTableCoord; C++ samples the same numbers the same way (env_brdf_table.hpp).

const int ENV_BRDF_TABLE_SIZE = 32;

// Texture coordinates of (NoV, gloss) in the table: texel centres at the grid points.
vec2 envBrdfTableCoord(float NoV, float gloss) {
    float n = float(ENV_BRDF_TABLE_SIZE);
    float x = sqrt(saturate(NoV)) * (n - 1.0f) + 0.5f;
    float y = saturate(gloss) * (n - 1.0f) + 0.5f;
    return vec2(x / n, y / n);
}

// ---------------------------------------------------------------------------------------------
// Surface response: the one place a material class picks its terms.

// Specular occlusion from an ambient occlusion `ao` (Lagarde and de Rousiers 2014, "Moving
// Frostbite to PBR", listing 26): saturate((NoV + ao)^(2^(-16 alpha - 1)) - 1 + ao). It is 1
// where ao is 1 and about ao on a rough surface; on a glossy one it rises towards normal view
// and falls towards grazing view, where the reflection leaves low over the horizon that the
// occluders hide (tests/lab/specular_occlusion_test measures it against a visibility cone).
float specularOcclusion(float NoV, float ao, float alpha) {
    return saturate(pow(NoV + ao, exp2(-16.0f * alpha - 1.0f)) - 1.0f + ao);
}

// The diffuse BRDF per unit albedo of model `diffuseModel` (DIFFUSE_*).
float diffuseBrdf(int diffuseModel, float gloss, BrdfDots d) {
    if (diffuseModel == DIFFUSE_MULTISCATTER) return Fd_Chan(d.NoV, d.NoL, d.LoH, d.NxH2, gloss);
    return Fd_Lambert();
}

// Chan 2018, "Material Advances in Call of Duty: WWII", sec. 5.3 (energy conservation): light
// the specular lobe reflects is not there for the diffuse layer, so diffuse is weighted by
// 1 - E_spec(f0, gloss, NoV), E_spec = f0 env.x + env.y the lobe's directional albedo from the
// split-sum table (`env`, the environment "Fresnel" the probes use too). Per channel for a
// coloured f0. A Lambert-only material has no lobe and keeps all of its diffuse.
vec3 diffuseEnergyWeight(int materialClass, vec3 f0, vec2 env) {
    if (materialClass == MATERIAL_LAMBERT) return vec3(1.0f);
    return saturate(vec3(1.0f) - (f0 * env.x + vec3(env.y)));
}

// f(v, l) NoL of a surface of class `materialClass` for one light: the level's diffuse model
// with `albedo`, weighted for energy conservation by `env` (diffuseEnergyWeight), plus the
// runtime specular lobe with `f0` and `gloss` (brdf.glsl). A dielectric's f0 is grey: the
// caller passes vec3(scalar). `cavity` ([0, 1], 1 = open) is the small-scale visibility of the
// texel's normal-mapped relief (docs/materials.md "Cavity"): it scales the primary diffuse, and
// the primary specular as an occlusion seen along the reflection (specularOcclusion), which
// lets glossy reflections at grazing view escape the cavities.
//
// footprintReflectance is the same for a pixel that covers many texels of a normal map
// (shaders/material.glsl, "A footprint's bumps"): `diffuseWeight` is the diffuse's energy weight
// (the caller's mean over the footprint's normals, for this light), and the share `bumpShare` of
// the lobe that is the normals' spread is shaded as facets (specularFacets_Beckmann) instead of
// the texel's lobe. surfaceReflectance is it for one texel: the weight diffuseEnergyWeight,
// bumpShare 0.
// `gaussianShare` is the share of the facets' slopes that are Gaussian (Beckmann's), the rest on
// a ring (facetSlopes_fromKurtosis): 1 where the slopes' shape is not known. Where the footprint
// holds a whole tile of the normal map, `tableShare` of the facets are the tile's own instead,
// `tableFacets` (specularFacets_Table of its facet table at h; 0 and 0 where there is none).
vec3 footprintReflectanceShaped(int materialClass, int diffuseModel, vec3 albedo,
                                vec3 diffuseWeight, vec3 f0, float gloss, float bumpShare,
                                float gaussianShare, float tableShare, float tableFacets,
                                float cavity, BrdfDots d) {
    vec3 diffuse = albedo * diffuseWeight * (diffuseBrdf(diffuseModel, gloss, d) * d.NoL * cavity);
    if (materialClass == MATERIAL_LAMBERT) return diffuse;
    vec3 specular = specularLobe(RUNTIME_NDF, RUNTIME_VIS, RUNTIME_FRESNEL, f0, gloss, d);
    if (bumpShare > 0.0f) {
        float a = ggxAlpha_fromGloss(gloss);
        float facets = specularFacets_Beckmann(d.NxH2, d.LoH, a);
        if (gaussianShare < 1.0f)
            facets = facets * gaussianShare +
                     specularFacets_Nakagami(d.NxH2, d.LoH, a, FACET_RING_SHAPE) *
                         (1.0f - gaussianShare);
        if (tableShare > 0.0f) facets = facets * (1.0f - tableShare) + tableFacets * tableShare;
        specular = specular * (1.0f - bumpShare) +
                   specularF(RUNTIME_FRESNEL, f0, d.LoH) * (facets * bumpShare);
    }
    if (cavity < 1.0f) specular = specular * specularOcclusion(d.NoV, cavity, ggxAlpha_fromGloss(gloss));
    if (materialClass == MATERIAL_METAL) return specular;
    return diffuse + specular;
}

// Facets of Gaussian slopes (Beckmann's).
vec3 footprintReflectance(int materialClass, int diffuseModel, vec3 albedo, vec3 diffuseWeight,
                          vec3 f0, float gloss, float bumpShare, float cavity, BrdfDots d) {
    return footprintReflectanceShaped(materialClass, diffuseModel, albedo, diffuseWeight, f0,
                                      gloss, bumpShare, 1.0f, 0.0f, 0.0f, cavity, d);
}

vec3 surfaceReflectance(int materialClass, int diffuseModel, vec3 albedo, vec3 f0, float gloss,
                        vec2 env, float cavity, BrdfDots d) {
    return footprintReflectance(materialClass, diffuseModel, albedo,
                                diffuseEnergyWeight(materialClass, f0, env), f0, gloss, 0.0f,
                                cavity, d);
}

// Diffuse only, for the omni effect lights (docs/lighting.md "Effect lights": gun flashes light
// diffusely): the diffuse term of footprintReflectance.
vec3 footprintDiffuse(int diffuseModel, vec3 albedo, vec3 diffuseWeight, float gloss, float cavity,
                      BrdfDots d) {
    return albedo * diffuseWeight * (diffuseBrdf(diffuseModel, gloss, d) * d.NoL * cavity);
}

// The same for one texel: the weight diffuseEnergyWeight.
vec3 diffuseReflectance(int materialClass, int diffuseModel, vec3 albedo, vec3 f0, float gloss,
                        vec2 env, float cavity, BrdfDots d) {
    return footprintDiffuse(diffuseModel, albedo, diffuseEnergyWeight(materialClass, f0, env),
                            gloss, cavity, d);
}

// ---------------------------------------------------------------------------------------------
// Baked secondary lighting (the contract with the baker)

// Directional irradiance stored per colour channel as four coefficients (c0, cx, cy, cz):
// E(n) = max(0, c0 + cx n.x + cy n.y + cz n.z) lux. A constant ambient of E lux is (E, 0, 0, 0).
float irradianceLinear(vec4 c, vec3 n) {
    return max(0.0f, c.x + c.y * n.x + c.z * n.y + c.w * n.z);
}

// A baked direct light's shadow edge as a distance field (docs/lighting.md "Baked shadow edges";
// Green 2007, "Improved Alpha-Tested Magnification for Vector Textures and Special Effects"):
// from the texels' visibility V, their signed distance to the edge in penumbra widths `ramps`
// (+ lit) and the edge's levels of visibility either side (`low`, `high`; both V where no edge
// is drawn), all filtered as the texels' direct light is, and a pixel's step of `ramps`, the
// factor g on the filtered direct light that draws the edge where `ramps` is 0, one penumbra
// (or one pixel, if wider) across: g = v / V, v = mix(low, high, clamp(0.5 + ramps / max(1,
// step))). The direct light over V keeps the texels' colour and unshadowed level. 1 where V is 0.
float directEdgeFactor(float visibility, float ramps, float rampsPerPixel, float low, float high) {
    float v = mix(low, high, clamp(0.5f + ramps / max(rampsPerPixel, 1.0f), 0.0f, 1.0f));
    return visibility > 1e-4f ? v / visibility : 1.0f;
}

// An ambient cube (Valve's, McTaggart 2004, "Half-Life 2 / Valve Source Shading", slide
// "Ambient Cube"): six irradiances E(+x) E(-x) E(+y) E(-y) E(+z) E(-z) in lux, blended by the
// squared normal components: E(n) = n.x^2 E(+-x) + n.y^2 E(+-y) + n.z^2 E(+-z), the sign of each
// component picking the face. The light grid stores secondary irradiance this way.
vec3 irradianceAmbientCube(vec3 px, vec3 nx, vec3 py, vec3 ny, vec3 pz, vec3 nz, vec3 n) {
    vec3 n2 = n * n;
    vec3 ex = n.x >= 0.0f ? px : nx;
    vec3 ey = n.y >= 0.0f ? py : ny;
    vec3 ez = n.z >= 0.0f ? pz : nz;
    return ex * n2.x + ey * n2.y + ez * n2.z;
}


// Secondary light reflected towards v: diffuse from irradiance E (lux, per channel) times the
// material's ambient occlusion `ao`, and specular from a normalised probe sample (radiance /
// average irradiance at its capture point) scaled back by `probeIrradiance` (probeDenormalize:
// the pixel's own value of the statistic the probe was normalised by), times the
// environment "Fresnel" f0 * env.x + env.y of the runtime model (EnvBRDF_Fit of
// env_brdf_fit.glsl, or the runtime's table of it) and the specular occlusion `so` (which
// replaces ao for the specular). The diffuse is weighted for energy conservation as the primary
// is (diffuseEnergyWeight); it stays Lambert whatever the level's diffuse model, since baked
// irradiance arrives from the whole hemisphere (Fd_Chan's view and light dependence averages
// out to about its albedo there). Lambert-only surfaces take no probe; metals no diffuse.
// footprintSecondaryRadiance takes the diffuse's weight as given: on a footprint of a normal
// map, the caller's mean over its normals (shaders/material.glsl, "A footprint's bumps"), with
// `env` the mean of theirs too.
vec3 footprintSecondaryRadiance(int materialClass, vec3 albedo, vec3 diffuseWeight, vec3 f0,
                                vec2 env, vec3 irradiance, float ao, float so,
                                vec3 normalisedProbe, vec3 probeIrradiance) {
    vec3 diffuse = albedo * diffuseWeight * (Fd_Lambert() * ao) * irradiance;
    if (materialClass == MATERIAL_LAMBERT) return diffuse;
    vec3 specular =
        (f0 * env.x + vec3(env.y)) * probeDenormalize(normalisedProbe, probeIrradiance) * so;
    if (materialClass == MATERIAL_METAL) return specular;
    return diffuse + specular;
}

vec3 secondaryRadiance(int materialClass, vec3 albedo, vec3 f0, vec2 env, vec3 irradiance,
                       float ao, float so, vec3 normalisedProbe, vec3 probeIrradiance) {
    return footprintSecondaryRadiance(materialClass, albedo,
                                      diffuseEnergyWeight(materialClass, f0, env), f0, env,
                                      irradiance, ao, so, normalisedProbe, probeIrradiance);
}

// ---------------------------------------------------------------------------------------------
// Shadows

// Near the camera the runtime shadow map, beyond `radius` the baked shadow mask; the two blend
// linearly over the last `band` metres inside the radius.
float blendShadow(float runtimeShadow, float bakedShadow, float viewDistance, float radius, float band) {
    float t = saturate((viewDistance - (radius - band)) / max(band, 1e-3f));
    return mix(runtimeShadow, bakedShadow, t);
}

#endif
