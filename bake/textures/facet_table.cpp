#include "bake/textures/facet_table.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <glm/gtc/packing.hpp>

#include "bake/parallel_for.hpp"
#include "shading.hpp"

namespace onelight::bake {

namespace {

constexpr double kPi = 3.14159265358979323846;

// A texel's slope and its lobe's alpha^2, or a bin's means (weight: its share of the tile).
struct SlopeLobe {
    double qx = 0.0, qy = 0.0, alpha2 = 0.0, weight = 0.0;
};

// Texel i's unit normal ((0, 0, 1) where not finite) and its lobe's alpha^2.
glm::dvec3 texelNormal(const NormalGlossLevel& level0, size_t i) {
    const glm::dvec3 n(level0.normals[i]);
    const double length = glm::length(n);
    return std::isfinite(length) && length > 1e-12 ? n / length : glm::dvec3(0.0, 0.0, 1.0);
}
double texelAlpha2(const NormalGlossLevel& level0, size_t i) {
    const float g = i < level0.gloss.size() && std::isfinite(level0.gloss[i])
                        ? std::clamp(level0.gloss[i], 0.0f, 1.0f)
                        : 0.0f;
    const double a = double(glsl::ggxAlpha_fromGloss(g));
    return a * a;
}

// Texel x + dx of a row of `size` texels under the wrap mode (repeat, else clamped: a mirrored
// map's neighbour across its edge is the edge texel itself).
int wrapTexel(int x, int size, bool repeat) {
    if (repeat) return ((x % size) + size) % size;
    return std::clamp(x, 0, size - 1);
}

// The map as the runtime reads it at its full resolution: bilinear between texel centres, the
// interpolated normal normalised (normal_fromTangentSpace), sampled at k^2 points per texel cell.
// Point slopes of the texels alone are a few hundred spikes on a small map (32^2 texels: 1024
// slopes), which drew a far glint as streaks; the filtered map's slopes are continuous, as the
// frame's and the reference's are. k is 4 up to 512^2 texels, 2 up to 2048^2, then 1: a large
// map's texels are dense enough in slope, and the points cost time.
int subsamplesFor(int width, int height) {
    const int64_t texels = int64_t(width) * height;
    return texels <= 512 * 512 ? 4 : texels <= 2048 * 2048 ? 2 : 1;
}

// Calls visit(lobe) for every point of row y of texel cells, in order (weight: the point's
// share of the tile).
template <class Visit>
void visitRow(const NormalGlossLevel& level0, bool repeatS, bool repeatT, int k, int y,
              Visit&& visit) {
    const int w = level0.width, h = level0.height;
    const double weight = 1.0 / (double(w) * double(h) * double(k * k));
    for (int sy = 0; sy < k; ++sy)
        for (int x = 0; x < w; ++x)
            for (int sx = 0; sx < k; ++sx) {
                // The point (x + (sx + 0.5) / k, y + (sy + 0.5) / k) in texels, between the
                // centres of texels x0, x0 + 1 and y0, y0 + 1.
                const double px = x + (sx + 0.5) / k - 0.5, py = y + (sy + 0.5) / k - 0.5;
                const int x0 = int(std::floor(px)), y0 = int(std::floor(py));
                const double tx = px - x0, ty = py - y0;
                glm::dvec3 n(0.0);
                double alpha2 = 0.0;
                for (int cy = 0; cy < 2; ++cy)
                    for (int cx = 0; cx < 2; ++cx) {
                        const size_t i = size_t(wrapTexel(y0 + cy, h, repeatT)) * size_t(w) +
                                         size_t(wrapTexel(x0 + cx, w, repeatS));
                        const double share = (cx ? tx : 1.0 - tx) * (cy ? ty : 1.0 - ty);
                        n += texelNormal(level0, i) * share;
                        alpha2 += texelAlpha2(level0, i) * share;
                    }
                const double length = glm::length(n);
                n = length > 1e-12 ? n / length : glm::dvec3(0.0, 0.0, 1.0);
                const double z = std::max(n.z, kMinCos);
                visit(SlopeLobe{n.x / z, n.y / z, alpha2, weight});
            }
}

// A binned lobe's alpha, at least this many bins: the bins' lobes then sum to a smooth density
// (a lattice of GGX lobes of alpha 1.5 bins varies by 0.1%, of alpha 0.95 bins by 3.5%; the
// bins' uneven weights made that 12% on an egg crate's table).
constexpr double kBinSpread = 1.5;

// Rows of texel cells are binned in this many fixed blocks, each into bins of its own, summed in
// block order: the same sums at any thread count, and a working set of a few MiB.
constexpr int kBinBlocks = 16;

// Every point of the map as a lobe, or, when there are more than kFacetBins^2, gathered into
// kFacetBins^2 bins over the texels' slope range (each bin its points' weighted mean slope and
// alpha^2; the filtered slopes lie within the texels'), in bin order; and the bins' width (0:
// not binned).
std::vector<SlopeLobe> mapLobes(const NormalGlossLevel& level0, bool repeatS, bool repeatT,
                                double& binWidth) {
    const int w = level0.width, h = level0.height;
    const int k = subsamplesFor(w, h);
    binWidth = 0.0;
    std::vector<SlopeLobe> lobes;
    if (int64_t(w) * h * k * k <= int64_t(kFacetBins) * kFacetBins) {
        for (int y = 0; y < h; ++y)
            visitRow(level0, repeatS, repeatT, k, y,
                     [&](const SlopeLobe& l) { lobes.push_back(l); });
        return lobes;
    }
    // The bins span the texels' slopes but their steepest 0.5%: one texel at the horizon (slope
    // 100 at kMinCos) would otherwise widen every bin a hundredfold and flatten the table (an egg
    // crate's middle at 0.06 of its density, with three such texels among 128^2). Steeper points
    // fall in the edge bins, whose means keep their slopes.
    std::vector<double> steepness(level0.normals.size());
    for (size_t i = 0; i < level0.normals.size(); ++i) {
        const glm::dvec3 n = texelNormal(level0, i);
        const double z = std::max(n.z, kMinCos);
        steepness[i] = std::max(std::abs(n.x / z), std::abs(n.y / z));
    }
    const size_t kept = std::min(steepness.size() - 1, size_t(double(steepness.size()) * 0.995));
    std::nth_element(steepness.begin(), steepness.begin() + std::ptrdiff_t(kept), steepness.end());
    const double range = std::max(steepness[kept], 1e-3);
    binWidth = 2.0 * range / kFacetBins;
    const int blocks = std::min(kBinBlocks, h);
    std::vector<std::vector<SlopeLobe>> blockBins(static_cast<size_t>(blocks));
    parallelFor(0, blocks, [&](int b) {
        std::vector<SlopeLobe>& bins = blockBins[size_t(b)];
        bins.assign(size_t(kFacetBins) * kFacetBins, SlopeLobe{});
        for (int y = int(int64_t(h) * b / blocks); y < int(int64_t(h) * (b + 1) / blocks); ++y)
            visitRow(level0, repeatS, repeatT, k, y, [&](const SlopeLobe& l) {
                const int bx = std::clamp(int((l.qx + range) / binWidth), 0, kFacetBins - 1);
                const int by = std::clamp(int((l.qy + range) / binWidth), 0, kFacetBins - 1);
                SlopeLobe& bin = bins[size_t(by) * kFacetBins + size_t(bx)];
                bin.qx += l.qx * l.weight;
                bin.qy += l.qy * l.weight;
                bin.alpha2 += l.alpha2 * l.weight;
                bin.weight += l.weight;
            });
    });
    for (size_t i = 0; i < size_t(kFacetBins) * kFacetBins; ++i) {
        SlopeLobe sum;
        for (const std::vector<SlopeLobe>& bins : blockBins) {
            sum.qx += bins[i].qx;
            sum.qy += bins[i].qy;
            sum.alpha2 += bins[i].alpha2;
            sum.weight += bins[i].weight;
        }
        if (sum.weight > 0.0)
            lobes.push_back(
                {sum.qx / sum.weight, sum.qy / sum.weight, sum.alpha2 / sum.weight, sum.weight});
    }
    return lobes;
}

// The table's point (x, y) on the projected disc, pulled in to the rim.
glm::dvec2 tablePoint(int x, int y) {
    glm::dvec2 c((x + 0.5) / kFacetTableSize * 2.0 - 1.0, (y + 0.5) / kFacetTableSize * 2.0 - 1.0);
    const double r = glm::length(c);
    if (r > double(kFacetTableRim)) c *= double(kFacetTableRim) / r;
    return c;
}

}  // namespace

FacetTable facetTable(const NormalGlossLevel& level0, bool repeatS, bool repeatT) {
    double binWidth = 0.0;
    std::vector<SlopeLobe> lobes = mapLobes(level0, repeatS, repeatT, binWidth);
    const double cell = 2.0 / kFacetTableSize;  // in c, per axis
    // Each lobe widened by the table's cell where it lies (dq/dc is 1/z^3 along c's radius, 1/z
    // across: the larger) and by the bins, once, so that every lobe is one density whose
    // integral is its weight wherever the table reads it.
    for (SlopeLobe& l : lobes) {
        const double z = 1.0 / std::sqrt(1.0 + l.qx * l.qx + l.qy * l.qy);
        const double cellSlope = cell / (z * z * z);
        l.alpha2 += cellSlope * cellSlope / 3.0 + kBinSpread * kBinSpread * binWidth * binWidth;
    }
    FacetTable table;
    table.density.assign(size_t(kFacetTableSize) * kFacetTableSize, 0.0f);
    parallelFor(0, kFacetTableSize, [&](int y) {
        for (int x = 0; x < kFacetTableSize; ++x) {
            const glm::dvec2 c = tablePoint(x, y);
            const double z = std::sqrt(std::max(1.0 - glm::dot(c, c), 1e-12));
            const glm::dvec2 q = c / z;
            double p = 0.0;
            for (const SlopeLobe& l : lobes) {
                const double a2 = l.alpha2;
                const double dx = q.x - l.qx, dy = q.y - l.qy;
                const double d = a2 + dx * dx + dy * dy;
                p += l.weight * a2 / (d * d);
            }
            const double density = p / kPi / (z * z * z * z);
            table.density[size_t(y) * kFacetTableSize + size_t(x)] =
                std::isfinite(density) ? float(std::min(density, 6.0e4)) : 0.0f;
        }
    });
    return table;
}

float facetTableDensity(const FacetTable& table, glm::vec3 m) {
    const double fx = (double(m.x) * 0.5 + 0.5) * kFacetTableSize - 0.5;
    const double fy = (double(m.y) * 0.5 + 0.5) * kFacetTableSize - 0.5;
    const double clampedX = std::clamp(fx, 0.0, double(kFacetTableSize - 1));
    const double clampedY = std::clamp(fy, 0.0, double(kFacetTableSize - 1));
    const int x0 = std::min(int(clampedX), kFacetTableSize - 2);
    const int y0 = std::min(int(clampedY), kFacetTableSize - 2);
    const double tx = clampedX - x0, ty = clampedY - y0;
    auto at = [&](int x, int y) {
        return double(table.density[size_t(y) * kFacetTableSize + size_t(x)]);
    };
    const double top = at(x0, y0) * (1.0 - tx) + at(x0 + 1, y0) * tx;
    const double bottom = at(x0, y0 + 1) * (1.0 - tx) + at(x0 + 1, y0 + 1) * tx;
    return float(top * (1.0 - ty) + bottom * ty);
}

world::ProcessedTexture facetTableTexture(const FacetTable& table, std::string name) {
    world::ProcessedTexture out;
    out.name = std::move(name);
    out.format = world::TexelFormat::kR16Float;
    out.width = out.height = uint32_t(kFacetTableSize);
    out.mipCount = world::fullMipCount(out.width, out.height);
    out.sampler = {9729, 9729, 33071, 33071};  // LINEAR, CLAMP_TO_EDGE
    out.texels.resize(world::mipChainBytes(out.format, out.width, out.height, out.mipCount));
    std::vector<float> level = table.density;
    size_t offset = 0;
    for (int size = kFacetTableSize;; size /= 2) {
        for (float v : level) {
            const uint16_t half = glm::packHalf1x16(v);
            std::memcpy(out.texels.data() + offset, &half, sizeof half);
            offset += sizeof half;
        }
        if (size == 1) break;
        const int next = size / 2;
        std::vector<float> down(size_t(next) * size_t(next));
        for (int y = 0; y < next; ++y)
            for (int x = 0; x < next; ++x) {
                auto at = [&](int dx, int dy) {
                    return double(level[size_t(2 * y + dy) * size_t(size) + size_t(2 * x + dx)]);
                };
                down[size_t(y) * size_t(next) + size_t(x)] =
                    float((at(0, 0) + at(1, 0) + at(0, 1) + at(1, 1)) * 0.25);
            }
        level = std::move(down);
    }
    return out;
}

}  // namespace onelight::bake
