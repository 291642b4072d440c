// Environment probes, shared by the baker (capture, prefiltering) and the runtime shader:
// cube-map addressing, the gloss-to-mip mapping, and box projection. Same GLSL/C++ subset as
// brdf.glsl.
#ifndef ONELIGHT_PROBE_GLSL
#define ONELIGHT_PROBE_GLSL

#include "common.glsl"

// ---------------------------------------------------------------------------------------------
// Cube-map addressing, as Vulkan samples a cube (Vulkan spec, "Cube Map Face Selection"):
// faces +X, -X, +Y, -Y, +Z, -Z are layers 0..5; (u, v) in [0, 1] with v pointing down.

int cubeFace(vec3 d) {
    vec3 a = abs(d);
    if (a.x >= a.y && a.x >= a.z) return d.x >= 0.0f ? 0 : 1;
    if (a.y >= a.z) return d.y >= 0.0f ? 2 : 3;
    return d.z >= 0.0f ? 4 : 5;
}

// (u, v) of direction d on `face` (d need not be unit; its major axis must be face's).
vec2 cubeFaceUV(vec3 d, int face) {
    float sc, tc, ma;
    if (face == 0) {
        sc = -d.z, tc = -d.y, ma = d.x;
    } else if (face == 1) {
        sc = d.z, tc = -d.y, ma = -d.x;
    } else if (face == 2) {
        sc = d.x, tc = d.z, ma = d.y;
    } else if (face == 3) {
        sc = d.x, tc = -d.z, ma = -d.y;
    } else if (face == 4) {
        sc = d.x, tc = -d.y, ma = d.z;
    } else {
        sc = -d.x, tc = -d.y, ma = -d.z;
    }
    return vec2(0.5f * (sc / ma + 1.0f), 0.5f * (tc / ma + 1.0f));
}

// The unit direction through (u, v) of `face`: the inverse of cubeFaceUV.
vec3 cubeDirection(int face, vec2 uv) {
    float s = 2.0f * uv.x - 1.0f;
    float t = 2.0f * uv.y - 1.0f;
    vec3 d;
    if (face == 0) {
        d = vec3(1.0f, -t, -s);
    } else if (face == 1) {
        d = vec3(-1.0f, -t, s);
    } else if (face == 2) {
        d = vec3(s, 1.0f, t);
    } else if (face == 3) {
        d = vec3(s, -1.0f, -t);
    } else if (face == 4) {
        d = vec3(s, -t, 1.0f);
    } else {
        d = vec3(-s, -t, -1.0f);
    }
    return normalize(d);
}

// Solid angle of the texel [u0, u1] x [v0, v1] of a face (any face), in steradians.
// Each face is the plane at distance 1 over [-1, 1]^2; the solid angle of the rectangle from
// the origin to (x, y) is atan(x y / sqrt(x^2 + y^2 + 1)) (Girard), so a texel is the signed
// sum over its four corners.
float cubeCornerSolidAngle(float x, float y) { return atan(x * y, sqrt(x * x + y * y + 1.0f)); }
float cubeTexelSolidAngle(float u0, float v0, float u1, float v1) {
    float x0 = 2.0f * u0 - 1.0f;
    float y0 = 2.0f * v0 - 1.0f;
    float x1 = 2.0f * u1 - 1.0f;
    float y1 = 2.0f * v1 - 1.0f;
    return cubeCornerSolidAngle(x0, y0) - cubeCornerSolidAngle(x0, y1) -
           cubeCornerSolidAngle(x1, y0) + cubeCornerSolidAngle(x1, y1);
}

// ---------------------------------------------------------------------------------------------
// Gloss and mips: mip 0 holds the mirror (gloss 1), the last mip gloss 0. Linear in gloss, as
// Lazarov 2011, slide "Environment map: prefiltering": mip = nMips - gloss * nMips; the baker
// convolves mip m with the GGX lobe of probeGlossOfMip(m) and the shader reads
// probeMipOfGloss(gloss), so both sides use this one pair.

float probeMipOfGloss(float gloss, int mipCount) {
    return (1.0f - saturate(gloss)) * float(mipCount - 1);
}

float probeGlossOfMip(int mip, int mipCount) {
    return mipCount > 1 ? 1.0f - float(mip) / float(mipCount - 1) : 1.0f;
}

// ---------------------------------------------------------------------------------------------
// Box projection (Lagarde and Zanuttini 2012, "Local Image-based Lighting With
// Parallax-corrected Cubemap", the Sparta 3D approach): the reflection ray from the shaded
// point P along R is intersected with the probe's box from inside; the cube is then read in
// the direction from the probe's capture point to that hit.
vec3 boxProjectedDirection(vec3 P, vec3 R, vec3 boxMin, vec3 boxMax, vec3 probePosition) {
    // Distance along R to the box's far planes, per axis; an axis R does not move along never
    // limits the ray (its distance is huge instead of an Inf or a NaN).
    float tx = abs(R.x) > 1e-8f ? (R.x > 0.0f ? boxMax.x - P.x : boxMin.x - P.x) / R.x : 1e30f;
    float ty = abs(R.y) > 1e-8f ? (R.y > 0.0f ? boxMax.y - P.y : boxMin.y - P.y) / R.y : 1e30f;
    float tz = abs(R.z) > 1e-8f ? (R.z > 0.0f ? boxMax.z - P.z : boxMin.z - P.z) / R.z : 1e30f;
    float t = max(min(min(tx, ty), tz), 0.0f);
    return P + R * t - probePosition;
}

// ---------------------------------------------------------------------------------------------
// Influence (Lagarde and Zanuttini 2012, "Local Image-based Lighting With Parallax-corrected
// Cubemap", section "Blending"): each probe lights the points inside its influence box, fully
// at least `band` metres inside every face and fading linearly to 0 at the faces. The runtime
// orders probes from the smallest influence volume to the largest and takes, per pixel, the
// first two that reach it: c1 = w1, c2 = (1 - w1) w2, normalised by c1 + c2 (an inner volume
// overrides an outer one; across a boundary the two blend).
float probeInfluenceWeight(vec3 p, vec3 influenceMin, vec3 influenceMax, float band) {
    vec3 inside = min(p - influenceMin, influenceMax - p);
    float d = min(min(inside.x, inside.y), inside.z);
    return saturate(d / max(band, 1e-4f));
}

// ---------------------------------------------------------------------------------------------
// Normalization (Lazarov 2011, slide "Environment map normalization": divide by the diffuse
// lighting at the capture point, multiply by the diffuse lighting reconstructed per pixel;
// docs/lighting.md "Normalisation"), of the light a probe holds at both ends: everything but the
// punctual lights' direct light (which the probes cannot see and the texels reflect by a lobe of
// their own).
// - The capture's side: the light grid's ambient cube at the capture point without that direct
//   light, E_c(n) (bake/bake_level.hpp probeIrradianceCubes). Its mean over normals E_avg
//   scales the stored texels (probeNormalize; RGB9E5 keeps L / E_avg near 1 / pi), and the
//   cube is kept relative to it: E_c(n) / E_avg (GpuProbe::relativeIrradiance).
// - The pixel's side: E_p(n), a static surface's lightmap texel less its direct light
//   (world::LightmapTexel::indirectIrradiance), a dynamic object's light grid.
// By default a pixel reads L / E_avg and multiplies by E_p(n) (probeDenormalize): L E_p(n) / E_avg.
// With RendererOptions::probesPerNormal (the same statistic at both ends) it divides by
// E_c(n) / E_avg first (probeAtNormal): L E_p(n) / E_c(n), exactly L where the pixel's light
// equals the capture's. Neither is better everywhere (docs/lighting.md measures both): the first
// brightens an up-facing floor's reflections where the capture's mean counts a dark ground under
// it, the second darkens or brightens reflections where a surface's irradiance differs from the
// capture point's for light it does not reflect (a floor beside a wall, a block's side facing a
// lit floor).
// E_avg is floored at PROBE_MIN_IRRADIANCE (lux) so that an unlit channel stays finite;
// E_c(n) / E_avg at PROBE_MIN_RELATIVE_IRRADIANCE, so that a normal whose side of the capture is
// dark (a probe over a black floor, seen from a ceiling) cannot blow a reflection up.
const float PROBE_MIN_IRRADIANCE = 1e-4f;
const float PROBE_MIN_RELATIVE_IRRADIANCE = 0.05f;

vec3 probeNormalize(vec3 radiance, vec3 averageIrradiance) {
    return radiance / max(averageIrradiance, vec3(PROBE_MIN_IRRADIANCE));
}

// A normalised sample over the capture's irradiance at the pixel's normal relative to its mean.
vec3 probeAtNormal(vec3 normalized, vec3 relativeIrradiance) {
    return normalized / max(relativeIrradiance, vec3(PROBE_MIN_RELATIVE_IRRADIANCE));
}

vec3 probeDenormalize(vec3 normalized, vec3 irradiance) { return normalized * irradiance; }

#endif
