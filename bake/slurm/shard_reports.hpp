// The summary of a Slurm bake from its shards' reports (WORK/shards/shard-I.json): the same
// lines a local bake prints, with each stage's seconds and rays summed over the shards
// (node-seconds), and a line per shard with its node and wall time.
#pragma once

#include <string>
#include <vector>

#include "bake/report/report.hpp"
#include "bake/slurm/work_folder.hpp"

namespace onelight::bake::slurm {

/// The fields of a report.json that the summary prints. Throws world::Error naming the file.
[[nodiscard]] BakeReport readReport(const std::string& path);

/// One report for the whole bake from the compile's (WORK/compiled.json: the texture stage, the
/// scene, the compile, the density pilot, the import's notes) and the shards': stages summed by
/// name (seconds, rays; items of the sharded stages), texels, probes and probe bytes summed,
/// noise weighted by texels, peak memory the largest; the rest (level, quality, whole-level
/// counts) from the first shard.
[[nodiscard]] BakeReport combineShardReports(const BakeReport& compile,
                                             const std::vector<BakeReport>& shards);

/// "  shard I    NODE  S s (lightmaps A s, grid B s, probes C s)" for each shard, the slowest
/// marked, and the spread (slowest / mean).
[[nodiscard]] std::string shardTimeLines(const std::vector<ShardStamp>& stamps,
                                         const std::vector<BakeReport>& reports);

/// The --report of a Slurm bake: the whole bake's report.json (combineShardReports), then
/// "compile" (node, seconds), "shards" (each shard's node, wall seconds, seconds per stage and
/// estimated core-seconds), "merge" (node, seconds) and "wall_seconds" from submission to the
/// package. Written atomically. Throws world::Error.
void writeSlurmReport(const std::string& path, const BakeReport& whole, const ShardStamp& compile,
                      const std::vector<ShardStamp>& stamps, const std::vector<BakeReport>& reports,
                      const MergeStamp& merge, double wallSeconds);

}  // namespace onelight::bake::slurm
