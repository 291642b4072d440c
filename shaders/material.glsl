// glTF metallic-roughness to onelight's material parameters, per texel, written once for GLSL and
// C++: the runtime's forward pass shades with it (the glTF textures as they are, mips made by a
// linear blit at upload), the baker and the reference path tracer evaluate every ray hit with it
// (bake/materials), and the level compiler applies it to the factors (world/compiled_level.hpp,
// Material).
#ifndef ONELIGHT_MATERIAL_GLSL
#define ONELIGHT_MATERIAL_GLSL

#include "common.glsl"
#include "lighting.glsl"

// glTF 2.0 specification, Appendix B: diffuse reflectance of the metallic-roughness model,
// albedo = baseColor (1 - metallic).
vec3 albedo_fromMetallic(vec3 baseColor, float metallic) { return baseColor * (1.0f - metallic); }

// glTF 2.0 specification, Appendix B: f0 = mix(0.04, baseColor, metallic).
vec3 specularColor_fromMetallic(vec3 baseColor, float metallic) {
    return vec3(0.04f) * (1.0f - metallic) + baseColor * metallic;
}

// Inverse of ggxAlpha_fromGloss (Chan 2018, eq. 2) with glTF's GGX alpha = roughness^2:
// gloss = log2(2 / roughness^4 - 1) / 18, clamped to [0, 1]; roughness^4 is floored so that a
// mirror (roughness 0) gives gloss 1 without an infinity.
float gloss_fromRoughness(float roughness) {
    float r2 = roughness * roughness;
    float r4 = max(r2 * r2, 1e-12f);
    return saturate(log2(max(2.0f / r4 - 1.0f, 1.0f)) * (1.0f / 18.0f));
}

// A material at one point: what the BRDF needs.
struct MaterialPoint {
    vec3 albedo;  // diffuse reflectance, linear
    vec3 f0;      // specular colour at normal incidence
    float gloss;  // [0, 1]
};

// The material at one point from its base colour (factor times texel, linear), metallic and
// roughness (factors times the metallic-roughness texel, see metallicRoughness_fromTexel), for a
// material of class `materialClass` (MATERIAL_*): a dielectric's f0 is its scalar
// `dielectricF0`, a Lambert-only material has no specular and a metal no diffuse, exactly the
// terms surfaceReflectance and secondaryRadiance of lighting.glsl keep for the class.
MaterialPoint materialPoint(int materialClass, vec3 baseColor, float metallic, float roughness,
                            float dielectricF0) {
    MaterialPoint m;
    m.albedo = albedo_fromMetallic(baseColor, metallic);
    if (materialClass == MATERIAL_METAL) m.albedo = vec3(0.0f);
    if (materialClass == MATERIAL_DIELECTRIC) {
        m.f0 = vec3(dielectricF0);
    } else if (materialClass == MATERIAL_LAMBERT) {
        m.f0 = vec3(0.0f);
    } else {
        m.f0 = specularColor_fromMetallic(baseColor, metallic);
    }
    m.gloss = gloss_fromRoughness(roughness);
    return m;
}

// glTF 2.0 specification, "metallicRoughnessTexture": roughness in G, metallic in B, each
// multiplying its factor; x = metallic, y = roughness. A Lambert-only material ignores the texel.
vec2 metallicRoughness_fromTexel(int materialClass, float metallic, float roughness, vec4 texel) {
    if (materialClass == MATERIAL_LAMBERT) return vec2(metallic, roughness);
    return vec2(metallic * texel.z, roughness * texel.y);
}

// glTF 2.0 specification, "occlusionTexture": 1 + strength (texel.r - 1).
float occlusion_fromTexel(float texelR, float strength) { return 1.0f + strength * (texelR - 1.0f); }

// Tangent-space normal map texel (in [0, 1]) to a unit world normal, glTF convention (+Y up in
// the texture), with the bitangent sign in tangentW and the glTF normalTexture.scale.
vec3 normal_fromTangentSpace(vec3 texel, float scale, vec3 n, vec3 t, float tangentW) {
    float x = (texel.x * 2.0f - 1.0f) * scale;
    float y = (texel.y * 2.0f - 1.0f) * scale;
    float z = texel.z * 2.0f - 1.0f;
    vec3 b = cross(n, t) * tangentW;
    vec3 mapped = t * x + b * y + n * z;
    float len2 = dot(mapped, mapped);
    if (len2 < 1e-12f) return n;
    return mapped * inversesqrt(len2);
}

#endif
