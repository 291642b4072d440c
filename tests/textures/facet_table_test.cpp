// The facet table of a normal map (bake/textures/facet_table.hpp) against closed forms: a flat
// map is its texels' GGX lobe; every table holds a whole distribution (its integral over the
// projected disc is 1); an egg crate's slopes are two independent arcsine distributions rotated
// by 45 degrees (the density the far glint reads); facetTableLookup (shaders/material.glsl)
// moves and scales the tile's facets without losing any; and bad normals and glosses give finite
// tables.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include <glm/glm.hpp>
#include <glm/gtc/packing.hpp>

#include "bake/textures/facet_table.hpp"
#include "shading.hpp"

namespace onelight::test {
namespace {

constexpr double kPi = 3.14159265358979323846;

bake::NormalGlossLevel flatLevel(int size, float gloss) {
    bake::NormalGlossLevel level;
    level.width = level.height = size;
    level.normals.assign(size_t(size) * size_t(size), glm::vec3(0.0f, 0.0f, 1.0f));
    level.gloss.assign(level.normals.size(), gloss);
    return level;
}

// An egg crate h = A sin(2 pi x / P) sin(2 pi y / P) over `size` texels (one period P = size),
// slopes up to `slope`: its normals (-dh/dx, -dh/dy, 1), normalised.
bake::NormalGlossLevel eggCrateLevel(int size, double slope, float gloss) {
    bake::NormalGlossLevel level = flatLevel(size, gloss);
    const double k = 2.0 * kPi / size;
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) {
            const double u = k * (x + 0.5), v = k * (y + 0.5);
            const glm::dvec3 n(-slope * std::cos(u) * std::sin(v),
                               -slope * std::sin(u) * std::cos(v), 1.0);
            level.normals[size_t(y) * size_t(size) + size_t(x)] = glm::vec3(glm::normalize(n));
        }
    return level;
}

// The integral of D over the projected disc, the hemisphere's integral of D(m) m.z (the table's
// points are the disc's cells, each (2 / N)^2; those outside the disc hold the rim's D and are
// left out).
double totalMass(const bake::FacetTable& table) {
    const int n = bake::kFacetTableSize;
    const double cell = 2.0 / n;
    double sum = 0.0;
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) {
            const double cx = (x + 0.5) * cell - 1.0, cy = (y + 0.5) * cell - 1.0;
            if (cx * cx + cy * cy < 1.0)
                sum += double(table.density[size_t(y) * n + x]) * cell * cell;
        }
    return sum;
}

glm::vec3 unitWithSlope(double sx, double sy) {
    return glm::vec3(glm::normalize(glm::dvec3(sx, sy, 1.0)));
}

TEST(FacetTable, AFlatMapIsItsTexelsGgxLobe) {
    // Roughness 0.7 (alpha 0.49): the widening by the table's cells (about 2e-4 in alpha^2 near
    // the middle) moves D by under 0.2% of alpha^2 = 0.24; 1% covers it and the float rounding.
    const float gloss = glsl::gloss_fromRoughness(0.7f);
    const double a = double(glsl::ggxAlpha_fromGloss(gloss));
    const bake::FacetTable table = bake::facetTable(flatLevel(8, gloss), true, true);
    for (double t : {0.0, 0.2, 0.5, 0.9, 1.5}) {
        const glm::vec3 m = unitWithSlope(t, 0.3 * t);
        const double expected = double(glsl::D_GGX(1.0f - m.z * m.z, float(a)));
        EXPECT_NEAR(double(bake::facetTableDensity(table, m)), expected, 0.01 * expected)
            << "slope " << t;
    }
    // The lobe is whole: the heavy tail of GGX beyond the rim (|c| > 0.995, 84 degrees) holds
    // a^2 / (a^2 + tan^2) = 0.2% of it.
    EXPECT_NEAR(totalMass(table), 1.0, 0.01);
}

TEST(FacetTable, AnEggCratesSlopesAreTwoArcsineDistributions) {
    // h = A sin(u) sin(v): its slopes (sx, sy) = s (cos u sin v, sin u cos v) are, as
    // p = (sx + sy) / 2 = (s / 2) sin(u + v) and q = (sy - sx) / 2 = (s / 2) sin(u - v), two
    // independent arcsine distributions on [-s/2, s/2]: P(sx, sy) = f(p) f(q) / 2,
    // f(p) = 1 / (pi sqrt(s^2 / 4 - p^2)), and D(m) = P(slope of m) / m.z^4. Compared away
    // from the arcsine's edges (|p|, |q| <= 0.6 s / 2, where f's relative slope over a table
    // cell is under 3%), on 128 texels of nearly mirror-like lobes (roughness 0.05): 5% covers
    // the cells' widening, the bilinear field between the texel centres and the rounding of
    // the slopes by the table's bilinear read.
    const double s = 0.6;
    const bake::FacetTable table =
        bake::facetTable(eggCrateLevel(128, s, glsl::gloss_fromRoughness(0.05f)), true, true);
    auto f = [&](double p) { return 1.0 / (kPi * std::sqrt(s * s / 4.0 - p * p)); };
    for (const glm::dvec2 slope :
         {glm::dvec2(0.0, 0.0), glm::dvec2(0.0, 0.13), glm::dvec2(0.1, 0.05),
          glm::dvec2(-0.12, 0.08), glm::dvec2(0.15, -0.02)}) {
        const double p = (slope.x + slope.y) / 2.0, q = (slope.y - slope.x) / 2.0;
        // The normals' slopes are -dh: the distribution is symmetric, so P(-s) = P(s).
        const glm::vec3 m = unitWithSlope(slope.x, slope.y);
        const double z4 = std::pow(double(m.z), 4.0);
        const double expected = f(p) * f(q) / 2.0 / z4;
        EXPECT_NEAR(double(bake::facetTableDensity(table, m)), expected, 0.05 * expected)
            << "slope (" << slope.x << ", " << slope.y << ")";
    }
    // Beyond the diamond |sx| + |sy| <= s no facet faces: what is there is the GGX tail of the
    // lobes (widened to 1.5 bins, 0.019 in slope) from the dense edges 0.21 away, about 1.4%
    // of the middle's density by a line mass's tail, alpha^2 / (2 d^3) per unit of it.
    const double middle = double(bake::facetTableDensity(table, unitWithSlope(0.0, 0.0)));
    EXPECT_LT(double(bake::facetTableDensity(table, unitWithSlope(0.5, 0.4))), 0.02 * middle);
    EXPECT_NEAR(totalMass(table), 1.0, 0.01);
}

TEST(FacetTable, TheLookupMovesAndScalesTheTileWithoutLosingFacets) {
    // facetTableLookup: at the tile's own mean and k = 1, the table's point is h's own and the
    // factor 1; moved to another mean and narrowed (k = 2.5), D(h) h.z still integrates to 1
    // over the hemisphere (the remap's Jacobian is in its factor). Midpoint rule on the
    // projected disc, 400^2 points, against a table of the egg crate under rough texels
    // (roughness 0.3: a smooth density the rule resolves): 1.5%.
    const bake::FacetTable table =
        bake::facetTable(eggCrateLevel(32, 0.6, glsl::gloss_fromRoughness(0.3f)), true, true);
    const glm::vec3 h = glm::normalize(glm::vec3(0.2f, -0.1f, 1.0f));
    const glm::vec3 same =
        glsl::facetTableLookup(h, glm::vec2(0.05f, 0.0f), glm::vec2(0.05f, 0.0f), 1.0f);
    EXPECT_NEAR(same.x, h.x, 1e-6f);
    EXPECT_NEAR(same.y, h.y, 1e-6f);
    EXPECT_NEAR(same.z, 1.0f, 1e-5f);
    for (const float k : {1.0f, 2.5f}) {
        const int n = 400;
        const double cell = 2.0 / n;
        double mass = 0.0;
        for (int y = 0; y < n; ++y)
            for (int x = 0; x < n; ++x) {
                const double cx = (x + 0.5) * cell - 1.0, cy = (y + 0.5) * cell - 1.0;
                const double r2 = cx * cx + cy * cy;
                if (r2 >= 0.999) continue;
                const glm::vec3 hm(float(cx), float(cy), float(std::sqrt(1.0 - r2)));
                const glm::vec3 c =
                    glsl::facetTableLookup(hm, glm::vec2(0.1f, -0.05f), glm::vec2(0.0f), k);
                const glm::vec3 mc(c.x, c.y,
                                   std::sqrt(std::max(0.0f, 1.0f - c.x * c.x - c.y * c.y)));
                mass += double(bake::facetTableDensity(table, mc)) * double(c.z) * cell * cell;
            }
        EXPECT_NEAR(mass, 1.0, 0.015) << "k " << k;
    }
}

TEST(FacetTable, AFewTexelsAtTheHorizonDoNotCoarsenTheTable) {
    // A map's bins span its slopes but the steepest 0.5%: three texels lying at the horizon
    // (slope 100 at kMinCos) among an egg crate's 128^2 leave its table within 2% of the clean
    // one in the diamond's middle. Spanning every slope, the bins were 2 wide in slope and the
    // middle came out at 0.06 of its density. The texels replaced are at the crate's steepest
    // points (u = 0, v = pi / 2 and the like), whose neighbours feed the diamond's edges, not
    // its middle: replaced where the crate is flat, they take the middle's own points away.
    const float gloss = glsl::gloss_fromRoughness(0.05f);
    bake::NormalGlossLevel level = eggCrateLevel(128, 0.6, gloss);
    const bake::FacetTable clean = bake::facetTable(level, true, true);
    level.normals[32 * 128 + 0] = glm::vec3(1.0f, 0.0f, 0.0f);
    level.normals[32 * 128 + 64] = glm::vec3(0.0f, -1.0f, 0.0f);
    level.normals[96 * 128 + 0] = glm::vec3(0.6f, 0.8f, 0.0f);
    const bake::FacetTable bad = bake::facetTable(level, true, true);
    for (const glm::dvec2 slope :
         {glm::dvec2(0.0, 0.0), glm::dvec2(0.0, 0.13), glm::dvec2(0.1, 0.05)}) {
        const glm::vec3 m = unitWithSlope(slope.x, slope.y);
        const double expected = double(bake::facetTableDensity(clean, m));
        EXPECT_NEAR(double(bake::facetTableDensity(bad, m)), expected, 0.02 * expected)
            << "slope (" << slope.x << ", " << slope.y << ")";
    }
}

TEST(FacetTable, BadNormalsAndGlossesGiveAFiniteTable) {
    bake::NormalGlossLevel level = flatLevel(4, 0.5f);
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const float inf = std::numeric_limits<float>::infinity();
    level.normals[0] = glm::vec3(nan, 0.0f, 1.0f);
    level.normals[1] = glm::vec3(0.0f);               // no direction
    level.normals[2] = glm::vec3(1.0f, 0.0f, 0.0f);   // on the horizon
    level.normals[3] = glm::vec3(0.0f, 0.6f, -0.8f);  // below it
    level.normals[4] = glm::vec3(inf, inf, inf);
    level.gloss[5] = nan;
    level.gloss[6] = 1.0f;  // a mirror
    level.gloss[7] = -3.0f;
    const bake::FacetTable table = bake::facetTable(level, false, true);
    for (float d : table.density) {
        ASSERT_TRUE(std::isfinite(d));
        ASSERT_GE(d, 0.0f);
    }
    // Every texel is some share of the tile, whatever its normal: no facets are lost from the
    // upper hemisphere but those of the texels at and below the horizon (their slopes floored
    // at 100, which the rim holds) and the GGX tails past the rim.
    EXPECT_GT(totalMass(table), 0.6);
    const world::ProcessedTexture texture = bake::facetTableTexture(table, "bad facets");
    EXPECT_EQ(texture.format, world::TexelFormat::kR16Float);
    EXPECT_EQ(texture.mipCount, world::fullMipCount(texture.width, texture.height));
    for (size_t i = 0; i + 1 < texture.texels.size(); i += 2) {
        const float v =
            glm::unpackHalf1x16(uint16_t(texture.texels[i] | (texture.texels[i + 1] << 8)));
        ASSERT_TRUE(std::isfinite(v));
        ASSERT_GE(v, 0.0f);
    }
}

TEST(FacetTable, TheTexturesMipZeroIsTheTableInHalfFloats) {
    const bake::FacetTable table =
        bake::facetTable(eggCrateLevel(16, 0.4, glsl::gloss_fromRoughness(0.2f)), true, true);
    const world::ProcessedTexture texture = bake::facetTableTexture(table, "egg crate facets");
    ASSERT_EQ(texture.width, uint32_t(bake::kFacetTableSize));
    for (size_t i = 0; i < table.density.size(); ++i) {
        const float v =
            glm::unpackHalf1x16(uint16_t(texture.texels[2 * i] | (texture.texels[2 * i + 1] << 8)));
        ASSERT_NEAR(v, table.density[i], 1e-3f * table.density[i] + 1e-6f) << i;  // half: 11 bits
    }
}

}  // namespace
}  // namespace onelight::test
