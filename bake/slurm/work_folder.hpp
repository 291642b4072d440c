// The work folder of a Slurm bake, on a filesystem every node shares: the manifest (which level,
// with which settings, in how many shards), each shard's package, report and stamp, the batch
// scripts and the jobs' logs. A shard counts as baked only when its stamp verifies: the package's
// checksum, and the level and settings it was baked from, equal the manifest's.
//
//   WORK/manifest.json                 the level, its content hash, the bake's arguments, N
//   WORK/compiled.olpak                the compiled level and its textures, made once by the
//                                      submitting command; every shard bakes from it
//   WORK/compiled.json                 the compile's report (texture stage, scene, compile)
//   WORK/compiled.stamp.json           its checksum, level and settings hashes, node, seconds
//   WORK/scripts/{shard,merge,submit}.sh
//   WORK/shards/shard-I.olpak          part I of N (written to a temporary name, then renamed)
//   WORK/shards/shard-I.json           its bake report (seconds per stage)
//   WORK/shards/shard-I.stamp.json     its checksum, level and settings hashes, node, seconds
//   WORK/merge.stamp.json              the merge's node, seconds and output
//   WORK/jobs.json                     the last submission's array job, merge job and shards
//   WORK/logs/shard-I.job-J.log, merge.job-J.log
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace onelight::bake::slurm {

struct WorkFolder {
    std::string root;  // absolute
    [[nodiscard]] std::string manifest() const { return root + "/manifest.json"; }
    [[nodiscard]] std::string compiled() const { return root + "/compiled.olpak"; }
    [[nodiscard]] std::string compiledReport() const { return root + "/compiled.json"; }
    [[nodiscard]] std::string compiledStamp() const { return root + "/compiled.stamp.json"; }
    [[nodiscard]] std::string scripts() const { return root + "/scripts"; }
    [[nodiscard]] std::string logs() const { return root + "/logs"; }
    [[nodiscard]] std::string shardPackage(uint32_t shard) const;
    [[nodiscard]] std::string shardReport(uint32_t shard) const;
    [[nodiscard]] std::string shardStamp(uint32_t shard) const;
    [[nodiscard]] std::string mergeStamp() const { return root + "/merge.stamp.json"; }
    [[nodiscard]] std::string jobs() const { return root + "/jobs.json"; }
};

/// What a work folder bakes. Two runs share a work folder only when their manifests are equal.
struct Manifest {
    std::string level;                       // as the shards import it (absolute when a file)
    std::string output;                      // the merged package (its images are placed for it)
    uint64_t levelHash = 0;                  // hashFiles of the import's input files
    std::vector<std::string> bakeArguments;  // the options every shard bakes with
    uint32_t shardCount = 0;
    /// The hash of the arguments and the shard count: what a stamp records of the settings.
    [[nodiscard]] uint64_t settingsHash() const;
};

/// What a finished shard task records beside its package.
struct ShardStamp {
    uint32_t shard = 0, shardCount = 0;
    uint64_t levelHash = 0, settingsHash = 0;
    uint64_t packageChecksum = 0, packageBytes = 0;  // hashBytes of the package file
    std::string node;
    double seconds = 0.0;  // the task's wall time: import, bake and write
};

/// What the merge task records: where it ran, how long it took, what it wrote.
struct MergeStamp {
    std::string node, output;
    double seconds = 0.0;
    uint64_t packageBytes = 0;
};

/// The jobs of the last submission: a rerun waits for them instead of submitting again while
/// they are still queued or running.
struct SubmittedJobs {
    std::string arrayJob;  // empty when only the merge was submitted
    std::string mergeJob;
    std::vector<uint32_t> shards;  // the array's indices
};

/// Makes the folder and its sub-folders (scripts, shards, logs). Throws world::Error.
void makeWorkFolder(const WorkFolder& work);

void writeManifest(const WorkFolder& work, const Manifest& manifest);
/// The manifest, or nothing when the folder has none. Throws world::Error when it is unreadable
/// or malformed (naming the file).
[[nodiscard]] std::optional<Manifest> readManifest(const WorkFolder& work);
/// Whether two manifests describe the same bake (level, its content, output, arguments, shard
/// count).
[[nodiscard]] bool sameBake(const Manifest& a, const Manifest& b);
/// A one-line account of what differs between `found` and `wanted` when !sameBake ("the level's
/// content changed (hash A, now B)", "the settings changed: ...").
[[nodiscard]] std::string describeChange(const Manifest& found, const Manifest& wanted);

/// Hashes the compiled level (compiled.olpak) and writes its stamp (atomically); the stamp's
/// shard is kCompiledStamp.
void writeCompiledStamp(const WorkFolder& work, const Manifest& manifest, const std::string& node,
                        double seconds);
/// The compiled level's stamp when compiled.olpak exists and the stamp verifies against
/// `manifest` (checksum, size, level and settings).
[[nodiscard]] std::optional<ShardStamp> verifiedCompiled(const WorkFolder& work,
                                                         const Manifest& manifest);
inline constexpr uint32_t kCompiledStamp = 0xffffffffu;

/// Hashes the shard's package and writes its stamp (atomically).
void writeShardStamp(const WorkFolder& work, const Manifest& manifest, uint32_t shard,
                     const std::string& node, double seconds);
/// The shard's stamp when its package exists and the stamp verifies against `manifest`.
[[nodiscard]] std::optional<ShardStamp> verifiedShard(const WorkFolder& work,
                                                      const Manifest& manifest, uint32_t shard);

void writeSubmittedJobs(const WorkFolder& work, const SubmittedJobs& jobs);
/// The last submission, or nothing when there is none or its record is damaged.
[[nodiscard]] std::optional<SubmittedJobs> readSubmittedJobs(const WorkFolder& work);

void writeMergeStamp(const WorkFolder& work, const MergeStamp& stamp);
[[nodiscard]] std::optional<MergeStamp> readMergeStamp(const WorkFolder& work);

/// The node this runs on, as Slurm names it (SLURMD_NODENAME), else the host name.
[[nodiscard]] std::string hostName();

}  // namespace onelight::bake::slurm
