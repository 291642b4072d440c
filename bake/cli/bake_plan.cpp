#include "bake/cli/bake_plan.hpp"

#include <string>
#include <vector>

#include "world/error.hpp"
#include "world/level_names.hpp"

namespace onelight::bake {
namespace {

using world::CommandOption;
using world::shortestNumber;

// --shard i/N with 0 <= i < N <= 65536.
bool shardAccepted(const std::string& text) {
    const size_t slash = text.find('/');
    int64_t index = 0, count = 0;
    return slash != std::string::npos &&
           world::parseWholeInteger(text.substr(0, slash), 0, 65535, index) &&
           world::parseWholeInteger(text.substr(slash + 1), 1, 65536, count) && index < count;
}

// --probe-face-size: a power of two in [4, 512].
bool faceSizeAccepted(const std::string& text) {
    int64_t size = 0;
    return world::parseWholeInteger(text, 4, 512, size) && (size & (size - 1)) == 0;
}

// --error-budget: a fraction in (0, 1] or a percentage in (0%, 100%].
bool budgetAccepted(const std::string& text, double& fraction) {
    std::string number = text;
    const bool percentage = !number.empty() && number.back() == '%';
    if (percentage) number.pop_back();
    double value = 0.0;
    if (!world::parseFiniteNumber(number, 0.0, percentage ? 100.0 : 1.0, value) || !(value > 0.0))
        return false;
    fraction = percentage ? value / 100.0 : value;
    return true;
}
bool budgetAccepted(const std::string& text) {
    double fraction = 0.0;
    return budgetAccepted(text, fraction);
}

// --time: Slurm's digits, ':' and '-' ("30", "1:00:00", "1-0").
bool timeLimitAccepted(const std::string& text) {
    return !text.empty() && text.find_first_not_of("0123456789:-") == std::string::npos;
}

// The bake's options, then the Slurm bake's own (from --slurm on): one table, each marked.
std::vector<CommandOption> bakeOptions() {
    const BakeOptions d;
    const world::ChartOptions& charts = d.compile.charts;
    return {
        local(world::textOption("-o", "PATH", "the package to write",
                                "LEVEL with the extension .olpak")),
        forwarded(world::choiceOption(
            "--quality", "Q",
            {qualityName(BakeQuality::kDraft), qualityName(BakeQuality::kDefault),
             qualityName(BakeQuality::kHigh)},
            "the bake's sample counts", qualityName(d.quality))),
        local(world::integerOption("--threads", "N", 1, 1024,
                                   "worker threads (with --slurm: the compile's, run here once)",
                                   "every core")),
        local(world::textOption("--report", "PATH", "a JSON report of every stage", "none")),
        // Refused with --slurm, which gives every shard task its own.
        local(world::customOption("--shard", "i/N", &shardAccepted, "i/N with 0 <= i < N <= 65536",
                                  "bake part i of N (join them with merge)", "the whole level")),
        forwarded(world::realOption("--sky", "CD_PER_M2", 0.0, 1e9, "a uniform sky's radiance",
                                    "the level's extras.onelight.sky, or 0")),
        forwarded(world::realOption("--grid-cell", "M", 0.05, 1000.0,
                                    "the light grid's cell size in metres",
                                    shortestNumber(d.gridCellSize))),
        forwarded(world::realOption("--texels-per-metre", "N", 0.01, 1024.0, "lightmap density",
                                    "the level's, or " + shortestNumber(charts.texelsPerMetre))),
        forwarded(patchLevelOption()),
        forwarded(world::realOption(
            "--probe-spacing", "M", 0.25, 1000.0, "metres between automatic probes",
            "the level's extras.onelight.probe_spacing, or " + shortestNumber(d.probeSpacing))),
        forwarded(world::customOption(
            "--probe-face-size", "N", &faceSizeAccepted, "a power of two in [4, 512]",
            "texels per probe cube face, a power of two 4..512", "draft 32, default 64, high 128")),
        forwarded(world::customOption(
            "--error-budget", "E", &budgetAccepted,
            "a fraction in (0, 1] or a percentage in (0%, 100%]",
            "leave out what the level's views are predicted not to need for a mean 8x8-block "
            "error of at most E, a fraction in (0, 1] or a percentage (5%); not with --shard or "
            "--slurm",
            "everything baked")),
        forwarded(world::flagOption("--all-lights",
                                    "every light with its own shadow rays at every point (slow)",
                                    "lights drawn by importance")),
        forwarded(world::flagOption("--paths-only",
                                    "whole paths for the indirect light, no cached bounces (slow)",
                                    "cached bounce passes")),
        forwarded(world::flagOption(
            "--no-denoise", "the lightmaps' indirect light as estimated, unfiltered", "denoised")),
        forwarded(world::flagOption("--no-direct-edges",
                                    "the baked direct light's shadow edges from the texels' "
                                    "bilinear visibility, without their distance field",
                                    "a distance field near sharp edges")),
        forwarded(world::flagOption("--no-facet-tables",
                                    "normal maps without their facet tables: a far footprint's "
                                    "facets from its slopes' moments alone",
                                    "each specular normal map's whole-tile facet table")),
        forwarded(world::flagOption("--own-visibility",
                                    "take the map's own potentially visible set (a Quake 3 map's "
                                    "q3map2 -vis) instead of sampling one: a faster bake, a looser "
                                    "set",
                                    "sampled with rays, within the map's own set where it has "
                                    "one")),
        forwarded(
            world::flagOption("--uniform-density", "every chart at the requested density",
                              "fewer texels on charts whose light a pilot pass finds smooth")),
        local(world::flagOption("--quiet", "no progress bars", "bars on a terminal")),
    };
}

std::vector<CommandOption> slurmOptions() {
    CommandOption shards = world::integerOption(
        "--slurm", "N", 1, 10000,
        "bake on a Slurm cluster as N shards (its options: --slurm 1 --help)", "this machine");
    shards.expected = "a number of shards";
    return {
        local(shards),
        local(world::textOption("--partition", "P", "the partition of every job",
                                "the cluster's default")),
        local(world::customOption("--time", "T", &timeLimitAccepted,
                                  "a Slurm time limit such as 30, 1:00:00 or 1-0",
                                  "each job's time limit (30, 1:00:00, 1-0)", "the partition's")),
        local(world::integerOption("--cpus-per-task", "C", 1, 1024,
                                   "cores of each job (its bake's threads)",
                                   "the cluster's default")),
        local(world::textOption("--work", "DIR", "the work folder, on a filesystem the nodes share",
                                "OUT with .slurm")),
        local(world::integerOption("--retries", "K", 0, 100,
                                   "resubmit failed shards up to K times (while waiting)", "0")),
        local(
            world::flagOption("--no-wait", "print the job ids and return", "wait, with progress")),
        local(world::textOption("--emit-scripts", "DIR",
                                "only write the batch scripts (shard, merge, submit) to DIR",
                                "submit")),
    };
}

bool isSlurmOption(const std::string& name) {
    for (const CommandOption& o : slurmOptions())
        if (o.name == name) return true;
    return false;
}

world::CommandTable usageTable(std::vector<CommandOption> options) {
    world::CommandTable table = bakeCommandTable();
    table.options = std::move(options);
    return table;
}

[[noreturn]] void refuse(const std::string& what) {
    throw world::Error(what);
}

float realOf(const world::ParsedOptions& parsed, const std::string& name) {
    return static_cast<float>(parsed.real(name));
}

}  // namespace

const world::CommandTable& bakeCommandTable() {
    static const world::CommandTable table = [] {
        world::CommandTable t;
        t.program = "onelight-bake";
        t.synopsis = "onelight-bake LEVEL [-o LEVEL.olpak] [OPTIONS]";
        t.summary =
            "compiles LEVEL and bakes its lighting: progress on stderr, a summary on stdout\n  " +
            kLevelMeaning;
        t.options = bakeOptions();
        for (CommandOption& o : slurmOptions()) t.options.push_back(std::move(o));
        t.positionalName = "level";
        t.minPositionals = t.maxPositionals = 1;
        return t;
    }();
    return table;
}

std::string bakeUsage() {
    std::vector<CommandOption> options = bakeOptions();
    options.push_back(slurmOptions().front());  // --slurm N, its own options in its help
    return world::formatHelp(usageTable(options));
}

std::string slurmUsage() {
    world::CommandTable table = usageTable(slurmOptions());
    table.synopsis = "onelight-bake LEVEL -o OUT.olpak --slurm N [OPTIONS] [BAKE OPTIONS]";
    table.summary =
        "bakes LEVEL on a Slurm cluster: compiles it once here, then a job array of N shards and "
        "a merge\n  job after them, with the bake's options (above; --threads is the compile's "
        "here); rerunning the\n  same command resumes (docs/slurm.md)";
    table.options.front().meaning = "shards, one array task each";
    table.options.front().defaultText = world::kRequiredOption;
    return world::formatHelp(table);
}

BakePlan resolveBakePlan(const world::ParsedOptions& parsed) {
    BakePlan plan;
    plan.input = parsed.positionals.at(0);
    plan.output = parsed.has("-o") ? parsed.text("-o") : world::defaultPackagePath(plan.input);
    plan.reportPath = parsed.text("--report");
    if (parsed.has("--threads")) plan.threads = int(parsed.integer("--threads"));

    BakeOptions& options = plan.options;
    options.adaptiveDensity = !parsed.has("--uniform-density");
    options.ownVisibility = parsed.has("--own-visibility");
    if (parsed.has("--quality")) (void)parseQuality(parsed.text("--quality"), options.quality);
    if (parsed.has("--shard")) {
        const std::string s = parsed.text("--shard");
        const size_t slash = s.find('/');
        options.shardIndex = uint32_t(std::stoul(s.substr(0, slash)));
        options.shardCount = uint32_t(std::stoul(s.substr(slash + 1)));
    }
    if (parsed.has("--sky")) options.skyRadiance = glm::vec3(realOf(parsed, "--sky"));
    if (parsed.has("--grid-cell")) options.gridCellSize = realOf(parsed, "--grid-cell");
    if (parsed.has("--texels-per-metre")) {
        options.compile.charts.texelsPerMetre = parsed.real("--texels-per-metre");
        options.compile.charts.densityFromCommandLine = true;
    }
    if (parsed.has("--patch-level"))
        plan.quake3.patchLevel = uint32_t(parsed.integer("--patch-level"));
    if (parsed.has("--probe-spacing")) {
        options.probeSpacing = realOf(parsed, "--probe-spacing");
        options.probeSpacingOverridesLevel = true;
    }
    if (parsed.has("--probe-face-size"))
        options.probeFaceSize = uint32_t(parsed.integer("--probe-face-size"));
    if (parsed.has("--error-budget")) {
        double fraction = 0.0;
        (void)budgetAccepted(parsed.text("--error-budget"), fraction);
        options.errorBudget = static_cast<float>(fraction);
    }
    options.showProgress = !parsed.has("--quiet");
    options.allLights = parsed.has("--all-lights");
    options.pathsOnly = parsed.has("--paths-only");
    options.noDenoise = parsed.has("--no-denoise");
    options.noDirectEdges = parsed.has("--no-direct-edges");
    options.noFacetTables = parsed.has("--no-facet-tables");
    plan.lightmap = lightmapSettings(options);
    plan.grid = gridSettings(options);
    plan.probes = probeSettings(options);

    if (options.errorBudget > 0.0f && options.shardCount > 1)
        refuse(
            "--error-budget with --shard: a budget's choices need the whole level; bake it "
            "whole");
    if (!parsed.has("--slurm")) {
        for (const auto& [name, value] : parsed.given)
            if (isSlurmOption(name))
                refuse(name + " is an option of the Slurm bake; expected --slurm N with it");
        return plan;
    }
    if (parsed.has("--shard"))
        refuse("--shard with --slurm; expected one or the other (--slurm N bakes every shard)");
    if (options.errorBudget > 0.0f)
        refuse(
            "--error-budget with --slurm: a budget's choices need the whole level, which no "
            "shard has; bake it whole, without --slurm");
    if (parsed.has("--retries") && (parsed.has("--no-wait") || parsed.has("--emit-scripts")))
        refuse(std::string("--retries with ") +
               (parsed.has("--no-wait") ? "--no-wait" : "--emit-scripts") +
               ": only a command that waits for the shards resubmits them; expected one or the "
               "other");
    SlurmPlan slurm;
    slurm.shards = uint32_t(parsed.integer("--slurm"));
    slurm.job.partition = parsed.text("--partition");
    slurm.job.timeLimit = parsed.text("--time");
    if (parsed.has("--cpus-per-task"))
        slurm.job.cpusPerTask = uint32_t(parsed.integer("--cpus-per-task"));
    slurm.work = parsed.text("--work");
    slurm.emitScripts = parsed.text("--emit-scripts");
    if (parsed.has("--retries")) slurm.retries = uint32_t(parsed.integer("--retries"));
    slurm.wait = !parsed.has("--no-wait");
    slurm.shardArguments = world::forwardedArguments(bakeCommandTable(), parsed);
    plan.slurm = std::move(slurm);
    return plan;
}

BakePlan bakePlanOf(const std::vector<std::string>& arguments) {
    return resolveBakePlan(world::parseOptions(bakeCommandTable(), arguments));
}

std::vector<std::string> shardTaskArguments(const slurm::WorkFolder& work,
                                            const slurm::Manifest& manifest, uint32_t shard) {
    std::vector<std::string> arguments = {
        manifest.level,
        "-o",
        work.shardPackage(shard),
        "--shard",
        std::to_string(shard) + "/" + std::to_string(manifest.shardCount),
        "--report",
        work.shardReport(shard),
        "--quiet"};
    arguments.insert(arguments.end(), manifest.bakeArguments.begin(), manifest.bakeArguments.end());
    return arguments;
}

}  // namespace onelight::bake
