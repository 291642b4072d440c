// Writer and reader of the error-budget section (39; layout in format.hpp). The reader checks
// the size, every flag, that every error is finite and >= 0, and that the counts agree with
// each other and with the light grid, and throws world::Error naming the section and the field.
#pragma once

#include <string>

#include "world/baked_lighting.hpp"
#include "world/package/package_writer.hpp"

namespace onelight::package {

/// Section 39 for serializePackage; `choices.budget` must be > 0.
[[nodiscard]] RawSection encodeBudgetSection(const world::ErrorBudgetChoices& choices);

/// The choices in `section`; `gridCells` is the light grid section's cell count. `name`
/// prefixes errors.
[[nodiscard]] world::ErrorBudgetChoices decodeBudgetSection(const RawSection& section,
                                                            uint64_t gridCells,
                                                            const std::string& name);

}  // namespace onelight::package
