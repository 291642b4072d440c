// The bake's option table and plan: every option is marked as forwarded to the Slurm shard tasks
// or as the submitting command's, a shard task's parser takes exactly what the submission
// forwards, combinations that cannot work are refused once, at the plan; and the option tables'
// whole-token checks.
#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <string>
#include <vector>

#include "bake/cli/bake_plan.hpp"
#include "world/command_options.hpp"
#include "world/error.hpp"

namespace {

using onelight::bake::bakeCommandTable;
using onelight::bake::BakePlan;
using onelight::bake::bakePlanOf;
using onelight::world::CommandOption;
using onelight::world::Forwarding;

// A valid value of each forwarded option that is not a flag: a forwarded option missing here
// fails the test, so that a new one is checked too.
const std::map<std::string, std::string> kSampleValues = {
    {"--quality", "draft"},      {"--sky", "2.5"},         {"--grid-cell", "0.5"},
    {"--texels-per-metre", "8"}, {"--patch-level", "3"},   {"--probe-spacing", "4"},
    {"--probe-face-size", "16"}, {"--error-budget", "5%"},
};

std::string refusal(const std::vector<std::string>& arguments) {
    try {
        (void)bakePlanOf(arguments);
    } catch (const onelight::world::Error& e) {
        return e.what();
    }
    return "";
}

TEST(BakePlan, EveryOptionIsForwardedToShardsOrMarkedLocal) {
    for (const CommandOption& o : bakeCommandTable().options)
        EXPECT_NE(o.forwarding, Forwarding::kUnmarked)
            << o.name << " is neither forwarded nor local";
}

TEST(BakePlan, AShardTaskAcceptsExactlyWhatTheSubmissionForwards) {
    std::vector<std::string> forwardedNames;
    std::vector<std::string> submitted = {
        "level.gltf", "-o",       "/out/level.olpak", "--slurm", "4",           "--threads",
        "3",          "--report", "r.json",           "--quiet", "--partition", "bake"};
    for (const CommandOption& o : bakeCommandTable().options) {
        if (o.forwarding != Forwarding::kToShards) continue;
        if (o.name == "--error-budget") continue;  // refused with --slurm: below
        forwardedNames.push_back(o.name);
        submitted.push_back(o.name);
        if (o.kind == onelight::world::OptionKind::kFlag) continue;
        ASSERT_TRUE(kSampleValues.count(o.name)) << o.name << ": add a sample value";
        submitted.push_back(kSampleValues.at(o.name));
    }
    const BakePlan plan = bakePlanOf(submitted);
    ASSERT_TRUE(plan.slurm);
    // Every forwarded option given is forwarded, and nothing local is.
    for (const std::string& name : forwardedNames)
        EXPECT_NE(
            std::find(plan.slurm->shardArguments.begin(), plan.slurm->shardArguments.end(), name),
            plan.slurm->shardArguments.end())
            << name;
    for (const char* local : {"-o", "--slurm", "--threads", "--report", "--quiet", "--partition",
                              "level.gltf", "/out/level.olpak"})
        EXPECT_EQ(
            std::find(plan.slurm->shardArguments.begin(), plan.slurm->shardArguments.end(), local),
            plan.slurm->shardArguments.end())
            << local;

    // The shard task's own arguments, as slurm-task builds them from the manifest.
    onelight::bake::slurm::Manifest manifest;
    manifest.level = "/levels/level.gltf";
    manifest.output = plan.output;
    manifest.bakeArguments = plan.slurm->shardArguments;
    manifest.shardCount = plan.slurm->shards;
    const onelight::bake::slurm::WorkFolder work{"/work/level.slurm"};
    const BakePlan shard = bakePlanOf(onelight::bake::shardTaskArguments(work, manifest, 2));
    EXPECT_FALSE(shard.slurm);
    EXPECT_EQ(shard.options.shardIndex, 2u);
    EXPECT_EQ(shard.options.shardCount, 4u);
    EXPECT_EQ(shard.output, work.shardPackage(2));
    EXPECT_EQ(shard.options.quality, plan.options.quality);
    EXPECT_EQ(shard.options.skyRadiance, plan.options.skyRadiance);
    EXPECT_EQ(shard.options.gridCellSize, plan.options.gridCellSize);
    EXPECT_EQ(shard.options.compile.charts.texelsPerMetre,
              plan.options.compile.charts.texelsPerMetre);
    EXPECT_EQ(shard.quake3.patchLevel, plan.quake3.patchLevel);
    EXPECT_EQ(shard.options.probeSpacing, plan.options.probeSpacing);
    EXPECT_EQ(shard.options.probeFaceSize, plan.options.probeFaceSize);
    EXPECT_EQ(shard.options.allLights, plan.options.allLights);
    EXPECT_EQ(shard.options.pathsOnly, plan.options.pathsOnly);
    EXPECT_EQ(shard.options.noDenoise, plan.options.noDenoise);
    EXPECT_EQ(shard.options.adaptiveDensity, plan.options.adaptiveDensity);
    // The shard forwards what it was given, unchanged.
    EXPECT_EQ(onelight::world::forwardedArguments(
                  bakeCommandTable(),
                  onelight::world::parseOptions(
                      bakeCommandTable(), onelight::bake::shardTaskArguments(work, manifest, 2))),
              plan.slurm->shardArguments);
}

TEST(BakePlan, CombinationsThatCannotWorkAreRefusedByName) {
    const std::vector<std::string> slurm = {"level.gltf", "-o", "out.olpak", "--slurm", "2"};
    auto with = [&](std::vector<std::string> more) {
        std::vector<std::string> a = slurm;
        a.insert(a.end(), more.begin(), more.end());
        return a;
    };
    EXPECT_NE(refusal(with({"--error-budget", "5%"})).find("--error-budget with --slurm"),
              std::string::npos);
    EXPECT_NE(refusal(with({"--shard", "0/2"})).find("--shard with --slurm"), std::string::npos);
    EXPECT_NE(refusal(with({"--retries", "1", "--no-wait"})).find("--retries with --no-wait"),
              std::string::npos);
    EXPECT_NE(refusal({"level.gltf", "--error-budget", "0.05", "--shard", "0/2"})
                  .find("--error-budget with --shard"),
              std::string::npos);
    EXPECT_NE(refusal({"level.gltf", "--partition", "bake"})
                  .find("--partition is an option of the Slurm bake"),
              std::string::npos);
    EXPECT_EQ(refusal({"level.gltf", "--error-budget", "5%"}), "");
}

TEST(BakePlan, TheQualityPresetIsExpandedWithItsOverrides) {
    const BakePlan draft = bakePlanOf({"level.gltf", "--quality", "draft"});
    const BakePlan high = bakePlanOf({"level.gltf", "--quality", "high", "--probe-face-size", "8"});
    EXPECT_EQ(draft.probes.faceSize, 32u);
    EXPECT_EQ(high.probes.faceSize, 8u);
    EXPECT_LT(draft.lightmap.indirectSamples, high.lightmap.indirectSamples);
    EXPECT_EQ(draft.output, "level.olpak");
}

TEST(CommandOptions, AValueIsTakenWholeAndInRange) {
    for (const auto& [arguments, expected] :
         std::vector<std::pair<std::vector<std::string>, std::string>>{
             {{"level.gltf", "--threads", "12abc"}, "--threads '12abc': expected an integer"},
             {{"level.gltf", "--threads", "-5"},
              "--threads '-5': expected an integer in [1, 1024]"},
             {{"level.gltf", "--threads", "1e3"}, "--threads '1e3'"},
             {{"level.gltf", "--threads", " 4"}, "--threads ' 4'"},
             {{"level.gltf", "--sky", "nan"}, "--sky 'nan': expected a number"},
             {{"level.gltf", "--sky", "inf"}, "--sky 'inf'"},
             {{"level.gltf", "--grid-cell", "1m"}, "--grid-cell '1m'"},
             {{"level.gltf", "--quality", "best"},
              "--quality 'best': expected draft, default or high"},
             {{"level.gltf", "--probe-face-size", "48"}, "a power of two in [4, 512]"},
             {{"level.gltf", "--error-budget", "0"}, "--error-budget '0'"},
             {{"level.gltf", "--error-budget", "150%"}, "--error-budget '150%'"},
             {{"level.gltf", "--shard", "2/2"}, "--shard '2/2'"},
             {{"level.gltf", "--threads"}, "--threads needs a value"},
             {{"level.gltf", "--nope"}, "unexpected argument '--nope'"},
             {{"level.gltf", "other.gltf"}, "unexpected argument 'other.gltf'"},
             {{"--quality", "draft"}, "no level given"}})
        EXPECT_NE(refusal(arguments).find(expected), std::string::npos)
            << arguments.back() << ": " << refusal(arguments);
}

TEST(CommandOptions, HelpListsEveryOptionWithItsDefaultAndRange) {
    const std::string help = onelight::bake::bakeUsage();
    for (const CommandOption& o : bakeCommandTable().options) {
        if (o.name != "--slurm" && o.forwarding == Forwarding::kLocal &&
            onelight::bake::slurmUsage().find("  " + o.name + " ") != std::string::npos)
            continue;  // a Slurm option: in the Slurm help
        EXPECT_NE(help.find("  " + o.name), std::string::npos) << o.name;
    }
    EXPECT_NE(help.find("worker threads (with --slurm: the compile's, run here once), 1..1024 "
                        "(default: every core)"),
              std::string::npos)
        << help;
}

TEST(CommandOptions, ParsedValuesReadBack) {
    onelight::world::CommandTable table;
    table.program = "test";
    table.options = {onelight::world::integerOption("--n", "N", -10, 10, "n", "0"),
                     onelight::world::realOption("--x", "X", 0.5, 2.0, "x", "1"),
                     onelight::world::sizeOption("--size", 1, 100, "size", "1x1"),
                     onelight::world::flagOption("--f", "f", "off")};
    table.maxPositionals = 1;
    const onelight::world::ParsedOptions p = onelight::world::parseOptions(
        table, {"--n", "-3", "--x", "1.5", "--size", "4x5", "--f", "thing", "--n", "7"});
    EXPECT_EQ(p.integer("--n"), 7);  // the last wins
    EXPECT_EQ(p.real("--x"), 1.5);
    EXPECT_EQ(p.size("--size"), std::make_pair(4u, 5u));
    EXPECT_TRUE(p.has("--f"));
    EXPECT_EQ(p.positionals, std::vector<std::string>{"thing"});
    EXPECT_TRUE(onelight::world::parseOptions(table, {"--n", "junk", "-h"}).help);
}

}  // namespace
