// Every BRDF piece behind one number, so that a compute shader and C++ evaluate exactly the same
// calls over the same inputs (tests/shaders/gpu_cpu_agreement). Not used for rendering.
//   dots = (NoV, NoL, LoH, NxH2), params = (gloss, f0, unused, unused)
#ifndef ONELIGHT_BRDF_PIECES_GLSL
#define ONELIGHT_BRDF_PIECES_GLSL

#include "brdf.glsl"
#include "env_brdf_fit.glsl"
#include "material.glsl"

#define BRDF_PIECE_COUNT 34

float brdfPiece(int piece, vec4 dots, vec4 params) {
    float NoV = dots.x;
    float NoL = dots.y;
    float LoH = dots.z;
    float NxH2 = dots.w;
    float gloss = params.x;
    float f0 = params.y;
    float n = specPower_fromGloss(gloss);
    BrdfDots d;
    d.NoV = NoV;
    d.NoL = NoL;
    d.LoH = LoH;
    d.NxH2 = NxH2;
    switch (piece) {
        case 0: return specPower_fromGloss(gloss);
        case 1: return gloss_fromSpecPower(n);
        case 2: return beckmannM_fromSpecPower(n);
        case 3: return ggxAlpha_fromGloss(gloss);
        case 4: return schlickSmithA_fromSpecPower(n);
        case 5: return D_BlinnPhong(NxH2, n);
        case 6: return D_Beckmann(NxH2, beckmannM_fromSpecPower(n));
        case 7: return D_GGX(NxH2, ggxAlpha_fromGloss(gloss));
        case 8: return V_None();
        case 9: return V_Kelemen(LoH);
        case 10: return V_SchlickSmith(NoV, NoL, schlickSmithA_fromSpecPower(n));
        case 11: return V_SmithBeckmannCorrelated(NoV, NoL, beckmannM_fromSpecPower(n));
        case 12: return V_SmithGGXCorrelated(NoV, NoL, ggxAlpha_fromGloss(gloss));
        case 13: return F_Schlick(f0, LoH);
        case 14: return Fd_Lambert();
        case 15: return EnvBRDF_BlackOps(NoV, gloss).x;
        case 16: return EnvBRDF_BlackOps(NoV, gloss).y;
        case 17: return EnvBRDF_Fit(NoV, gloss).x;
        case 18: return EnvBRDF_Fit(NoV, gloss).y;
        case 19: return specularLobe(NDF_BLINN_PHONG, VIS_NONE, FRESNEL_SCHLICK, vec3(f0), gloss, d).x;
        case 20: return specularLobe(NDF_BLINN_PHONG, VIS_KELEMEN, FRESNEL_SCHLICK, vec3(f0), gloss, d).x;
        case 21: return specularLobe(NDF_BLINN_PHONG, VIS_SCHLICK_SMITH, FRESNEL_SCHLICK, vec3(f0), gloss, d).x;
        case 22: return specularLobe(NDF_BECKMANN, VIS_SMITH_CORRELATED, FRESNEL_SCHLICK, vec3(f0), gloss, d).x;
        case 23: return specularLobe(NDF_GGX, VIS_SMITH_CORRELATED, FRESNEL_SCHLICK, vec3(f0), gloss, d).x;
        case 24: return Fd_Chan(NoV, NoL, LoH, NxH2, gloss);
        case 25: return ggxExcessArea(ggxAlpha_fromGloss(gloss));
        case 26: return gloss_fromAverageNormalDistance(NxH2);
        case 27: return gloss_withFilteredNormal(gloss, vec3(NoV, NoL, LoH) * 0.57735f);
        case 28: return specularFacets_Beckmann(NxH2, LoH, ggxAlpha_fromGloss(gloss));
        case 29: return bumpShare(gloss, NoL);  // NoL stands for the texels' own gloss
        case 30: return bumpSlopeRadius(gloss, NoL);
        case 31: return footprintReflectance(MATERIAL_DIELECTRIC, DIFFUSE_LAMBERT, vec3(0.5f),
                                             vec3(1.0f - f0), vec3(f0), gloss, NoV, 1.0f, d).x;
        case 32: return specularFacets_Nakagami(NxH2, LoH, ggxAlpha_fromGloss(gloss), FACET_RING_SHAPE);
        case 33: return exp(logGamma(1.0f + 9.0f * NoV));  // Gamma on [1, 10]
    }
    return 0.0f;
}

#endif
