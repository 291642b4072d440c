// Many lights, chosen by importance where they are needed: a uniform grid of cells over the
// scene, each holding the lights (or emissive triangles) that can reach it, with the
// probability of choosing each there. A shading point finds its cell and draws one source, so
// the cost per point does not grow with the light count, and a light whose range or cone
// cannot reach a cell is never drawn (and never costs a ray) in it.
#pragma once

#include <cstdint>
#include <functional>
#include <vector>

#include <glm/glm.hpp>

namespace onelight::bake {

/// What the cells need to know of a light source to bound its light over a box.
struct LightBound {
    glm::vec3 lo{0.0f}, hi{0.0f};  // where it emits from (a point: lo == hi)
    float power = 0.0f;            // lux at 1 m (candela; emitters: area x luminance), or lux
    float range = 0.0f;            // metres beyond which it gives nothing; 0: unlimited
    bool directional = false;      // the same everywhere (a sun): weight = power
    glm::vec3 axis{0.0f};          // spot axis (the way light travels); zero: all around
    float cosOuter = -1.0f;        // spot: cosine of the outer cone
    glm::vec3 planeNormal{0.0f};   // one-sided emitter: it lights only in front of its plane
    glm::vec3 planePoint{0.0f};
};

/*
   Weight of source s in cell C (box of half-diagonal h), an estimate of its largest light there:
     w(s, C) = 0                                  if s cannot reach C (range, cone, plane)
             = power_s x f(s, C)                  for a directional source
             = power_s / (d(s, C)^2 + h^2) x f    else, d the distance between s's and C's boxes
   f(s, C) = 0.1 + 0.9 v(s, C), v the fraction of the cell's surface points that see s (in
   front of them and unoccluded, cell_visibility.hpp), 1 where no estimate is given: a sun
   that no surface of an interior cell sees is drawn there ten times less often, never never.
   The probability of drawing s at any point x of C is P(s | x) = w(s, C) / sum_t w(t, C). The
   weight only steers the choice: an estimator that divides by P(s | x) stays unbiased wherever
   every source that gives light at x has w > 0, which the reach tests guarantee (they are
   conservative). Points outside the grid use the sources' powers alone.
*/
/// One source of a cell, with its probability there and its slot of the cell's alias table
/// (Vose 1991, "A linear algorithm for generating random numbers with a given distribution":
/// slot k of n is drawn with probability 1 / n, then keeps its own source with probability
/// `keep`, else gives its `alias`' source), so a draw costs O(1) whatever the light count.
struct LightCellEntry {
    uint32_t source = 0;       // increasing within a cell
    float probability = 0.0f;  // P(s | x) for x in the cell
    float keep = 1.0f;         // the alias table's threshold of this slot
    uint32_t alias = 0;        // the cell's entry that this slot gives otherwise
};

struct LightCells {
    glm::vec3 origin{0.0f};
    float cellSize = 1.0f;
    glm::uvec3 dims{0u};
    std::vector<uint32_t> first;  // cellCount + 2 offsets into entries; the last cell: outside
    std::vector<LightCellEntry> entries;
    [[nodiscard]] bool empty() const { return first.empty(); }
};

/// The cells over the box [lo, hi] for `sourceCount` sources, without their tables: cubic, at
/// most 64 per axis and about 4096 in all, fewer when there are so many sources that the table
/// would pass ~16 M entries.
[[nodiscard]] LightCells layoutLightCells(size_t sourceCount, glm::vec3 lo, glm::vec3 hi);

[[nodiscard]] inline uint32_t cellCount(const LightCells& cells) {
    return cells.dims.x * cells.dims.y * cells.dims.z;
}
/// Cell c's box (c < cellCount), and the cell a point is in (cellCount: outside the grid).
void cellBox(const LightCells& cells, uint32_t cell, glm::vec3& lo, glm::vec3& hi);
[[nodiscard]] uint32_t cellOf(const LightCells& cells, const glm::vec3& position);

/// v(s, C) in [0, 1] for source s and cell C, or a negative number when it is not known.
using CellVisibility = std::function<float(uint32_t source, uint32_t cell)>;

/// Fills the tables of `cells` (from layoutLightCells) for `sources`, weighted by `visibility`
/// where given.
void fillLightCells(LightCells& cells, const std::vector<LightBound>& sources,
                    const CellVisibility& visibility = {});

/// layoutLightCells then fillLightCells without visibility.
[[nodiscard]] LightCells buildLightCells(const std::vector<LightBound>& sources, glm::vec3 lo,
                                         glm::vec3 hi);

/// A source drawn for a point: its index and the probability it was drawn with.
struct LightPick {
    uint32_t source = 0;
    float probability = 0.0f;  // 0: no source can light the point
};

/// P(s | x): the probability with which pickLight draws `source` at `position`.
[[nodiscard]] float lightProbability(const LightCells& cells, const glm::vec3& position,
                                     uint32_t source);

/// The cell's sources and their probabilities: the table of the cell `position` is in.
struct LightCellView {
    const LightCellEntry* entry = nullptr;
    uint32_t count = 0;
};
[[nodiscard]] LightCellView lightsAt(const LightCells& cells, const glm::vec3& position);

/// Draws a source with P(s | x) from a uniform number u in [0, 1).
[[nodiscard]] LightPick pickLight(const LightCellView& view, float u);
[[nodiscard]] inline LightPick pickLight(const LightCells& cells, const glm::vec3& position,
                                         float u) {
    return pickLight(lightsAt(cells, position), u);
}

}  // namespace onelight::bake
