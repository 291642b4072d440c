// onelight-lab level-report: speed against error for a whole level, per camera and per
// approximation knob (docs/level-report.md). The measuring (level_report_measure.cpp) and the
// writing (level_report_write.cpp) share these plain structs.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "level_knobs.hpp"

namespace onelight::lab {

struct LevelReportOptions {
    std::string level;                 // a glTF with cameras
    std::string output;                // DIR
    std::vector<std::string> cameras;  // empty: all of the level's
    uint32_t spp = 64;                 // the reference's paths per pixel, each seed
    uint32_t width = 320, height = 180;
    double budgetMinutes = 0.0;  // 0: no limit
    bool quick = false;          // one value per knob
    uint32_t timingRuns = 3;     // rounds of frame timing over all settings; the least counts
};

constexpr uint32_t kFramesPerRun = 9;  // the runtime draws these; their median GPU time

// One setting seen from one camera.
struct ReportRow {
    KnobSetting setting;
    double frameMs = 0.0;      // median GPU ms of kFramesPerRun frames (capture JSON), the least
                               // of the timing rounds
    bool gpuTimed = true;      // false: the device gave no timestamps, frameMs is CPU ms
    double bakeSeconds = 0.0;  // the bake report's seconds_total (the baseline's for a runtime
                               // knob: same package)
    uint64_t packageBytes = 0;
    uint32_t msaaInUse = 0;
    double error = 0.0;  // mean relative 8x8-block error against the reference (seed 0)
    bool front = false;  // on this camera's Pareto front
    std::string frameExr;
    float ev100 = 0.0f;  // the exposure the runtime chose (for pictures only)
    // An error budget's bake: the error its choices are predicted to cost from this camera
    // (the bake report's lightmap_error, plus the probes' predicted error from this view when
    // it dropped them); -1 for other settings.
    double predictedError = -1.0;
    double budget = 0.0;
};

struct CameraReport {
    std::string name;
    std::string referenceExr;     // seed 0
    double referenceNoise = 0.0;  // the same error measure, seed 1 against seed 0
    std::vector<ReportRow> rows;
};

struct LevelReport {
    LevelReportOptions options;
    std::vector<CameraReport> cameras;
    size_t settingsPlanned = 0, settingsMeasured = 0;
    bool stoppedByBudget = false;
    uint32_t timingRuns = 0;        // rounds of frame timing done (fewer than asked: the budget)
    double referenceSeconds = 0.0;  // wall time of the references, all cameras and seeds
    double seconds = 0.0;           // wall time of the whole run
    std::string device;             // the runtime's Vulkan device, from its capture JSON
    std::string loadBefore, loadAfter;  // /proc/loadavg's 1-minute figure at start and end
};

// Checks the options and the level (throws std::invalid_argument or world::Error naming the
// argument), bakes, renders the references and the frames, and fills the report; rows whose
// Pareto flags are set. Intermediate files go to DIR/work.
[[nodiscard]] LevelReport measureLevel(const LevelReportOptions& options);

// Writes DIR/README.md, DIR/level_report.csv, and per camera two plots and a contact sheet,
// each to a temporary name renamed into place.
void writeLevelReport(const LevelReport& report);

// level-report: measureLevel then writeLevelReport (level_report_measure.cpp).
[[nodiscard]] int levelReport(const LevelReportOptions& options);

}  // namespace onelight::lab
