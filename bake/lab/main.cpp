// onelight-lab: speed against error for every approximation the engine makes.
//   onelight-lab brdf-albedo --models LIST --mu LIST --gloss LIST   CSV of albedo scale and bias
//   onelight-lab brdf-report -o DIR                                 tables, CSVs and plots
//   onelight-lab env-fit [-o FILE]                                  fits shaders/env_brdf_fit.glsl
//   onelight-lab env-table [-o FILE]                          integrates shaders/env_brdf_table.inc
//   onelight-lab level-report LEVEL [--cameras all|NAME,...] [--spp N] [--size WxH]
//                             [--budget-minutes M] [--timing-runs N] [--quick] -o DIR
//                                             speed against error per camera and knob
//   onelight-lab frame-error FRAME.exr REFERENCE.exr
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
#include <vector>

#include "albedo.hpp"
#include "block_error.hpp"
#include "cli.hpp"
#include "commands.hpp"
#include "level_report.hpp"
#include "world/images/image_files.hpp"

namespace onelight::lab {
namespace {

constexpr const char* kUsage =
    "usage: onelight-lab brdf-albedo --models LIST --mu LIST --gloss LIST\n"
    "       onelight-lab brdf-report -o DIR [--quick]\n"
    "       onelight-lab env-fit [-o FILE]\n"
    "       onelight-lab env-table [-o FILE]\n"
    "       onelight-lab level-report LEVEL [--cameras all|NAME,...] [--spp N] [--size WxH] "
    "[--budget-minutes M] [--timing-runs N] [--quick] -o DIR\n"
    "       onelight-lab frame-error FRAME.exr REFERENCE.exr\n"
    "       onelight-lab sheet -o OUT.png --ev100 E[,E per row...] --images A.exr,B.exr[,...] "
    "[--rect x,y,w,h] [--columns N]\n"
    "models: bp_none, bp_kelemen, bp_schlick, beck_smith, ggx_smith; mu in (0,1]; gloss in "
    "[0,1]\n";

// --name VALUE pairs after the subcommand; flags listed in `flags` take no value.
struct Options {
    std::vector<std::pair<std::string, std::string>> values;
    std::string get(std::string_view name, std::string fallback = {}) const {
        for (auto& [k, v] : values)
            if (k == name) return v;
        return fallback;
    }
    bool has(std::string_view name) const {
        for (auto& [k, v] : values)
            if (k == name) return true;
        return false;
    }
};

// `first`: the index of the first option (after the subcommand and its positional arguments).
Options parseOptions(int argc, char** argv, std::vector<std::string_view> known,
                     std::vector<std::string_view> flags, int first = 2) {
    Options o;
    for (int i = first; i < argc; ++i) {
        std::string_view a = argv[i];
        bool isFlag = std::find(flags.begin(), flags.end(), a) != flags.end();
        if (!isFlag && std::find(known.begin(), known.end(), a) == known.end())
            throw std::invalid_argument(std::string(argv[1]) + ": unknown option '" +
                                        std::string(a) + "'");
        if (isFlag) {
            o.values.emplace_back(a, "");
        } else {
            if (i + 1 >= argc)
                throw std::invalid_argument(std::string(a) + ": expected a value after it");
            o.values.emplace_back(a, argv[++i]);
        }
    }
    return o;
}

std::string required(const Options& o, std::string_view name) {
    if (!o.has(name)) throw std::invalid_argument("missing option " + std::string(name));
    return o.get(name);
}

int brdfAlbedo(int argc, char** argv) {
    Options o = parseOptions(argc, argv, {"--models", "--mu", "--gloss"}, {});
    std::vector<const SpecularModel*> models;
    for (const std::string& name : parseWordList(required(o, "--models")))
        models.push_back(&findModel(name));
    std::vector<double> mus = parseNumberList("--mu", required(o, "--mu"), 0.0, 1.0, true);
    std::vector<double> glosses =
        parseNumberList("--gloss", required(o, "--gloss"), 0.0, 1.0, false);
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
    Options o = parseOptions(argc, argv, {"-o"}, {"--quick"});
    return brdfReport(required(o, "-o"), o.has("--quick"));
}

int envFitCommand(int argc, char** argv) {
    Options o = parseOptions(argc, argv, {"-o"}, {});
    return envFit(o.get("-o"));
}

int envTableCommand(int argc, char** argv) {
    Options o = parseOptions(argc, argv, {"-o"}, {});
    return envTable(o.get("-o"));
}

// One whole number in [lo, hi].
uint32_t wholeNumber(const std::string& option, const std::string& text, double lo, double hi) {
    const std::string expected = option + ": '" + text + "' is not a whole number in [" +
                                 std::to_string(uint32_t(lo)) + ", " +
                                 std::to_string(uint32_t(hi)) + "]";
    std::vector<double> v;
    try {
        v = parseNumberList(option, text, lo, hi, false);
    } catch (const std::invalid_argument&) {
        throw std::invalid_argument(expected);
    }
    if (v.size() != 1 || v[0] != double(uint32_t(v[0]))) throw std::invalid_argument(expected);
    return uint32_t(v[0]);
}

int levelReportCommand(int argc, char** argv) {
    if (argc < 3 || argv[2][0] == '-')
        throw std::invalid_argument("LEVEL: expected a level (a .gltf or .glb) after level-report");
    Options o = parseOptions(
        argc, argv, {"-o", "--cameras", "--spp", "--size", "--budget-minutes", "--timing-runs"},
        {"--quick"}, 3);
    LevelReportOptions r;
    r.level = argv[2];
    r.output = required(o, "-o");
    if (r.output.empty()) throw std::invalid_argument("-o: expected a folder");
    const std::string cameras = o.get("--cameras", "all");
    if (cameras != "all") {
        r.cameras = parseWordList(cameras);
        for (const std::string& c : r.cameras)
            if (c.empty())
                throw std::invalid_argument("--cameras: an empty name in '" + cameras +
                                            "'; expected all or NAME,NAME...");
    }
    if (o.has("--spp")) r.spp = wholeNumber("--spp", o.get("--spp"), 1, 65536);
    if (o.has("--size")) {
        const std::string s = o.get("--size");
        const size_t x = s.find('x');
        if (x == std::string::npos)
            throw std::invalid_argument("--size: '" + s + "' is not WxH, e.g. 320x180");
        r.width = wholeNumber("--size", s.substr(0, x), 8, 8192);
        r.height = wholeNumber("--size", s.substr(x + 1), 8, 8192);
    }
    if (o.has("--budget-minutes"))
        r.budgetMinutes =
            parseNumberList("--budget-minutes", o.get("--budget-minutes"), 0.0, 1e5, true).at(0);
    if (o.has("--timing-runs"))
        r.timingRuns = wholeNumber("--timing-runs", o.get("--timing-runs"), 1, 20);
    r.quick = o.has("--quick");
    return levelReport(r);
}

int sheetCommand(int argc, char** argv) {
    Options o = parseOptions(argc, argv, {"-o", "--ev100", "--images", "--rect", "--columns"}, {});
    std::vector<float> ev;
    for (double v : parseNumberList("--ev100", required(o, "--ev100"), -20.0, 30.0, false))
        ev.push_back(float(v));
    uint32_t columns = 0;
    if (o.has("--columns")) {
        const std::vector<double> c =
            parseNumberList("--columns", o.get("--columns"), 1.0, 64.0, false);
        if (c.size() != 1 || c[0] != double(uint32_t(c[0])))
            throw std::invalid_argument("--columns: expected one whole number in [1, 64]");
        columns = uint32_t(c[0]);
    }
    std::vector<uint32_t> rect;
    if (o.has("--rect"))
        for (double v : parseNumberList("--rect", o.get("--rect"), 0.0, 1e6, false))
            rect.push_back(uint32_t(v));
    return sheet(required(o, "-o"), ev, parseWordList(required(o, "--images")), rect, columns);
}

// frame-error FRAME.exr REFERENCE.exr: the level report's error measure for two linear images
// of one size (block_error.hpp), as "error=E blocks=N worst=W" on stdout.
int frameErrorCommand(int argc, char** argv) {
    if (argc != 4) throw std::invalid_argument("expected two EXR files: FRAME.exr REFERENCE.exr");
    const BlockErrors e = blockErrors(world::readExrFile(argv[2]), world::readExrFile(argv[3]));
    double worst = 0.0;
    for (double v : e.relative) worst = std::max(worst, v);
    std::printf("error=%.6f blocks=%zu worst=%.6f\n", e.mean, e.relative.size(), worst);
    return 0;
}

}  // namespace
}  // namespace onelight::lab

int main(int argc, char** argv) {
    using namespace onelight::lab;
    if (argc < 2) {
        std::fputs(kUsage, stderr);
        return 1;
    }
    std::string_view command = argv[1];
    try {
        if (command == "brdf-albedo") return brdfAlbedo(argc, argv);
        if (command == "brdf-report") return brdfReportCommand(argc, argv);
        if (command == "env-fit") return envFitCommand(argc, argv);
        if (command == "env-table") return envTableCommand(argc, argv);
        if (command == "sheet") return sheetCommand(argc, argv);
        if (command == "frame-error") return frameErrorCommand(argc, argv);
        if (command == "level-report") return levelReportCommand(argc, argv);
        std::fprintf(stderr, "onelight-lab: unknown command '%s'\n%s", argv[1], kUsage);
        return 1;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "onelight-lab %s: %s\n", argv[1], e.what());
        return 1;
    }
}
