// The default bake's command line (onelight-bake LEVEL [-o LEVEL.olpak] [OPTIONS]) as data, and
// the bake it runs: shared by the bake itself, the Slurm submission (which checks the options a
// shard will be given before it submits anything) and the Slurm shard task.
#pragma once

#include <string>
#include <vector>

#include "bake/bake_level.hpp"
#include "world/import/q3/q3_import.hpp"
#include "world/source_level.hpp"

namespace onelight::bake {

struct BakeCommandLine {
    std::string input, output, reportPath;  // output: LEVEL with .olpak when -o is not given
    BakeOptions options;
    world::Quake3Options quake3;
    int threads = 0;  // 0: every core
};

/// Parses the bake's arguments. On a bad one prints "onelight-bake: WHAT" and the usage on
/// stderr and returns false (the command then exits 2).
[[nodiscard]] bool parseBakeCommandLine(const std::vector<std::string>& arguments,
                                        BakeCommandLine& line);

/// Bakes the imported `source` as `line` says, then writeBakedPackage; returns the report.
/// Throws world::Error on bad input.
BakeReport bakeAndWritePackage(const world::SourceLevel& source, const BakeCommandLine& line);

/// Writes the report (if asked) and the package of `level` (its images already placed for
/// line.output) atomically, prints the summary on stdout and the warnings on stderr.
void writeBakedPackage(const BakeCommandLine& line, const world::CompiledLevel& level,
                       const world::BakedLighting& baked, const world::ProcessedTextures& textures,
                       BakeReport& report);

}  // namespace onelight::bake
