// onelight-lab: speed against error for every approximation the engine makes.
//   onelight-lab brdf-albedo --models LIST --mu LIST --gloss LIST   CSV of albedo scale and bias
//   onelight-lab brdf-report -o DIR                                 tables, CSVs and plots
//   onelight-lab env-fit [-o FILE]                                  fits shaders/env_brdf_fit.glsl
//   onelight-lab env-table [-o FILE]                          integrates shaders/env_brdf_table.inc
//   onelight-lab horizon-cut [--steps N]        the floor's cut of a normal map's specular lobes
//   onelight-lab level-report LEVEL [--cameras all|NAME,...] [--spp N] [--size WxH]
//                             [--budget-minutes M] [--timing-runs N] [--quick] -o DIR
//                                             speed against error per camera and knob
//   onelight-lab frame-error FRAME.exr REFERENCE.exr [--heat-map OUT.png]
//                                             mean relative 8x8-block error of a frame
//   onelight-lab sheet -o OUT.png --ev100 E[,E...] --images A.exr,B.exr [--rect x,y,w,h]
//                      [--columns N]
//                                                                   EXRs side by side, tonemapped
#include <algorithm>
#include <cstdio>
#include <exception>
#include <stdexcept>
#include <string>
#include <string_view>
#include <tuple>
#include <vector>

#include "albedo.hpp"
#include "block_error.hpp"
#include "cli.hpp"
#include "commands.hpp"
#include "level_report.hpp"
#include "world/command_options.hpp"
#include "world/error.hpp"
#include "world/file_read.hpp"
#include "world/images/image_files.hpp"

namespace onelight::lab {
namespace {

using world::CommandTable;
using world::ParsedOptions;

// --budget-minutes: a number of minutes in (0, 100000].
bool minutesAccepted(const std::string& text) {
    double minutes = 0.0;
    return world::parseFiniteNumber(text, 0.0, 1e5, minutes) && minutes > 0.0;
}

CommandTable commandTable(const std::string& name, const std::string& synopsis,
                          const std::string& summary, std::vector<world::CommandOption> options) {
    CommandTable t;
    t.program = "onelight-lab " + name;
    t.synopsis = "onelight-lab " + name + " " + synopsis;
    t.summary = summary;
    t.options = std::move(options);
    return t;
}

// Every command's table, by name.
const std::vector<CommandTable>& commandTables() {
    static const std::vector<CommandTable> tables = [] {
        const LevelReportOptions d;
        std::vector<CommandTable> t;
        t.push_back(commandTable(
            "brdf-albedo", "--models LIST --mu LIST --gloss LIST",
            "CSV of the specular models' albedo scale and bias",
            {world::textOption("--models", "LIST",
                               "comma-separated: bp_none, bp_kelemen, bp_schlick, beck_smith, "
                               "ggx_smith",
                               world::kRequiredOption),
             world::textOption("--mu", "LIST", "comma-separated cosines in (0, 1]",
                               world::kRequiredOption),
             world::textOption("--gloss", "LIST", "comma-separated gloss values in [0, 1]",
                               world::kRequiredOption)}));
        t.push_back(commandTable(
            "brdf-report", "-o DIR [--quick]", "tables, CSVs and plots of every approximation",
            {world::textOption("-o", "DIR", "the report's folder", world::kRequiredOption),
             world::flagOption("--quick", "coarse grids", "fine grids")}));
        t.push_back(commandTable("env-fit", "[-o FILE]", "fits shaders/env_brdf_fit.glsl",
                                 {world::textOption("-o", "FILE", "the GLSL to write", "stdout")}));
        t.push_back(
            commandTable("env-table", "[-o FILE]", "integrates shaders/env_brdf_table.inc",
                         {world::textOption("-o", "FILE", "the table to write", "stdout")}));
        t.push_back(commandTable(
            "horizon-cut", "[--steps N]",
            "a normal-mapped floor's mean specular albedo with and without the floor's plane "
            "cutting its texels' lobes (CSV)",
            {world::integerOption("--steps", "N", 16, 4096,
                                  "quadrature cells of cos theta per texel (4 N of phi)", "600")}));
        CommandTable report = commandTable(
            "level-report",
            "LEVEL [--cameras all|NAME,...] [--spp N] [--size WxH] [--budget-minutes M] "
            "[--timing-runs N] [--quick] -o DIR",
            "speed against error per camera and knob (docs/level-report.md)",
            {world::textOption("-o", "DIR", "the report's folder", world::kRequiredOption),
             world::textOption("--cameras", "all|NAME,...", "the cameras to measure", "all"),
             world::integerOption("--spp", "N", 1, 65536,
                                  "the reference's paths per pixel, per seed",
                                  std::to_string(d.spp)),
             world::sizeOption("--size", 8, 8192, "the frames' and references' size",
                               std::to_string(d.width) + "x" + std::to_string(d.height)),
             world::customOption("--budget-minutes", "M", &minutesAccepted,
                                 "minutes, a number in (0, 100000]",
                                 "stop measuring after M minutes", "no limit"),
             world::integerOption("--timing-runs", "N", 1, 20,
                                  "rounds of frame timing; the least counts",
                                  std::to_string(d.timingRuns)),
             world::flagOption("--quick", "one value per knob", "every value")});
        report.positionalName = "level (a .gltf or .glb)";
        report.minPositionals = report.maxPositionals = 1;
        t.push_back(report);
        CommandTable frameError =
            commandTable("frame-error", "FRAME.exr REFERENCE.exr [--heat-map OUT.png]",
                         "mean relative 8x8-block error of a frame against its reference",
                         {world::textOption("--heat-map", "OUT.png",
                                            "each block's error as a picture: black 0, red, "
                                            "yellow, white at 50% and above",
                                            "none")});
        frameError.positionalName = "FRAME.exr and REFERENCE.exr";
        frameError.minPositionals = frameError.maxPositionals = 2;
        t.push_back(frameError);
        t.push_back(commandTable(
            "sheet",
            "-o OUT.png --ev100 E[,E per row...] --images A.exr,B.exr[,...] [--rect x,y,w,h] "
            "[--columns N]",
            "EXRs side by side, tonemapped, with each image's mean in a rectangle",
            {world::textOption("-o", "OUT.png", "the sheet to write", world::kRequiredOption),
             world::textOption("--ev100", "E[,E...]", "one exposure, or one per row",
                               world::kRequiredOption),
             world::textOption("--images", "A.exr,B.exr", "the images, comma-separated",
                               world::kRequiredOption),
             world::textOption("--rect", "x,y,w,h", "where each image's mean is measured", "none"),
             world::integerOption("--columns", "N", 1, 64, "images to a row", "all in one")}));
        return t;
    }();
    return tables;
}

const CommandTable& tableOf(std::string_view name) {
    for (const CommandTable& t : commandTables())
        if (t.program == "onelight-lab " + std::string(name)) return t;
    throw world::Error("unknown command '" + std::string(name) + "'");
}

// Every command's synopsis, for onelight-lab without a command.
std::string usage() {
    std::string text;
    for (const CommandTable& t : commandTables())
        text += (text.empty() ? "usage: " : "       ") + t.synopsis + "\n";
    return text + "onelight-lab COMMAND --help: its options\n";
}

// The arguments after the command name, parsed by its table.
ParsedOptions parse(std::string_view name, int argc, char** argv) {
    return world::parseOptions(tableOf(name), std::vector<std::string>(argv + 2, argv + argc));
}

int brdfAlbedo(int argc, char** argv) {
    const ParsedOptions o = parse("brdf-albedo", argc, argv);
    std::vector<const SpecularModel*> models;
    for (const std::string& name : parseWordList(o.text("--models")))
        models.push_back(&findModel(name));
    std::vector<double> mus = parseNumberList("--mu", o.text("--mu"), 0.0, 1.0, true);
    std::vector<double> glosses = parseNumberList("--gloss", o.text("--gloss"), 0.0, 1.0, false);
    std::printf("model,mu,gloss,scale,bias\n");
    for (const SpecularModel* m : models)
        for (double mu : mus)
            for (double g : glosses) {
                ScaleBias sb = specularAlbedo(*m, mu, g);
                std::printf("%s,%.9g,%.9g,%.9f,%.9f\n", std::string(m->name).c_str(), mu, g,
                            sb.scale, sb.bias);
            }
    return 0;
}

int brdfReportCommand(int argc, char** argv) {
    const ParsedOptions o = parse("brdf-report", argc, argv);
    return brdfReport(o.text("-o"), o.has("--quick"));
}

int envFitCommand(int argc, char** argv) {
    return envFit(parse("env-fit", argc, argv).text("-o"));
}

int envTableCommand(int argc, char** argv) {
    return envTable(parse("env-table", argc, argv).text("-o"));
}

int horizonCutCommand(int argc, char** argv) {
    const ParsedOptions o = parse("horizon-cut", argc, argv);
    return horizonCut(o.has("--steps") ? int(o.integer("--steps")) : 300);
}

int levelReportCommand(int argc, char** argv) {
    const ParsedOptions o = parse("level-report", argc, argv);
    LevelReportOptions r;
    r.level = o.positionals.at(0);
    r.output = o.text("-o");
    if (r.output.empty()) throw world::Error("-o: expected a folder");
    const std::string cameras = o.has("--cameras") ? o.text("--cameras") : "all";
    if (cameras != "all") {
        r.cameras = parseWordList(cameras);
        for (const std::string& c : r.cameras)
            if (c.empty())
                throw world::Error("--cameras: an empty name in '" + cameras +
                                   "'; expected all or NAME,NAME...");
    }
    if (o.has("--spp")) r.spp = uint32_t(o.integer("--spp"));
    if (o.has("--size")) std::tie(r.width, r.height) = o.size("--size");
    if (o.has("--budget-minutes")) r.budgetMinutes = o.real("--budget-minutes");
    if (o.has("--timing-runs")) r.timingRuns = uint32_t(o.integer("--timing-runs"));
    r.quick = o.has("--quick");
    return levelReport(r);
}

int sheetCommand(int argc, char** argv) {
    const ParsedOptions o = parse("sheet", argc, argv);
    std::vector<float> ev;
    for (double v : parseNumberList("--ev100", o.text("--ev100"), -20.0, 30.0, false))
        ev.push_back(float(v));
    const uint32_t columns = o.has("--columns") ? uint32_t(o.integer("--columns")) : 0u;
    std::vector<uint32_t> rect;
    if (o.has("--rect"))
        for (double v : parseNumberList("--rect", o.text("--rect"), 0.0, 1e6, false))
            rect.push_back(uint32_t(v));
    return sheet(o.text("-o"), ev, parseWordList(o.text("--images")), rect, columns);
}

// frame-error FRAME.exr REFERENCE.exr [--heat-map OUT.png]: the level report's error measure for
// two linear images of one size (block_error.hpp), as "error=E blocks=N worst=W level=L
// median_level=M" on stdout (L: the frame's mean luminance over the reference's; M: the median
// block's), and each block's error as a picture.
int frameErrorCommand(int argc, char** argv) {
    const ParsedOptions o = parse("frame-error", argc, argv);
    const world::FloatImage frame = world::readExrFile(o.positionals[0]);
    const BlockErrors e = blockErrors(frame, world::readExrFile(o.positionals[1]));
    double worst = 0.0;
    for (double v : e.relative) worst = std::max(worst, v);
    if (o.has("--heat-map"))
        world::writePngFile(o.text("--heat-map"), frame.width, frame.height,
                            heatMap(e, frame.width, frame.height, kHeatFullScale));
    std::printf("error=%.6f blocks=%zu worst=%.6f level=%.6f median_level=%.6f\n", e.mean,
                e.relative.size(), worst, e.level, e.medianLevel);
    return 0;
}

}  // namespace
}  // namespace onelight::lab

int main(int argc, char** argv) {
    using namespace onelight::lab;
    if (argc < 2) {
        std::fputs(usage().c_str(), stderr);
        return 1;
    }
    const std::string_view command = argv[1];
    if (command == "-h" || command == "--help") {
        std::fputs(usage().c_str(), stdout);
        return 0;
    }
    try {
        const onelight::world::CommandTable& table = tableOf(command);
        for (int i = 2; i < argc; ++i)
            if (std::string_view(argv[i]) == "-h" || std::string_view(argv[i]) == "--help") {
                std::fputs(onelight::world::formatHelp(table).c_str(), stdout);
                return 0;
            }
        if (command == "brdf-albedo") return brdfAlbedo(argc, argv);
        if (command == "brdf-report") return brdfReportCommand(argc, argv);
        if (command == "env-fit") return envFitCommand(argc, argv);
        if (command == "env-table") return envTableCommand(argc, argv);
        if (command == "horizon-cut") return horizonCutCommand(argc, argv);
        if (command == "sheet") return sheetCommand(argc, argv);
        if (command == "frame-error") return frameErrorCommand(argc, argv);
        if (command == "level-report") return levelReportCommand(argc, argv);
        throw onelight::world::Error("unknown command '" + std::string(command) + "'");
    } catch (const std::exception& e) {
        std::fprintf(stderr, "onelight-lab %s: %s\n", argv[1],
                     onelight::world::oneLineMessage(e.what()).c_str());
        return 1;
    }
}
