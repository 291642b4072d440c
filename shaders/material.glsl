// glTF metallic-roughness to onelight's material parameters, per texel, written once for GLSL and
// C++. The level compiler applies the same conversion to the factors (world/compiled_level.hpp,
// Material); the runtime applies it per texel to the glTF textures as they are, with mips made
// by a linear blit at upload. Texture processing in the baker (albedo, f0 and gloss maps with
// filtered mips) is planned, not built (docs/architecture.md, "Planned, not built").
#ifndef ONELIGHT_MATERIAL_GLSL
#define ONELIGHT_MATERIAL_GLSL

#include "common.glsl"

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
