// level-report's outputs: README.md with a table per camera, a CSV of every row, per camera a
// plot of error against frame ms and against bake seconds, and a contact sheet of
// reference | frame | error heat map per setting. Each written whole (world::writeFileAtomically).
#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <stdexcept>
#include <thread>
#include <utility>

#include "block_error.hpp"
#include "display_image.hpp"
#include "grids.hpp"
#include "level_report.hpp"
#include "plot.hpp"
#include "world/file_write.hpp"
#include "world/images/image_files.hpp"

namespace onelight::lab {

namespace {

std::string fixed(double v, int digits) {
    if (!std::isfinite(v)) throw std::runtime_error("level-report: a non-finite measurement");
    char text[64];
    std::snprintf(text, sizeof text, "%.*f", digits, v);
    return text;
}

// Every digit, so that a reader of the CSV ranks the rows as the report did.
std::string exact(double v) {
    if (!std::isfinite(v)) throw std::runtime_error("level-report: a non-finite measurement");
    char text[64];
    std::snprintf(text, sizeof text, "%.17g", v);
    return text;
}

// A camera's name as a file name: letters, digits, '-' and '_' kept, the rest '_'.
std::string fileStem(size_t index, const std::string& name) {
    std::string s = "cam" + std::to_string(index) + "_";
    for (char c : name) s += std::isalnum(static_cast<unsigned char>(c)) || c == '-' ? c : '_';
    return s;
}

// A knob as the plot's legend shows it: short enough for its column (about 22 characters).
std::string knobLegend(const std::string& knob) {
    const std::pair<const char*, const char*> shortNames[] = {
        {"shadow-map size", "shadow map"},
        {"shadow distance m", "shadow m"},
        {"bake quality", "quality"},
        {"texels per metre", "texels/m"},
        {"grid cell m", "grid m"},
        {"anisotropy", "aniso"},
        {"probe spacing m", "probe spacing m"},
        {"probe face size", "probe face"}};
    for (const auto& [longName, shortName] : shortNames)
        if (knob == longName) return shortName;
    return knob;
}

void writePlots(const CameraReport& cam, const std::string& dir, const std::string& stem) {
    for (const bool againstFrame : {true, false}) {
        Plot plot;
        plot.title = cam.name + ": error against " + (againstFrame ? "frame ms" : "bake seconds");
        plot.xLabel = againstFrame ? "GPU ms per frame" : "bake seconds";
        plot.yLabel = "mean relative 8x8-block error";
        // One colour and legend entry per knob; each point labelled with its value (`*`: on
        // the front), so that every row stays readable however many there are.
        std::vector<std::string> knobs;
        for (const ReportRow& row : cam.rows) {
            auto known = std::find(knobs.begin(), knobs.end(), row.setting.knob);
            const int colour = int(known - knobs.begin());
            if (known == knobs.end()) {
                knobs.push_back(row.setting.knob);
                PlotSeries legend;
                legend.label = knobLegend(row.setting.knob);
                legend.color = seriesColor(colour);
                plot.series.push_back(legend);
            }
            PlotSeries s;
            s.label = (row.setting.knob == "baseline" ? std::string("base") : row.setting.value) +
                      (row.front ? " *" : "");
            s.color = seriesColor(colour);
            s.points = {{againstFrame ? row.frameMs : row.bakeSeconds, row.error}};
            s.labelPoints = true;
            s.inLegend = false;
            plot.series.push_back(s);
        }
        const std::string path =
            dir + "/" + stem + (againstFrame ? "_error_vs_frame_ms.png" : "_error_vs_bake_s.png");
        writePlotPng(path, plot);
    }
}

void writeSheet(const CameraReport& cam, const std::string& path) {
    const world::FloatImage reference = world::readExrFile(cam.referenceExr);
    const uint32_t w = reference.width, h = reference.height;
    const uint32_t sheetWidth = 3 * w;
    std::vector<uint8_t> sheet(size_t(sheetWidth) * h * cam.rows.size() * 4, 255);
    const float ev100 = cam.rows.empty() ? 0.0f : cam.rows[0].ev100;
    const std::vector<uint8_t> shownReference = displayRgba8(reference, ev100);
    for (size_t k = 0; k < cam.rows.size(); ++k) {
        const world::FloatImage frame = world::readExrFile(cam.rows[k].frameExr);
        const uint32_t y = uint32_t(k) * h;
        placeTile(sheet, sheetWidth, shownReference, w, 0, y);
        placeTile(sheet, sheetWidth, displayRgba8(frame, ev100), w, w, y);
        placeTile(sheet, sheetWidth, heatMap(blockErrors(frame, reference), w, h, kHeatFullScale),
                  w, 2 * w, y);
    }
    world::writePngFile(path, sheetWidth, h * uint32_t(cam.rows.size()), sheet);
}

std::string csv(const LevelReport& report) {
    std::string out =
        "camera,knob,value,frame_ms,msaa_in_use,bake_s,package_bytes,error,"
        "reference_noise,pareto_front\n";
    for (const CameraReport& cam : report.cameras)
        for (const ReportRow& row : cam.rows)
            out += cam.name + "," + row.setting.knob + "," + row.setting.value + "," +
                   exact(row.frameMs) + "," + std::to_string(row.msaaInUse) + "," +
                   exact(row.bakeSeconds) + "," + std::to_string(row.packageBytes) + "," +
                   exact(row.error) + "," + exact(cam.referenceNoise) + "," +
                   (row.front ? "1" : "0") + "\n";
    return out;
}

// The error-budget rows of a camera: what the bake predicted its choices cost against the error
// measured over the baseline's, and whether the frame met the budget.
std::string budgetTable(const CameraReport& cam) {
    std::string md;
    double baseline = -1.0;
    for (const ReportRow& row : cam.rows)
        if (row.setting.knob == "baseline") baseline = row.error;
    for (const ReportRow& row : cam.rows) {
        if (row.predictedError < 0.0) continue;
        if (md.empty())
            md = "\nError budgets (`onelight-bake --error-budget E`): what the bake predicted its "
                 "choices would add, against what they added over the baseline's error, and "
                 "whether the frame met the budget.\n\n| budget | predicted | measured over "
                 "the baseline | error | met |\n|---:|---:|---:|---:|---|\n";
        md += "| " + fixed(100.0 * row.budget, 1) + "% | " + fixed(row.predictedError, 4) + " | " +
              (baseline >= 0.0 ? fixed(row.error - baseline, 4) : std::string("?")) + " | " +
              fixed(row.error, 4) + " | " + (row.error <= row.budget ? "yes" : "**no**") + " |\n";
    }
    return md;
}

std::string markdown(const LevelReport& report) {
    const LevelReportOptions& o = report.options;
    std::string md = "# Level report: " + o.level + "\n\n";
    md += "Made by `onelight-lab level-report` (docs/level-report.md) in " +
          fixed(report.seconds, 1) + " s (references " + fixed(report.referenceSeconds, 1) +
          " s), frames of " + std::to_string(o.width) + "x" + std::to_string(o.height) + " on " +
          (report.device.empty() ? std::string("the runtime's device") : report.device) + ", " +
          std::to_string(std::thread::hardware_concurrency()) + " cores, load average " +
          report.loadBefore + " at the start and " + report.loadAfter +
          " at the end. Each row's frame ms is its own run: on a busy machine runs of one "
          "setting spread up to 1.6x (docs/toolchain.md, \"Timing things\"), so read small "
          "differences in frame ms as noise.\n\n";
    if (report.stoppedByBudget)
        md += "**Stopped by --budget-minutes " + fixed(o.budgetMinutes, 2) + ":** " +
              std::to_string(report.settingsMeasured) + " of " +
              std::to_string(report.settingsPlanned) +
              " settings measured; the rest were not run.\n\n";
    md += "## How it is measured\n\n";
    md +=
        "- **Baseline**: `onelight-bake --quality draft` at the level's own lightmap density "
        "and grid, and `onelight`'s defaults (MSAA 2x requested, anisotropy 1, probes on, "
        "1024-texel shadow maps, 40 m of runtime shadows). Each other row changes one knob.\n";
    md +=
        "- **frame ms**: the median GPU time (timestamp queries, `timings_ms.gpu_median` of "
        "the capture JSON) of the " +
        std::to_string(kFramesPerRun) +
        " frames that `onelight PKG --headless --camera NAME --frames " +
        std::to_string(kFramesPerRun) + " --capture` draws, the least over " +
        std::to_string(report.timingRuns) + " run(s) of every setting in turn (" +
        std::to_string(o.timingRuns) +
        " asked; load only adds time, and the rounds interleave the settings). `(CPU)` marks a "
        "device without timestamps: the CPU time instead. The MSAA column "
        "is the sample count in use (the renderer takes the nearest "
        "the device supports to the request; lavapipe offers 1x and 4x).\n";
    md +=
        "- **bake s** and **bytes**: the bake report's `seconds_total` and `package_bytes`. "
        "A runtime knob uses the baseline's package, so it shows the baseline's.\n";
    md += "- **error**: the mean over 8x8-pixel blocks of |L - L_ref| / max(L_ref, " +
          fixed(kErrorFloor, 2) +
          " x mean L_ref), L a block's mean luminance, of the capture's EXR against `onelight-bake "
          "reference --spp " +
          std::to_string(o.spp) +
          " --seed 0`. Both are linear radiance in cd/m^2 before exposure, so the comparison "
          "does not depend on the exposure. **reference noise** is the same measure of the seed 1 "
          "reference against seed 0's: errors near it are below what the reference resolves.\n";
    md +=
        "- **Pareto front** (`yes`): no other row of the same camera is at least as good in "
        "frame ms, bake s and error and strictly better in one. Bytes are shown, not ranked.\n";
    md +=
        "- Pictures: per camera, `*_sheet.png` has a row per setting, in the table's order: "
        "reference | frame | error heat map (black 0, red, yellow, white at " +
        fixed(kHeatFullScale * 100.0, 0) +
        "% and above), at the baseline frame's exposure; `*_error_vs_frame_ms.png` and "
        "`*_error_vs_bake_s.png` plot each row (`*` marks the front).\n\n";
    for (size_t c = 0; c < report.cameras.size(); ++c) {
        const CameraReport& cam = report.cameras[c];
        const std::string stem = fileStem(c, cam.name);
        md += "## Camera " + cam.name + "\n\n";
        md +=
            "| knob | value | frame ms | MSAA | bake s | bytes | error | reference noise | "
            "Pareto front |\n";
        md += "|---|---|---:|---:|---:|---:|---:|---:|---|\n";
        for (const ReportRow& row : cam.rows)
            md += "| " + row.setting.knob + " | " + row.setting.value + " | " +
                  fixed(row.frameMs, 2) + (row.gpuTimed ? "" : " (CPU)") + " | " +
                  std::to_string(row.msaaInUse) + "x | " + fixed(row.bakeSeconds, 2) + " | " +
                  std::to_string(row.packageBytes) + " | " + fixed(row.error, 4) + " | " +
                  fixed(cam.referenceNoise, 4) + " | " + (row.front ? "yes" : "no") + " |\n";
        md += budgetTable(cam);
        md += "\n![error against frame ms](" + stem + "_error_vs_frame_ms.png)\n";
        md += "![error against bake seconds](" + stem + "_error_vs_bake_s.png)\n\n";
        md += "Contact sheet: [" + stem + "_sheet.png](" + stem + "_sheet.png)\n\n";
    }
    md += "## Knobs not measured\n\n| knob | why |\n|---|---|\n";
    for (const MissingKnob& m : missingKnobs()) md += "| " + m.knob + " | " + m.why + " |\n";
    return md;
}

}  // namespace

void writeLevelReport(const LevelReport& report) {
    const std::string& dir = report.options.output;
    std::filesystem::create_directories(dir);
    for (size_t c = 0; c < report.cameras.size(); ++c) {
        const std::string stem = fileStem(c, report.cameras[c].name);
        if (report.cameras[c].rows.empty()) continue;
        writePlots(report.cameras[c], dir, stem);
        writeSheet(report.cameras[c], dir + "/" + stem + "_sheet.png");
    }
    world::writeFileAtomically(dir + "/level_report.csv", csv(report));
    world::writeFileAtomically(dir + "/README.md", markdown(report));
}

}  // namespace onelight::lab
