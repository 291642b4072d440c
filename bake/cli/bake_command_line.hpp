// The bake itself, as its plan says (bake_plan.hpp): shared by the local bake and the Slurm
// shard task.
#pragma once

#include "bake/bake_level.hpp"
#include "bake/cli/bake_plan.hpp"
#include "world/source_level.hpp"

namespace onelight::bake {

/// Bakes the imported `source` as `plan` says, then writeBakedPackage; returns the report.
/// Throws world::Error on bad input.
BakeReport bakeAndWritePackage(const world::SourceLevel& source, const BakePlan& plan);

/// Writes the report (if asked) and the package of `level` (its images already placed for
/// plan.output) atomically, prints the summary on stdout and the warnings on stderr.
void writeBakedPackage(const BakePlan& plan, const world::CompiledLevel& level,
                       const world::BakedLighting& baked, const world::ProcessedTextures& textures,
                       BakeReport& report);

}  // namespace onelight::bake
