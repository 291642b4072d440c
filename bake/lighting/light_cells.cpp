#include "bake/lighting/light_cells.hpp"

#include <algorithm>
#include <cmath>

#include "bake/parallel_for.hpp"

namespace onelight::bake {
namespace {

constexpr uint32_t kMaxCellsPerAxis = 64;
constexpr double kTargetCells = 4096.0;
constexpr double kMaxEntries = 16.0 * 1024.0 * 1024.0;
// A reachable source keeps at least this share of its cell's total weight, so that its
// probability stays a positive float (dividing by it must never overflow).
constexpr double kMinShare = 1e-5;
// The weight factor of a source that none of a cell's surface points sees (f at v = 0).
constexpr double kUnseenWeight = 0.1;

float boxDistance(const LightBound& s, const glm::vec3& lo, const glm::vec3& hi) {
    const glm::vec3 gap = glm::max(glm::vec3(0.0f), glm::max(s.lo - hi, lo - s.hi));
    return glm::length(gap);
}

/// Whether `s` can light some point of the box [lo, hi] (conservative: true when unsure).
bool reaches(const LightBound& s, const glm::vec3& lo, const glm::vec3& hi) {
    if (s.directional) return true;
    if (s.range > 0.0f && boxDistance(s, lo, hi) > s.range) return false;
    if (s.planeNormal != glm::vec3(0.0f)) {
        bool inFront = false;
        for (int corner = 0; corner < 8 && !inFront; ++corner) {
            const glm::vec3 p((corner & 1) ? hi.x : lo.x, (corner & 2) ? hi.y : lo.y,
                              (corner & 4) ? hi.z : lo.z);
            inFront = glm::dot(p - s.planePoint, s.planeNormal) > 0.0f;
        }
        if (!inFront) return false;
    }
    if (s.axis != glm::vec3(0.0f) && s.cosOuter > -1.0f) {
        // The cone reaches the box if the box's bounding sphere, seen from the light, comes
        // within the outer angle of the axis.
        const glm::vec3 centre = 0.5f * (lo + hi);
        const float radius = 0.5f * glm::length(hi - lo);
        const glm::vec3 to = centre - 0.5f * (s.lo + s.hi);
        const float distance = glm::length(to);
        if (distance <= radius) return true;
        const float toAxis = std::acos(std::clamp(glm::dot(to / distance, s.axis), -1.0f, 1.0f));
        const float spread = std::asin(std::min(1.0f, radius / distance));
        if (toAxis - spread > std::acos(std::clamp(s.cosOuter, -1.0f, 1.0f))) return false;
    }
    return true;
}

/// One cell's entries from `weights` (0: left out): probabilities and alias table.
std::vector<LightCellEntry> cellTable(const std::vector<double>& weights) {
    double total = 0.0;
    for (double w : weights) total += w;
    const double floor = total * kMinShare;
    double sum = 0.0;
    for (double w : weights) sum += w > 0.0 ? std::max(w, floor) : 0.0;
    std::vector<LightCellEntry> entries;
    std::vector<double> scaled;  // n p_k: slots above 1 give to slots below
    for (size_t s = 0; s < weights.size(); ++s) {
        if (!(weights[s] > 0.0)) continue;
        const double p = std::max(weights[s], floor) / sum;
        LightCellEntry e;
        e.source = static_cast<uint32_t>(s);
        e.probability = static_cast<float>(p);
        entries.push_back(e);
        scaled.push_back(p);
    }
    const size_t n = scaled.size();
    for (double& x : scaled) x *= double(n);
    std::vector<uint32_t> small, large;
    for (uint32_t k = 0; k < n; ++k) (scaled[k] < 1.0 ? small : large).push_back(k);
    while (!small.empty() && !large.empty()) {
        const uint32_t a = small.back(), b = large.back();
        small.pop_back();
        LightCellEntry& e = entries[a];
        e.keep = static_cast<float>(scaled[a]);
        e.alias = b;
        scaled[b] -= 1.0 - scaled[a];
        if (scaled[b] < 1.0) {
            large.pop_back();
            small.push_back(b);
        }
    }
    // Leftovers are 1 up to rounding: they keep themselves.
    for (uint32_t k : small) entries[k].keep = 1.0f;
    for (uint32_t k : large) entries[k].keep = 1.0f;
    return entries;
}

}  // namespace

uint32_t cellOf(const LightCells& cells, const glm::vec3& position) {
    const glm::vec3 c = (position - cells.origin) / cells.cellSize;
    const uint32_t outside = cells.dims.x * cells.dims.y * cells.dims.z;
    for (int a = 0; a < 3; ++a)
        if (!(c[a] >= 0.0f && c[a] < static_cast<float>(cells.dims[a]))) return outside;
    const glm::uvec3 i = glm::min(glm::uvec3(c), cells.dims - 1u);
    return (i.z * cells.dims.y + i.y) * cells.dims.x + i.x;
}

void cellBox(const LightCells& cells, uint32_t cell, glm::vec3& lo, glm::vec3& hi) {
    const uint32_t x = cell % cells.dims.x, y = (cell / cells.dims.x) % cells.dims.y,
                   z = cell / (cells.dims.x * cells.dims.y);
    lo = cells.origin + glm::vec3(x, y, z) * cells.cellSize;
    hi = lo + glm::vec3(cells.cellSize);
}

LightCells layoutLightCells(size_t sourceCount, glm::vec3 lo, glm::vec3 hi) {
    LightCells cells;
    const glm::vec3 extent = glm::max(hi - lo, glm::vec3(0.0f));
    const float largest = std::max({extent.x, extent.y, extent.z, 1e-3f});
    const double target =
        std::clamp(kMaxEntries / double(std::max<size_t>(1, sourceCount)), 1.0, kTargetCells);
    const double volume = std::max(double(extent.x) * double(extent.y) * double(extent.z), 0.0);
    // Cubic cells: about `target` over the volume (or the area, for a flat level), and no more
    // than 64 along the largest side.
    float size =
        std::max(static_cast<float>(std::cbrt(volume / target)), largest / float(kMaxCellsPerAxis));
    const auto cellCount = [&](float s) {
        double n = 1.0;
        for (int a = 0; a < 3; ++a) n *= std::max(1.0, std::ceil(double(extent[a]) / double(s)));
        return n;
    };
    while (cellCount(size) > 2.0 * target) size *= 1.25f;
    for (int a = 0; a < 3; ++a)
        cells.dims[a] =
            std::clamp(static_cast<uint32_t>(std::ceil(extent[a] / size)), 1u, kMaxCellsPerAxis);
    // Centre the grid on the box, with a margin of a thousandth of a cell each side.
    const glm::vec3 span = glm::vec3(cells.dims) * size;
    cells.origin = 0.5f * (lo + hi) - 0.5f * span * 1.001f;
    cells.cellSize = size * 1.001f;
    return cells;
}

void fillLightCells(LightCells& cells, const std::vector<LightBound>& sources,
                    const CellVisibility& visibility) {
    cells.first.clear();
    cells.entries.clear();
    if (sources.empty()) return;
    const float halfDiagonal = 0.5f * std::sqrt(3.0f) * cells.cellSize;
    const uint32_t count = cellCount(cells);
    // Each cell's table on its own (in parallel: the visibility traces rays), then joined in
    // cell order, so the result does not depend on the threads.
    std::vector<std::vector<LightCellEntry>> tables(count + 1);
    bake::parallelFor(tbb::blocked_range<uint32_t>(0, count + 1), [&](const auto& range) {
        std::vector<double> weights(sources.size());
        for (uint32_t c = range.begin(); c != range.end(); ++c) {
            glm::vec3 cLo(0.0f), cHi(0.0f);
            if (c < count) cellBox(cells, c, cLo, cHi);
            for (size_t s = 0; s < sources.size(); ++s) {
                const LightBound& b = sources[s];
                weights[s] = 0.0;
                if (!(b.power > 0.0f)) continue;
                if (c == count) {  // outside the grid: every source, by power
                    weights[s] = double(b.power);
                    continue;
                }
                if (!reaches(b, cLo, cHi)) continue;
                double w = double(b.power);
                if (!b.directional) {
                    const double d = double(boxDistance(b, cLo, cHi));
                    w /= d * d + double(halfDiagonal) * double(halfDiagonal);
                }
                const float v = visibility ? visibility(static_cast<uint32_t>(s), c) : -1.0f;
                if (v >= 0.0f)
                    w *= kUnseenWeight + (1.0 - kUnseenWeight) * double(std::min(v, 1.0f));
                weights[s] = w;
            }
            tables[c] = cellTable(weights);
        }
    });
    cells.first.push_back(0);
    for (const std::vector<LightCellEntry>& table : tables) {
        cells.entries.insert(cells.entries.end(), table.begin(), table.end());
        cells.first.push_back(static_cast<uint32_t>(cells.entries.size()));
    }
}

LightCells buildLightCells(const std::vector<LightBound>& sources, glm::vec3 lo, glm::vec3 hi) {
    LightCells cells = layoutLightCells(sources.size(), lo, hi);
    fillLightCells(cells, sources);
    return cells;
}

LightCellView lightsAt(const LightCells& cells, const glm::vec3& position) {
    if (cells.empty()) return {};
    const uint32_t c = cellOf(cells, position);
    const uint32_t begin = cells.first[c], end = cells.first[c + 1];
    return {cells.entries.data() + begin, end - begin};
}

LightPick pickLight(const LightCellView& view, float u) {
    if (view.count == 0) return {};
    const float scaled = u * static_cast<float>(view.count);
    const uint32_t k = std::min(static_cast<uint32_t>(scaled), view.count - 1);
    const LightCellEntry& slot = view.entry[k];
    const LightCellEntry& e =
        scaled - static_cast<float>(k) < slot.keep ? slot : view.entry[slot.alias];
    return {e.source, e.probability};
}

float lightProbability(const LightCells& cells, const glm::vec3& position, uint32_t source) {
    const LightCellView view = lightsAt(cells, position);
    const LightCellEntry* end = view.entry + view.count;
    const LightCellEntry* at = std::lower_bound(
        view.entry, end, source, [](const LightCellEntry& e, uint32_t s) { return e.source < s; });
    return at != end && at->source == source ? at->probability : 0.0f;
}

}  // namespace onelight::bake
