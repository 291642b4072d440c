// A Quake 3 map's source (.map, as Radiant writes it and q3map2 reads it): its entities' keys,
// for the light entities that q3map2 strips from the .bsp it compiles. Brushes (both the old
// plane format and brushDef) and patches (patchDef2, patchDef3) are skipped.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "world/import/q3/entity_lump.hpp"

namespace onelight::world::q3 {

inline constexpr size_t kMaxMapSourceBytes = size_t(64) << 20;  // the largest shipped is 2.7 MB
inline constexpr size_t kMaxMapSourceEntities = size_t(1) << 20;
inline constexpr int kMaxMapSourceDepth = 4;  // entity, brush or patch, its body, one more

/*
   The format: "{" opens an entity; inside it "key" "value" pairs (quoted, one line each) and
   blocks in braces (brushes: "( x y z ) ( x y z ) ( x y z ) shader ..." lines or a brushDef
   block; patches: a patchDef2 / patchDef3 block), skipped by counting braces outside quotes and
   parentheses are not looked into. "//" starts a comment to the end of the line (outside
   quotes). Values are kept as text; numberKey / vectorKey read them (finite numbers only).
*/
/// Throws world::Error "where: line N: ..." on anything else: a brace never closed, text
/// outside an entity, a key without a value, nesting deeper than kMaxMapSourceDepth, more than
/// kMaxMapSourceBytes or kMaxMapSourceEntities.
[[nodiscard]] std::vector<MapEntity> parseMapSource(const std::string& text,
                                                    const std::string& where);

}  // namespace onelight::world::q3
