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

// A mapped normal n whose mirror reflection of the view v would leave below the plane of the
// surface's own normal ns, bent towards ns just enough that the reflection stays `lift` above
// that plane (lift = min(0.9 ns.v, 0.01), as Blender Cycles' ensure_valid_reflection): the
// reflection lifted to that elevation, and the normal the half vector of v and it. A normal map
// is not a microsurface: where a bump faces away from the view, the reference ended the paths
// its reflection sent under the surface (and weighted its diffuse by the bump's grazing
// Fresnel), while the frame read the probe below the horizon; both now shade the bent normal.
vec3 normal_withValidReflection(vec3 n, vec3 ns, vec3 v) {
    float lift = min(0.9f * dot(ns, v), 0.01f);
    vec3 r = n * (2.0f * dot(n, v)) - v;
    float rUp = dot(r, ns);
    if (rUp >= lift) return n;
    vec3 across = r - ns * rUp;
    float acrossLength2 = dot(across, across);
    if (acrossLength2 < 1e-12f) return ns;  // the reflection straight down: no side to keep
    vec3 lifted = across * (sqrt(max(1.0f - lift * lift, 0.0f)) * inversesqrt(acrossLength2)) +
                  ns * lift;
    vec3 h = v + lifted;
    float hLength2 = dot(h, h);
    return hLength2 > 1e-12f ? h * inversesqrt(hLength2) : ns;
}

// ---------------------------------------------------------------------------------------------
// What the surface's plane takes from a bumped texel's specular lobe.
//
// The split-sum table counts a lobe over the hemisphere of its own normal n. Where n is a normal
// map's and not the surface's ns, part of that hemisphere lies below the surface's plane, and
// the reference ends the paths sent there (bake/lighting/radiance.cpp); on the accuracy scenes'
// bumped floor under a sky that is 5-22% of the specular (docs/materials.md,
// "A footprint's bumps"). The share kept, linearised about the mirror direction r = reflect(-v, n)
// (n bent by normal_withValidReflection, so that r.ns >= 0): a microfacet whose slope from n is s
// (2D, in n's tangent plane) reflects v to l = r + 2 ((v.s) n + (n.v) s) to first order, so
/*
     l.ns = e + 2 g.s,     e = r.ns,     g = (n.ns) v_t + (n.v) ns_t
     l.n  = n.v + 2 v_t.s                 (v_t, ns_t: v and ns less their parts along n)

     kept = 1 - P(l.ns < 0 and l.n > 0) / P(l.n > 0)
*/
// under GGX's slope distribution (Walter et al. 2007), whose radial survival is
// alpha^2 / (alpha^2 + |s|^2). The terms in kept are a half-plane and a wedge of two, in closed
// form below. Left out: the lobe's masking and Fresnel across it (the cut lies at l.n near 0,
// where masking is strongest) and the curvature of the map from s to l at grazing view, both of
// which make the cut smaller than this: over the egg-crate texels, from 2.8 to 46.6 m and alpha
// 0.0225 to 0.3, the share is 0.09 under the quadrature at worst (onelight-lab horizon-cut).

// P(u.s > p) for a unit u: a half-plane of GGX's slopes of roughness alpha at distance p >= 0.
float ggxSlopesBeyond(float p, float alpha) {
    return 0.5f * (1.0f - p * inversesqrt(alpha * alpha + p * p));
}

// P(u_a.s > p and u_b.s > q) for unit u_a, u_b with u_a.u_b = cosGamma, p, q >= 0: the polar
// integral of the radial survival beyond the wedge's nearer edge, alpha^2 / (alpha^2 +
// r_min(phi)^2), over the directions phi (from u_a) that reach both half-planes,
// (gamma - pi/2, pi/2). The edge is u_b's (r = q / cos(phi - gamma)) up to phi* = atan2(q - p
// cos gamma, p sin gamma), u_a's (r = p / cos phi) after it. With the antiderivative of
// cos^2 phi / (cos^2 phi + k^2), phi - k / sqrt(1 + k^2) atan(k tan phi / sqrt(1 + k^2)), the
// phi terms sum to pi - gamma and the rest needs phi* only as a direction:
/*
     2 pi P = pi - gamma - kq / cq (atan2(kq sin(phi* - gamma), cq cos(phi* - gamma)) + pi/2)
                         - kp / cp (pi/2 - atan2(kp sin phi*, cp cos phi*))
     k = distance / alpha,  c = sqrt(1 + k^2)
*/
float ggxSlopesInWedge(float p, float q, float cosGamma, float alpha) {
    float sinGamma = sqrt(max(1.0f - cosGamma * cosGamma, 0.0f));
    if (cosGamma < 0.0f && sinGamma < 1e-4f) return 0.0f;  // opposite half-planes: disjoint
    float x = p * sinGamma, y = q - p * cosGamma;  // phi*'s direction, x >= 0
    float r = sqrt(x * x + y * y);
    vec2 phi = r > 1e-30f ? vec2(x, y) / r : vec2(1.0f, 0.0f);  // (cos, sin) phi*
    vec2 phiFromB = vec2(phi.x * cosGamma + phi.y * sinGamma, phi.y * cosGamma - phi.x * sinGamma);
    if (phiFromB.x < 0.0f) {  // phi* before gamma - pi/2, where the range starts: u_a's edge alone
        phi = vec2(sinGamma, -cosGamma);
        phiFromB = vec2(0.0f, -1.0f);
    }
    float kp = p / alpha, kq = q / alpha;
    float cp = sqrt(1.0f + kp * kp), cq = sqrt(1.0f + kq * kq);
    float sum = (PI - acos(clamp(cosGamma, -1.0f, 1.0f))) -
                (kq / cq) * (atan(kq * phiFromB.y, max(cq * phiFromB.x, 1e-30f)) + 0.5f * PI) -
                (kp / cp) * (0.5f * PI - atan(kp * phi.y, max(cp * phi.x, 1e-30f)));
    return max(sum, 0.0f) * (0.5f * INV_PI);
}

// The share of the specular lobe at normal n (bent, see above), view v and GGX roughness alpha
// that leaves above the plane of the surface's normal ns: 1 where n is ns.
float specularShareAboveSurface(vec3 n, vec3 ns, vec3 v, float alpha) {
    float NoV = dot(n, v), NoNs = dot(n, ns);
    vec3 vt = v - n * NoV;
    vec3 g = vt * NoNs + (ns - n * NoNs) * NoV;
    float e = 2.0f * NoV * NoNs - dot(v, ns);
    float gLength = length(g), vtLength = length(vt);
    if (NoV <= 0.0f || gLength < 1e-6f) return 1.0f;
    alpha = max(alpha, 1e-4f);
    float p = max(e, 0.0f) / (2.0f * gLength);
    float below = ggxSlopesBeyond(p, alpha);
    if (vtLength < 1e-6f) return saturate(1.0f - below);  // v along n: no slope turns l under n
    float q = NoV / (2.0f * vtLength);
    float cosGamma = clamp(dot(g, vt) / (gLength * vtLength), -1.0f, 1.0f);
    float cut = max(below - ggxSlopesInWedge(p, q, cosGamma, alpha), 0.0f);
    return saturate(1.0f - cut / max(1.0f - ggxSlopesBeyond(q, alpha), 1e-6f));
}

// The GGX lobe's microsurface area per unit projected area, minus 1 (Chan 2018, "Material
// Advances in Call of Duty: WWII", sec. 2.1: the lobe's area-weighted average normal has length
// 1 / A). Closed form of A, the integral of D_GGX over the hemisphere, for alpha <= 1:
/*
   A = alpha^2 int_0^inf sqrt(1 + u) / (alpha^2 + u)^2 du        (u = tan^2 theta_m)
     = 1 + alpha^2 atanh(b) / b,   b = sqrt(1 - alpha^2),  atanh(b) = log((1 + b) / alpha)
                      +-----------------------------------------------+
                      | A - 1 = alpha^2 log((1 + b) / alpha) / b      |
                      +-----------------------------------------------+
*/
// (1 - b^2 = alpha^2 removes the cancellation of (1 + b) / (1 - b)); atanh(b) / b = 1 + b^2 / 3 +
// O(b^4) near alpha = 1 (gloss 0: A = 2). Matches bake::ggxLobeStatistics's quadrature to 2e-12.
float ggxExcessArea(float alpha) {
    float b = sqrt(max(1.0f - alpha * alpha, 0.0f));
    float ratio = b < 1e-3f ? 1.0f + b * b * (1.0f / 3.0f) : log((1.0f + b) / alpha) / b;
    return alpha * alpha * ratio;
}

// Chan 2018, sec. 2.1 and 3: the gloss whose GGX lobe has the average normal length 1 - d. The
// rational fit of bake::averageNormalLengthFit, P3 / Q2 in x = (-log2 d - 1) / 13.2809 (the
// table's range, gloss 0 to 1), max error 4.6e-4 in gloss (tests/textures checks these numbers
// against the fit). d = 0 gives 1; NaN gives 0 (a broken fetch should not sparkle).
float gloss_fromAverageNormalDistance(float d) {
    if (!(d >= 0.0f)) return 0.0f;
    if (d == 0.0f) return 1.0f;
    float x = saturate((-log2(d) - 1.0f) * (1.0f / 13.280911336918688f));
    float p = 4.55163588e-4f + x * (4.26408704f + x * (50.6270528f + x * 93.4651985f));
    float q = 1.0f + x * (27.6837885f + x * 119.638839f);
    return saturate(p / q);
}

// Toksvig 2005, "Mipmapping Normal Maps", in Chan 2018's terms: a filtered normal-map fetch
// (bilinear, trilinear or anisotropic) averages unit texels n_i with weights w_i into a vector
// shorter than 1 by their spread. Each texel's lobe has the average normal n_i / A, so the
// mixture's has length |sum w_i n_i| / A: its distance from a mirror is
//   d = 1 - (1 - u) / A = (e + u) / (1 + e),   e = A - 1,  u = 1 - |n_f|,
// and the gloss becomes that of the lobe with this distance (never glossier). `filtered` is the
// fetched texel decoded to [-1, 1] (before the normal scale). An 8-bit texel decodes to a vector
// whose length misses 1 by up to (|x| + |y| + |z|) / 255 (each component rounds by up to 1/255):
// that much shortening is quantization, not spread, and is not counted.
float gloss_withFilteredNormal(float gloss, vec3 filtered) {
    float quantization = (abs(filtered.x) + abs(filtered.y) + abs(filtered.z)) * (1.0f / 255.0f);
    float u = 1.0f - length(filtered) - quantization;
    if (!(u > 0.0f)) return gloss;
    float e = ggxExcessArea(ggxAlpha_fromGloss(gloss));
    return min(gloss, gloss_fromAverageNormalDistance((e + u) / (1.0f + e)));
}

// ---------------------------------------------------------------------------------------------
// A footprint's bumps (docs/materials.md, "A footprint's bumps").
//
// A pixel far from the camera covers many texels of a normal map. CLEAN's mips (Olano and Baker
// 2010, sec. 5; bake/textures/normal_gloss_mips.hpp) give its lobe alpha^2 = alpha_b^2 + s^2:
// the texels' own lobes (alpha_b, the metallic-roughness texture's A, `baseGloss` here) plus the
// variance s^2 of the footprint's slopes about their mean, over both axes. The two parts reflect
// differently. The texels' lobes are microfacet lobes, which mask each other (Smith). The
// normals' spread is the normal map's texels, which do not: each is a small mirror of its own
// lobe, whose Fresnel and energy split are its own (at its own view angle). The runtime shades the
// spread's share of the lobe as such facets (specularFacets_Beckmann), and the footprint's energy
// split as the mean of its texels' over a ring of normals about the mean, at slope s
// (footprintRingNormal). Where the texture stage also stored the slopes' kurtosis k (the normal
// texture's A), the facets take its shape (facetGaussianShare_fromKurtosis),
// and the mean puts a share of its weight on the mean normal and moves the ring out
// (footprintCentreWeight, footprintRingRadius): an egg crate's slopes sit near their extremes
// (k 1.25), a rough stone's are nearer Gaussian (k 2).

// s^2 = alpha^2 - alpha_b^2, 0 where baseGloss is at least gloss (a single texel, or a
// footprint of parallel normals). With alpha^2 = 2 / (1 + 2^(18 g)) (Chan 2018, eq. 2) the
// difference is 2 2^(18 g) (2^(18 (g_b - g)) - 1) / ((1 + 2^(18 g)) (1 + 2^(18 g_b))), without
// the cancellation of subtracting the two alphas when the footprint is nearly flat.
float bumpSlopeVariance(float gloss, float baseGloss) {
    float g = saturate(gloss);
    float gb = max(saturate(baseGloss), g);
    float e = exp2(18.0f * g), eb = exp2(18.0f * gb);
    return 2.0f * e * exp2m1(18.0f * (gb - g)) / ((1.0f + e) * (1.0f + eb));
}

// s^2 / alpha^2: the share of the lobe that is the normals' spread, in [0, 1].
float bumpShare(float gloss, float baseGloss) {
    float a = ggxAlpha_fromGloss(gloss);
    return saturate(bumpSlopeVariance(gloss, baseGloss) / max(a * a, 1e-20f));
}

// s: the RMS slope of the footprint's normals about their mean, over both axes.
float bumpSlopeRadius(float gloss, float baseGloss) { return sqrt(bumpSlopeVariance(gloss, baseGloss)); }

// The footprint's slopes of kurtosis k (1 where not known) as a share 1 - 1/k at the mean normal
// and the rest on the ring, at radius s sqrt(k): the rule with the slopes' second and fourth
// moments, E|s|^2 = s^2 and E|s|^4 = k s^4. At k = 1, the ring at the RMS slope alone.
float footprintCentreWeight(float kurtosis) { return 1.0f - 1.0f / max(kurtosis, 1.0f); }
float footprintRingRadius(float radius, float kurtosis) { return radius * sqrt(max(kurtosis, 1.0f)); }

// The whole lobe's facets as a share w of Gaussian slopes (specularFacets_Beckmann) and the rest
// on a ring (specularFacets_Nakagami at FACET_RING_SHAPE, kurtosis k_r = 17/16), of one mean
// square: w 2 + (1 - w) k_r is the facets' kurtosis. That is the bumps' slopes (variance s2,
// kurtosis k) plus the texels' own lobes taken as Gaussian (variance b2), independent and
// isotropic:
//   E|x + y|^4 = k s2^2 + 4 s2 b2 + 2 b2^2,   kurtosis = that / (s2 + b2)^2,
// so w = (kurtosis - k_r) / (2 - k_r), in [0, 1]: slopes more peaked than a Gaussian's (k > 2)
// are shaded as Gaussian. A kurtosis says nothing of how many slopes lie near the mean; a
// Nakagami lobe of the whole kurtosis would have none there (an egg crate's have a third of a
// Gaussian's), the mixture has w of a Gaussian's.
float facetGaussianShare_fromKurtosis(float kurtosis, float s2, float b2) {
    float total = s2 + b2;
    if (total <= 0.0f) return 1.0f;
    float k = (max(kurtosis, 1.0f) * s2 * s2 + 4.0f * s2 * b2 + 2.0f * b2 * b2) / (total * total);
    const float ringKurtosis = (FACET_RING_SHAPE + 1.0f) / FACET_RING_SHAPE;
    return saturate((k - ringKurtosis) / (2.0f - ringKurtosis));
}

// The whole tile's facets (the normal map's facet table, bake/textures/facet_table.hpp) give the
// facets' shape; the footprint gives their moments. A footprint's slopes are taken as the tile's,
// moved to the footprint's mean slope and scaled to its lobe: a slope q of the footprint is the
// tile's q' = (q - mean) k + tileMean, k = tileAlpha / alpha (the whole lobes' alphas, CLEAN's
// alpha^2 being the mean square of the slopes and the texels' lobes), so that
//   P(q) = k^2 P_tile(q'),   D(h) = P(q) / h.z^4 = k^2 D_tile(m') (m'.z / h.z)^4,
// m' the unit normal of slope q'. Where the footprint holds the whole tile, mean = tileMean and
// k = 1: the table itself. Where it holds a part, its moments are the part's (as the mixture of
// facetGaussianShare_fromKurtosis keeps them) and its shape the tile's, whose slopes fill the
// middle of their range as the tile's do and as no ring does: an egg crate's glint far away is
// a filled fan, not a ring with a dark middle.
// A footprint whose bumps' variance s2 nears the whole tile's, tileS2, is taken as the whole tile
// (facetTableWhole 1: the tile's mean slope and k = 1), the filter's estimate of its mean slope
// and lobe set aside: such a footprint holds most of the tile's slopes, and the texture filter
// takes its moments from mip texels of half a tile and more, whose means swing with the tile's
// phase under the pixel where the true footprint's hold still. 0 up to a fifth of the tile's
// variance, 1 from 0.9 of it to 1.2, and 0 again from 1.6 (a footprint much rougher than the
// whole tile is a rough part of it, not all of it). On the normal-mapped floor of
// docs/accuracy.md: 7.0% a block with this ramp, 7.8% with it from half the tile's variance.
float facetTableWhole(float s2, float tileS2) {
    if (!(tileS2 > 0.0f)) return 0.0f;
    float r = s2 / tileS2;
    return saturate((r - 0.2f) / 0.7f) * saturate((1.6f - r) / 0.4f);
}

// `h` in the table's frame (x, y along the map's axes, z the surface's normal, z > 0): the
// table's point c' = m'.xy in xy, and the factor z to multiply its density by.
vec3 facetTableLookup(vec3 h, vec2 mean, vec2 tileMean, float k) {
    vec2 q = (vec2(h.x, h.y) / h.z - mean) * k + tileMean;
    float mz = inversesqrt(1.0f + dot(q, q));
    float ratio = mz / h.z;
    return vec3(q * mz, k * k * (ratio * ratio) * (ratio * ratio));
}

// A pixel's footprint split into parts, each read from its own mip texels of a normal map where
// the facet table gives the parts' facets (docs/materials.md, "The footprint's parts"). One lobe
// of a footprint's mean and variance fills the middle of its slopes, where a low sun's glint
// looks: on an egg crate its core comes out 1.5 to 2.5 times the reference's, the flanks half,
// for footprints of 1/8 to 1/2 of a bump. Lobes of the parts follow the slopes' own spread. The
// parts tile the footprint's parallelogram (du, dv: the texture coordinates' derivatives
// across and down the screen; texels: the map's size): FOOTPRINT_PARTS along its long axis
// where it is at least twice as long as it is wide, else two by two. `lod`: the map's level of
// detail of a part, log2 of its longer side in texels. `split` false: the footprint is within a
// texel, and its own lobe is right.
const int FOOTPRINT_PARTS = 4;
struct FootprintParts {
    bool split;
    vec2 offsets[FOOTPRINT_PARTS];  // each part's centre from the footprint's, in du's units
    float lod;
};

FootprintParts footprintParts(vec2 du, vec2 dv, vec2 texels) {
    FootprintParts parts;
    parts.split = false;
    parts.lod = 0.0f;
    float lu = length(du * texels), lv = length(dv * texels);
    for (int i = 0; i < FOOTPRINT_PARTS; ++i) parts.offsets[i] = vec2(0.0f);
    // Within a texel, or a derivative not finite (a degenerate triangle's): not split.
    if (!(max(lu, lv) > 1.0f) || !(max(lu, lv) < 1e9f)) return parts;
    vec2 major = lu >= lv ? du : dv, minor = lu >= lv ? dv : du;
    float majorLength = max(lu, lv), minorLength = min(lu, lv);
    int columns = majorLength >= 2.0f * minorLength ? FOOTPRINT_PARTS : 2;
    int rows = FOOTPRINT_PARTS / columns;
    for (int i = 0; i < FOOTPRINT_PARTS; ++i) {
        float c = float(i % columns), r = float(i / columns);
        parts.offsets[i] = major * ((c + 0.5f) / float(columns) - 0.5f) +
                           minor * ((r + 0.5f) / float(rows) - 0.5f);
    }
    parts.split = true;
    parts.lod = log2(max(majorLength / float(columns), minorLength / float(rows)));
    return parts;
}

// The ring of a footprint's normals: FOOTPRINT_RING_COUNT unit normals about n, each tilted to
// slope `radius` towards cos(phi) t + sin(phi) b (t, b unit and perpendicular to n), phi =
// 2 pi k / count. At the RMS slope, the ring has the footprint's second moment of slopes, so a
// mean over it is exact for a quantity quadratic in the slopes. The energy split is far from
// quadratic at grazing view; on the accuracy scenes' egg-crate bumps, six points give 0.7 to 1.0
// of the mean over every texel, where the pixel's normal with the footprint's lobe gives 1.4 to
// 7 (scripts/footprint-scan.py).
const int FOOTPRINT_RING_COUNT = 6;
vec3 footprintRingNormal(vec3 n, vec3 t, vec3 b, float radius, int k) {
    float phi = float(k) * (2.0f * PI / float(FOOTPRINT_RING_COUNT));
    return normalize(n + (t * cos(phi) + b * sin(phi)) * radius);
}

#endif
