// level-report's measurements: the level's cameras, a reference per camera (two seeds), and per
// setting a bake (when it changes the baker's arguments) and a timed frame per camera. The
// baker and the runtime run as child processes found beside onelight-lab.
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <stdexcept>

#include "bake/report/progress.hpp"
#include "block_error.hpp"
#include "gltf_patch.hpp"
#include "level_report.hpp"
#include "pareto.hpp"
#include "world/error.hpp"
#include "world/images/image_files.hpp"
#include "world/import/level_import.hpp"
#include "world/process/child_process.hpp"

namespace onelight::lab {

namespace {

constexpr double kDefaultTexelsPerMetre = 16.0;  // world/charts/chart_build.hpp's default

nlohmann::json readJson(const std::string& path) {
    std::ifstream in(path);
    if (!in) throw std::runtime_error(path + ": cannot read");
    try {
        return nlohmann::json::parse(in);
    } catch (const std::exception& e) {
        throw std::runtime_error(path + ": not JSON: " + e.what());
    }
}

double finiteNumber(const nlohmann::json& j, const char* key, const std::string& path) {
    if (!j.is_object() || !j.contains(key) || !j[key].is_number())
        throw std::runtime_error(path + ": no number '" + key + "'");
    const double v = j[key].get<double>();
    if (!std::isfinite(v)) throw std::runtime_error(path + ": '" + key + "' is not finite");
    return v;
}

const nlohmann::json& member(const nlohmann::json& j, const char* key, const std::string& path) {
    if (!j.is_object() || !j.contains(key) || !j[key].is_object())
        throw std::runtime_error(path + ": no object '" + key + "'");
    return j[key];
}

struct Runner {
    std::string bakeExe, runtimeExe, work, log;
};

// The last `count` lines of `text`, joined by " | ", for an error message.
std::string lastLines(const std::string& text, size_t count) {
    std::vector<std::string> lines;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) lines.push_back(line);
    std::string out;
    for (size_t i = lines.size() > count ? lines.size() - count : 0; i < lines.size(); ++i)
        out += (out.empty() ? "" : " | ") + lines[i];
    return out;
}

// Runs `argv` (argv[0] a path) with its stdout and stderr appended to the log; throws when it
// does not exit with 0.
void mustRun(const Runner& r, const std::vector<std::string>& argv) {
    world::ChildOptions merged;
    merged.err = world::ChildStream::kIntoStdout;
    const world::ChildResult run = world::runChild(argv, merged);
    std::ofstream(r.log, std::ios::app | std::ios::binary) << run.out;
    if (run.exitCode != 0) {
        std::string line;
        for (const std::string& a : argv) line += (line.empty() ? "" : " ") + a;
        throw std::runtime_error(line + " ended with " + world::describeEnd(run) + ": " +
                                 lastLines(run.out, 3));
    }
}

// `name` beside onelight-lab, where the build and an install put the engine's programs.
std::string besideTheLab(const std::string& name) {
    const std::string path = world::executableBeside(name);
    if (::access(path.c_str(), X_OK) != 0)
        throw std::runtime_error(path + ": not found beside onelight-lab (build it)");
    return path;
}

std::string sizeText(const LevelReportOptions& o) {
    return std::to_string(o.width) + "x" + std::to_string(o.height);
}

// The cameras to measure: all of the level's, or those named (each must exist).
std::vector<std::string> chosenCameras(const LevelReportOptions& o,
                                       const world::SourceLevel& level) {
    std::vector<std::string> all;
    for (const world::Camera& c : level.cameras) all.push_back(c.name);
    if (all.empty())
        throw world::Error(o.level + ": the level has no cameras; level-report measures from them");
    if (o.cameras.empty()) return all;
    std::string names;
    for (const std::string& n : all) names += (names.empty() ? "" : ", ") + n;
    for (const std::string& want : o.cameras)
        if (std::find(all.begin(), all.end(), want) == all.end())
            throw std::invalid_argument("--cameras: no camera '" + want + "' in " + o.level +
                                        "; expected all or some of: " + names);
    return o.cameras;
}

// The index of camera `name` among the level's cameras.
size_t cameraIndex(const world::SourceLevel& level, const std::string& name) {
    for (size_t i = 0; i < level.cameras.size(); ++i)
        if (level.cameras[i].name == name) return i;
    return level.cameras.size();
}

struct Bake {
    std::string package;
    double seconds = 0.0;
    uint64_t bytes = 0;
    nlohmann::json budget;  // the bake report's error_budget, when it had one
};

// The error a budget's bake predicts from camera `index` of the level's (budgetViews: the
// level's cameras in order), or -1 without a budget.
double predictedError(const nlohmann::json& budget, size_t index) {
    if (!budget.is_object()) return -1.0;
    double e = budget.value("lightmap_error", 0.0);
    const nlohmann::json& views = budget["probe_error_per_view"];
    if (budget.value("probes_dropped", false) && views.is_array() && index < views.size())
        e += views[index].get<double>();
    return e;
}

Bake bake(const Runner& r, const LevelReportOptions& o, const KnobSetting& s, size_t index) {
    Bake b;
    b.package = r.work + "/bake" + std::to_string(index) + ".olpak";
    const std::string json = r.work + "/bake" + std::to_string(index) + ".json";
    std::vector<std::string> argv = {r.bakeExe,  o.level, "-o",     b.package,
                                     "--report", json,    "--quiet"};
    for (const std::string& a : baselineBakeArgs()) argv.push_back(a);
    for (const std::string& a : s.bakeArgs) argv.push_back(a);
    mustRun(r, argv);
    const nlohmann::json j = readJson(json);
    b.seconds = finiteNumber(j, "seconds_total", json);
    b.bytes = uint64_t(finiteNumber(j, "package_bytes", json));
    if (j.contains("error_budget")) b.budget = j["error_budget"];
    return b;
}

// One timed frame: its capture's EXR, GPU ms, MSAA in use and exposure.
ReportRow frame(const Runner& r, const LevelReportOptions& o, const std::string& package,
                const std::string& camera, const std::string& base, const KnobSetting& s,
                std::string& device) {
    std::vector<std::string> argv = {r.runtimeExe, package,     "--headless",
                                     "--size",     sizeText(o), "--camera",
                                     camera,       "--frames",  std::to_string(kFramesPerRun),
                                     "--capture",  base};
    for (const std::string& a : s.frameArgs) argv.push_back(a);
    mustRun(r, argv);
    const std::string json = base + ".json";
    const nlohmann::json j = readJson(json);
    ReportRow row;
    row.setting = s;
    row.frameExr = base + ".exr";
    const nlohmann::json& timings = member(j, "timings_ms", json);
    row.gpuTimed = timings.contains("gpu_timestamps") && timings["gpu_timestamps"].is_boolean() &&
                   timings["gpu_timestamps"].get<bool>();
    row.frameMs = finiteNumber(timings, row.gpuTimed ? "gpu_median" : "cpu", json);
    row.msaaInUse = uint32_t(finiteNumber(member(j, "msaa", json), "in_use", json));
    row.ev100 = float(finiteNumber(member(j, "camera", json), "ev100", json));
    if (j.contains("device") && j["device"].is_string()) device = j["device"].get<std::string>();
    return row;
}

// Per camera, the references of seeds 0 and 1 and the noise between them.
std::vector<CameraReport> references(const Runner& r, const LevelReportOptions& o,
                                     const std::vector<std::string>& cameras,
                                     bake::Progress& progress) {
    std::vector<CameraReport> out;
    for (size_t c = 0; c < cameras.size(); ++c) {
        CameraReport cam;
        cam.name = cameras[c];
        std::string seeds[2];
        for (int seed = 0; seed < 2; ++seed) {
            seeds[seed] = r.work + "/cam" + std::to_string(c) + "_reference_seed" +
                          std::to_string(seed) + ".exr";
            mustRun(r, {r.bakeExe, "reference", o.level, "--camera", cam.name, "--spp",
                        std::to_string(o.spp), "--size", sizeText(o), "--seed",
                        std::to_string(seed), "-o", seeds[seed]});
            progress.advance(1);
        }
        cam.referenceExr = seeds[0];
        cam.referenceNoise =
            blockErrors(world::readExrFile(seeds[1]), world::readExrFile(seeds[0])).mean;
        out.push_back(cam);
    }
    return out;
}

// Each row's Pareto flag among its camera's rows.
void markFront(CameraReport& cam) {
    std::vector<Costs> costs;
    for (const ReportRow& row : cam.rows)
        costs.push_back({row.frameMs, row.bakeSeconds, row.error});
    const std::vector<bool> front = paretoFront(costs);
    for (size_t k = 0; k < cam.rows.size(); ++k) cam.rows[k].front = front[k];
}

// One more timing round: every measured setting's frame again, in the table's order (so the
// rounds interleave the settings); each row keeps its least median GPU time.
void retime(const Runner& r, const LevelReportOptions& o, const std::vector<KnobSetting>& settings,
            const std::vector<Bake>& packages, LevelReport& report, bake::Progress& progress) {
    for (size_t i = 0; i < packages.size(); ++i)
        for (size_t c = 0; c < report.cameras.size(); ++c) {
            CameraReport& cam = report.cameras[c];
            const std::string base = r.work + "/cam" + std::to_string(c) + "_timing";
            const ReportRow again =
                frame(r, o, packages[i].package, cam.name, base, settings[i], report.device);
            cam.rows[i].frameMs = std::min(cam.rows[i].frameMs, again.frameMs);
            progress.advance(1);
        }
}

// A setting that changes the bake rather than only the runtime.
bool ownBake(const KnobSetting& s) {
    return !s.bakeArgs.empty() || !s.levelKey.empty();
}

std::string glossMipsName(world::GlossMipMethod m) {
    switch (m) {
        case world::GlossMipMethod::kBlit:
            return "blit";
        case world::GlossMipMethod::kWwii:
            return "wwii";
        case world::GlossMipMethod::kClean:
            return "clean";
        case world::GlossMipMethod::kBlackOps:
            break;
    }
    return "black_ops";
}

// The 1-minute load average, as /proc/loadavg gives it ("?" where there is none).
std::string loadAverage() {
    std::ifstream in("/proc/loadavg");
    std::string first;
    return in >> first ? first : "?";
}

double minutesSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() / 60.0;
}

}  // namespace

LevelReport measureLevel(const LevelReportOptions& o) {
    const auto start = std::chrono::steady_clock::now();
    LevelReport report;
    report.options = o;
    report.loadBefore = loadAverage();
    const world::SourceLevel level = world::importLevel(o.level);
    const std::vector<std::string> cameras = chosenCameras(o, level);
    const double texelsPerMetre =
        level.texelsPerMetre > 0.0f ? double(level.texelsPerMetre) : kDefaultTexelsPerMetre;
    const std::vector<KnobSetting> settings =
        levelKnobs(texelsPerMetre, glossMipsName(level.glossMips), canPatchLevel(o.level), o.quick);
    report.settingsPlanned = settings.size();

    Runner r;
    r.bakeExe = besideTheLab("onelight-bake");
    r.runtimeExe = besideTheLab("onelight");
    r.work = o.output + "/work";
    std::filesystem::create_directories(r.work);
    r.log = r.work + "/children.log";
    std::filesystem::remove(r.log);

    size_t bakes = 0;
    for (const KnobSetting& s : settings) bakes += ownBake(s) ? 1 : 0;
    const size_t frames = settings.size() * std::max(o.timingRuns, 1u);
    bake::Progress progress("level-report", cameras.size() * (2 + frames) + bakes + 1, true);

    const auto referencesStart = std::chrono::steady_clock::now();
    report.cameras = references(r, o, cameras, progress);
    report.referenceSeconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - referencesStart).count();

    Bake baseline;
    std::vector<Bake> packages;  // each measured setting's, kept for the timing rounds
    for (size_t i = 0; i < settings.size(); ++i) {
        const KnobSetting& s = settings[i];
        // The baseline always; every other setting while the budget lasts.
        if (i > 0 && o.budgetMinutes > 0.0 && minutesSince(start) >= o.budgetMinutes) {
            report.stoppedByBudget = true;
            break;
        }
        const bool baked = i == 0 || ownBake(s);
        const Bake b = baked ? bake(r, o, s, i) : baseline;
        if (baked) progress.advance(1);
        if (i == 0) baseline = b;
        for (size_t c = 0; c < cameras.size(); ++c) {
            CameraReport& cam = report.cameras[c];
            const std::string base =
                r.work + "/cam" + std::to_string(c) + "_setting" + std::to_string(i);
            ReportRow row = frame(r, o, b.package, cam.name, base, s, report.device);
            row.bakeSeconds = b.seconds;
            row.packageBytes = b.bytes;
            row.predictedError = predictedError(b.budget, cameraIndex(level, cam.name));
            row.budget = b.budget.is_object() ? b.budget.value("budget", 0.0) : 0.0;
            row.error =
                blockErrors(world::readExrFile(row.frameExr), world::readExrFile(cam.referenceExr))
                    .mean;
            cam.rows.push_back(row);
            progress.advance(1);
        }
        packages.push_back(b);
        ++report.settingsMeasured;
    }
    report.timingRuns = 1;
    for (uint32_t round = 1; round < o.timingRuns; ++round) {
        if (o.budgetMinutes > 0.0 && minutesSince(start) >= o.budgetMinutes) break;
        retime(r, o, settings, packages, report, progress);
        ++report.timingRuns;
    }
    progress.finish();
    for (const Bake& b : packages)
        if (b.package != baseline.package) std::filesystem::remove(b.package);
    for (CameraReport& cam : report.cameras) markFront(cam);
    report.loadAfter = loadAverage();
    report.seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return report;
}

int levelReport(const LevelReportOptions& options) {
    const LevelReport report = measureLevel(options);
    writeLevelReport(report);
    std::printf("wrote %s/README.md: %zu cameras, %zu of %zu settings in %.1f s%s\n",
                options.output.c_str(), report.cameras.size(), report.settingsMeasured,
                report.settingsPlanned, report.seconds,
                report.stoppedByBudget ? " (stopped by --budget-minutes)" : "");
    return 0;
}

}  // namespace onelight::lab
