#include "world/package/budget_section.hpp"

#include <cmath>
#include <cstring>

#include "world/error.hpp"
#include "world/package/format.hpp"
#include "world/package/records.hpp"

namespace onelight::package {

RawSection encodeBudgetSection(const world::ErrorBudgetChoices& c) {
    const DiskErrorBudget d = toDisk(c);
    RawSection s;
    s.id = kSectionErrorBudget;
    s.elementSize = sizeof(DiskErrorBudget);
    s.count = 1;
    s.bytes.resize(sizeof(d));
    std::memcpy(s.bytes.data(), &d, sizeof(d));
    return s;
}

world::ErrorBudgetChoices decodeBudgetSection(const RawSection& section, uint64_t gridCells,
                                              const std::string& name) {
    const std::string at = name + ": section error_budget: ";
    if (section.elementSize != sizeof(DiskErrorBudget) || section.count != 1 ||
        section.bytes.size() != sizeof(DiskErrorBudget))
        throw world::Error(
            at + "element size " + std::to_string(section.elementSize) + ", count " +
            std::to_string(section.count) + ", " + std::to_string(section.bytes.size()) +
            " bytes; expected one record of " + std::to_string(sizeof(DiskErrorBudget)) + " bytes");
    DiskErrorBudget d;
    std::memcpy(&d, section.bytes.data(), sizeof(d));
    auto bad = [&](const std::string& field, const std::string& value, const std::string& want) {
        return world::Error(at + field + " = " + value + "; expected " + want);
    };
    if (!(d.budget > 0.0f && d.budget <= 1.0f))
        throw bad("budget", std::to_string(d.budget), "a fraction in (0, 1]");
    if (d.flags & ~world::kAllErrorBudgetFlags)
        throw bad("flags", std::to_string(d.flags), "no bits but 1 (probes) and 2 (grid)");
    const std::pair<const char*, float> errors[] = {{"probeError", d.probeError},
                                                    {"lightmapError", d.lightmapError},
                                                    {"predictedError", d.predictedError}};
    for (const auto& [field, value] : errors)
        if (!std::isfinite(value) || value < 0.0f)
            throw bad(field, std::to_string(value), "a finite error >= 0");
    if (!(d.densityTolerance > 0.0f && d.densityTolerance <= 8.0f))
        throw bad("densityTolerance", std::to_string(d.densityTolerance), "(0, 8]");
    if (d.texelsSampled > d.texelsRequested)
        throw bad("texelsSampled", std::to_string(d.texelsSampled),
                  "at most texelsRequested (" + std::to_string(d.texelsRequested) + ")");
    if (d.gridCells != gridCells)
        throw bad("gridCells", std::to_string(d.gridCells),
                  "the light grid's " + std::to_string(gridCells) + " cells");
    if (d.gridCellsFull < d.gridCells)
        throw bad("gridCellsFull", std::to_string(d.gridCellsFull),
                  "at least gridCells (" + std::to_string(d.gridCells) + ")");
    return fromDisk(d);
}

}  // namespace onelight::package
