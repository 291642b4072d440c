// The BRDF "lego pieces" of onelight, written once for GLSL and C++ (see common.glsl for the
// dialect). Factoring as in the Black Ops slides: f_spec = F * D * V / 4 with
// V = G / (NoL * NoV), so a visibility term of 1 means G = NoL * NoV.
//
// Inputs are clamped dot products (see brdfDots): NoV in [MIN_NOV, 1]; NoL, LoH, NxH2 in [0, 1].
// Every piece returns a finite, non-negative value for any such input, including 0, 1 and
// denormals; tests/shaders checks this and compares each piece against a double reference.
#ifndef ONELIGHT_BRDF_GLSL
#define ONELIGHT_BRDF_GLSL

#include "common.glsl"

// ---------------------------------------------------------------------------------------------
// Constants

const float GLOSS_MAX_SPEC_POWER = 8192.0f;  // Blinn-Phong exponent at gloss 1
const float MIN_NOV = 1e-4f;    // view at or below the horizon (normal maps) is clamped here
const float MIN_DENOM = 1e-12f; // floor of denominators that vanish only where NoL * f -> 0

// Model selectors. One place picks the variant: specularD / specularV / specularF below.
// GLSL callers pass specialization constants, so the unused branches fold away.
#define NDF_BLINN_PHONG 0
#define NDF_BECKMANN 1
#define NDF_GGX 2

#define VIS_NONE 0
#define VIS_KELEMEN 1
#define VIS_SCHLICK_SMITH 2
#define VIS_SMITH_CORRELATED 3

#define FRESNEL_NONE 0
#define FRESNEL_SCHLICK 1

// ---------------------------------------------------------------------------------------------
// Gloss conversions

// Lazarov 2011, "Physically Based Lighting in Call of Duty: Black Ops", slide "Phong lobe NDF":
// n = 8192^g = 2^(13 g).
float specPower_fromGloss(float gloss) { return exp2(13.0f * gloss); }

// Inverse of specPower_fromGloss.
float gloss_fromSpecPower(float n) { return log2(n) * (1.0f / 13.0f); }

// Lazarov 2011, slide "Beckmann": m = sqrt(2 / (n + 2)), the Beckmann roughness whose lobe
// matches a Blinn-Phong lobe of exponent n.
float beckmannM_fromSpecPower(float n) { return sqrt(2.0f / (n + 2.0f)); }

// Chan 2018, "Material Advances in Call of Duty: WWII", eq. 2: alpha = sqrt(2 / (1 + 2^(18 g))).
// Reaches 1 at gloss 0 and 0.00276 at gloss 1.
float ggxAlpha_fromGloss(float gloss) { return sqrt(2.0f / (1.0f + exp2(18.0f * gloss))); }

// Lazarov 2011, slide "Schlick-Smith": a = m sqrt(2 / pi) = 1 / sqrt(pi/4 n + pi/2).
float schlickSmithA_fromSpecPower(float n) {
    return inversesqrt(0.25f * PI * n + 0.5f * PI);
}

// ---------------------------------------------------------------------------------------------
// Normal distribution functions D(h); each integrates to 1 as D(h) NoH over the hemisphere.
// They take NxH2 = |n x h|^2 = 1 - NoH^2 (see brdfDots), not NoH: at gloss 1 the GGX lobe lives
// where 1 - NoH ~ 1e-6, which a float NoH resolves only in steps of 6e-8 (a 1.6% staircase in D,
// visible as banded highlights); |n x h|^2 has full relative precision there.

// Lazarov 2011, "Physically Based Lighting in Call of Duty: Black Ops", slide "Phong lobe NDF":
// D = (n + 2) / (2 pi) NoH^n, with NoH^n = exp(n/2 ln(1 - NxH2)) evaluated by log1m.
float D_BlinnPhong(float NxH2, float n) {
    return (n + 2.0f) * (0.5f * INV_PI) * exp(0.5f * n * log1m(saturate(NxH2)));
}

// Lazarov 2011, slide "Beckmann": D = exp((NoH^2 - 1) / (m^2 NoH^2)) / (pi m^2 NoH^4),
// with NoH^2 = 1 - NxH2, floored where the exponential is 0 anyway.
float D_Beckmann(float NxH2, float m) {
    float m2 = m * m;
    float s2 = saturate(NxH2);
    float c2 = max(1.0f - s2, 1e-8f);
    return exp(-s2 / (m2 * c2)) / (PI * m2 * c2 * c2);
}

// Walter et al. 2007, "Microfacet Models for Refraction through Rough Surfaces", eq. 33 (GGX):
// D = a^2 / (pi (NxH2 + NoH^2 a^2)^2): a sum of two non-negative terms, exact near NoH = 1.
float D_GGX(float NxH2, float a) {
    float a2 = a * a;
    float s2 = saturate(NxH2);
    float d = s2 + (1.0f - s2) * a2;
    return a2 / (PI * d * d);
}

// The specular per unit Fresnel of a spread of mirror facets, f NoL / F = D(h) NoH / (4 VoH),
// for facet normals distributed as a Beckmann lobe of alpha `a` that do not mask each other (a
// normal map's texels, each much narrower than the spread: shaders/material.glsl, "A
// footprint's bumps"). Derivation: a facet of normal m reflects F D_m(m.h) / (4 m.v) times the
// illuminance; averaged over facets of density D(m) m.n per projected area, the narrow D_m picks
// m = h, and h.v = VoH. Its albedo at normal view is the lobe's share of h within 45 degrees of
// n, 1 - exp(-1 / a^2) (the reflection leaves below the horizon beyond).
float specularFacets_Beckmann(float NxH2, float LoH, float a) {
    return D_Beckmann(NxH2, a) * sqrt(1.0f - saturate(NxH2)) / (4.0f * max(LoH, 1e-4f));
}

// ln Gamma(x) for x >= 1: Stirling's series at x + 2, where its error is under 2e-7, brought back
// by Gamma(x + 2) = (x + 1) x Gamma(x).
float logGamma(float x) {
    float z = x + 2.0f;
    float inv = 1.0f / z, inv2 = inv * inv;
    float series = inv * (1.0f / 12.0f - inv2 * (1.0f / 360.0f - inv2 * (1.0f / 1260.0f)));
    return (z - 0.5f) * log(z) - z + 0.918938533f + series - log(x * (x + 1.0f));
}

// Slopes with a Nakagami distribution of their length (Nakagami 1960; 2D, isotropic), mean
// square a^2 and shape m >= 1: the density of slopes
//   P(s) = m^m / (pi Gamma(m) a^(2m)) |s|^(2m - 2) exp(-m |s|^2 / a^2),
// Gaussian at m = 1 (D_Beckmann's slopes), narrowing to a ring of radius a as m grows. Their
// kurtosis E|s|^4 / (E|s|^2)^2 is (m + 1) / m, so m = 1 / (k - 1) matches a footprint's
// (normal_gloss_mips.hpp). As an NDF, D(h) = P(tan theta_h) / cos^4 theta_h; with x =
// m tan^2 / a^2, pi P t2 = x^m exp(-x) / Gamma(m), whose log has terms of the size of m only
// (where m log(m / a^2) and (m - 1) log t2 each reach 90 for a glossy lobe, and their rounding
// showed as 1e-5 of D between the GPU and the CPU).
float D_NakagamiSlopes(float NxH2, float a, float m) {
    float s2 = saturate(NxH2);
    float c2 = max(1.0f - s2, 1e-8f);
    float t2 = max(s2 / c2, 1e-30f);  // tan^2 theta_h
    float x = m * t2 / max(a * a, 1e-12f);
    return exp(m * log(max(x, 1e-30f)) - x - logGamma(m)) * INV_PI / (t2 * c2 * c2);
}

// The shape of a ring of slopes (kurtosis 17/16): shaders/material.glsl,
// facetGaussianShare_fromKurtosis.
const float FACET_RING_SHAPE = 8.0f;

// specularFacets_Beckmann for facets of Nakagami slopes of shape m (the same at m = 1).
float specularFacets_Nakagami(float NxH2, float LoH, float a, float m) {
    return D_NakagamiSlopes(NxH2, a, m) * sqrt(1.0f - saturate(NxH2)) / (4.0f * max(LoH, 1e-4f));
}

// specularFacets_Beckmann for facets of a tabulated distribution: `D` the table's normal
// distribution at h (bake/textures/facet_table.hpp: D(m) m.n integrates to 1 over the
// hemisphere about the surface's normal n), NoH = h.n.
float specularFacets_Table(float D, float NoH, float LoH) {
    return D * max(NoH, 0.0f) / (4.0f * max(LoH, 1e-4f));
}

// ---------------------------------------------------------------------------------------------
// Visibility V = G / (NoL NoV)

// Lazarov 2011, slide "No visibility function": G = NoL NoV.
float V_None() { return 1.0f; }

// Kelemen and Szirmay-Kalos 2001, via Lazarov 2011, slide "Kelemen-Szirmay-Kalos":
// V = 4 / ((v + l).(v + l)) = 1 / LoH^2, since |v + l| = 2 LoH. LoH -> 0 only when l = -v,
// where one of NoL, NoV is <= 0; the floor keeps that case finite.
float V_Kelemen(float LoH) { return 1.0f / max(LoH * LoH, 1e-8f); }

// Schlick 1994 via Lazarov 2011, slide "Schlick-Smith":
// V = 1 / ((NoL (1 - a) + a) (NoV (1 - a) + a)), a = schlickSmithA_fromSpecPower(n).
float V_SchlickSmith(float NoV, float NoL, float a) {
    return 1.0f / ((NoL * (1.0f - a) + a) * (NoV * (1.0f - a) + a));
}

// mu * Lambda(mu) of the Smith masking function for Beckmann (exact, Walter et al. 2007 eq. 25
// with erfc from Abramowitz and Stegun 7.1.26, |error| <= 1.5e-7):
//   c = mu / (m sqrt(1 - mu^2)),  Lambda = (exp(-c^2) / (c sqrt(pi)) - erfc(c)) / 2
//   mu Lambda = exp(-c^2) / 2 * (m sqrt(1 - mu^2) / sqrt(pi) - mu P(t)),  t = 1 / (1 + p c)
// The product stays finite as mu -> 0, where Lambda itself diverges. c is capped at 8, where
// exp(-c^2) = 1.6e-28 makes the term vanish.
float muLambda_Beckmann(float mu, float m) {
    float s = sqrt(oneMinusSq(mu));
    float c = min(mu / max(m * s, 1e-20f), 8.0f);
    float t = 1.0f / (1.0f + 0.3275911f * c);
    float P = t * (0.254829592f +
                   t * (-0.284496736f + t * (1.421413741f + t * (-1.453152027f + t * 1.061405429f))));
    float bracket = max(m * s * 0.564189583547756f - mu * P, 0.0f);
    return 0.5f * exp(-c * c) * bracket;
}

// Heitz 2014, "Understanding the Masking-Shadowing Function in Microfacet-Based BRDFs", eq. 99
// (height-correlated Smith): G = 1 / (1 + Lambda(v) + Lambda(l)), so
// V = 1 / (NoL NoV + NoL (NoV Lambda(v)) + NoV (NoL Lambda(l))), Beckmann's Lambda.
float V_SmithBeckmannCorrelated(float NoV, float NoL, float m) {
    float d = NoL * NoV + NoL * muLambda_Beckmann(NoV, m) + NoV * muLambda_Beckmann(NoL, m);
    return 1.0f / max(d, MIN_DENOM);
}

// Heitz 2014, eq. 99 with GGX's Lambda = (sqrt(1 + a^2 tan^2) - 1) / 2:
// V = 2 / (NoL sqrt(NoV^2 + a^2 (1 - NoV^2)) + NoV sqrt(NoL^2 + a^2 (1 - NoL^2))).
// (Filament's V_SmithGGXCorrelated is this divided by 4.) No cancellation: all terms >= 0.
float V_SmithGGXCorrelated(float NoV, float NoL, float a) {
    float a2 = a * a;
    float lambdaV = NoL * sqrt(NoV * NoV + a2 * oneMinusSq(NoV));
    float lambdaL = NoV * sqrt(NoL * NoL + a2 * oneMinusSq(NoL));
    return 2.0f / max(lambdaV + lambdaL, MIN_DENOM);
}

// ---------------------------------------------------------------------------------------------
// Fresnel

// Lazarov 2011, slide "Fresnel": no Fresnel, the specular colour itself.
vec3 F_None(vec3 f0) { return f0; }

// Schlick 1994, via Lazarov 2011, slide "Schlick's approximation", microfacet form on h.l:
// F = f0 + (1 - f0) (1 - LoH)^5.
vec3 F_Schlick(vec3 f0, float LoH) { return f0 + (vec3(1.0f) - f0) * pow5(1.0f - LoH); }
float F_Schlick(float f0, float LoH) { return f0 + (1.0f - f0) * pow5(1.0f - LoH); }

// ---------------------------------------------------------------------------------------------
// Diffuse

// Lambert: f = 1 / pi, directional albedo exactly 1.
float Fd_Lambert() { return INV_PI; }

// Chan 2018, "Material Advances in Call of Duty: WWII", sec. 5 (multiscattering diffuse): a fit
// to Lambertian microfacets under the GGX NDF of `gloss` (eq. 2) with multiple scattering between
// them, per unit albedo. A rough surface (gloss 0) goes from Lambert towards the microfacet
// response LoH + (1 - LoH)^5; a smooth one darkens at grazing view and light,
// (1 - 0.75 (1 - NoL)^5)(1 - 0.75 (1 - NoV)^5); the last term is the retro-reflection peak
// around h = n. With g = gloss and NoH = sqrt(1 - NxH2):
//   f = (mix(F_rough, F_smooth, saturate(2.2 g - 0.5)) + F_retro) / pi,
//   F_retro = ((34.5 g - 59) g + 24.5) LoH 2^(-max(73.2 g - 21.2, 8.9) sqrt(NoH)).
float Fd_Chan(float NoV, float NoL, float LoH, float NxH2, float gloss) {
    float g = saturate(gloss);
    float roughResponse = LoH + pow5(1.0f - LoH);
    float smoothResponse = (1.0f - 0.75f * pow5(1.0f - NoL)) * (1.0f - 0.75f * pow5(1.0f - NoV));
    float fd = mix(roughResponse, smoothResponse, saturate(2.2f * g - 0.5f));
    float NoH = sqrt(1.0f - saturate(NxH2));
    float retro = ((34.5f * g - 59.0f) * g + 24.5f) * LoH *
                  exp2(-max(73.2f * g - 21.2f, 8.9f) * sqrt(NoH));
    // The retro coefficient dips to -0.7 near g = 0.86, where its exponential is 2^-41: the floor
    // changes nothing measurable and keeps the piece non-negative.
    return (fd + max(retro, 0.0f)) * INV_PI;
}

// ---------------------------------------------------------------------------------------------
// Environment "Fresnel": the directional albedo of the specular BRDF with Schlick Fresnel,
// written as f0 * scale + bias. Returned as vec2(scale, bias).

// Lazarov 2011, slide "Environment map Fresnel": F = c + (1 - c) (1 - NoV)^5 / (4 - 3 g),
// i.e. scale = 1 - k, bias = k, k = (1 - NoV)^5 / (4 - 3 g).
vec2 EnvBRDF_BlackOps(float NoV, float gloss) {
    float k = pow5(1.0f - NoV) / (4.0f - 3.0f * gloss);
    return vec2(1.0f - k, k);
}

// ---------------------------------------------------------------------------------------------
// Dot products from vectors, robust at l = -v and below the horizon.

struct BrdfDots {
    float NoV;   // [MIN_NOV, 1]
    float NoL;   // [0, 1]
    float LoH;   // [0, 1]
    float NxH2;  // |n x h|^2 = 1 - NoH^2, [0, 1]
};

// n, v, l unit vectors. h is never normalized: with VoL = v.l, |l + v|^2 = 2 + 2 VoL,
// LoH = (1 + VoL) / |l + v| and |n x h|^2 = |n x (l + v)|^2 / |l + v|^2; at l = -v the
// numerators vanish with the denominators, and the floor keeps the quotient at 0.
BrdfDots brdfDots(vec3 n, vec3 v, vec3 l) {
    float VoL = dot(v, l);
    float lenH2 = max(2.0f + 2.0f * VoL, 1e-30f);
    vec3 nxh = cross(n, l + v);
    BrdfDots d;
    d.NoV = clamp(dot(n, v), MIN_NOV, 1.0f);
    d.NoL = saturate(dot(n, l));
    d.LoH = saturate((1.0f + VoL) * inversesqrt(lenH2));
    d.NxH2 = saturate(dot(nxh, nxh) / lenH2);
    return d;
}

// ---------------------------------------------------------------------------------------------
// Dispatch: the one place a model is picked.

float specularD(int ndf, float NxH2, float gloss) {
    if (ndf == NDF_GGX) return D_GGX(NxH2, ggxAlpha_fromGloss(gloss));
    float n = specPower_fromGloss(gloss);
    if (ndf == NDF_BECKMANN) return D_Beckmann(NxH2, beckmannM_fromSpecPower(n));
    return D_BlinnPhong(NxH2, n);
}

// VIS_SMITH_CORRELATED is the exact height-correlated Smith term of the NDF; for Blinn-Phong it
// uses Beckmann's Lambda at the matching m (Walter et al. 2007, sec. 5.2).
float specularV(int ndf, int vis, float NoV, float NoL, float LoH, float gloss) {
    if (vis == VIS_KELEMEN) return V_Kelemen(LoH);
    if (vis == VIS_SCHLICK_SMITH)
        return V_SchlickSmith(NoV, NoL, schlickSmithA_fromSpecPower(specPower_fromGloss(gloss)));
    if (vis == VIS_SMITH_CORRELATED) {
        if (ndf == NDF_GGX) return V_SmithGGXCorrelated(NoV, NoL, ggxAlpha_fromGloss(gloss));
        return V_SmithBeckmannCorrelated(NoV, NoL,
                                         beckmannM_fromSpecPower(specPower_fromGloss(gloss)));
    }
    return V_None();
}

vec3 specularF(int fresnel, vec3 f0, float LoH) {
    if (fresnel == FRESNEL_SCHLICK) return F_Schlick(f0, LoH);
    return F_None(f0);
}

// The specular BRDF times the cosine, f_spec * NoL = F D V NoL / 4: what a light of unit
// irradiance (at normal incidence) reflects towards v.
vec3 specularLobe(int ndf, int vis, int fresnel, vec3 f0, float gloss, BrdfDots d) {
    float DV = specularD(ndf, d.NxH2, gloss) * specularV(ndf, vis, d.NoV, d.NoL, d.LoH, gloss);
    return specularF(fresnel, f0, d.LoH) * (0.25f * DV * d.NoL);
}

#endif
