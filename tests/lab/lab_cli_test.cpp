// onelight-lab as a user runs it: output format, agreement with the library, bad input.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "albedo.hpp"
#include "run_command.hpp"
#include "shading.hpp"
#include "world/images/image_decode.hpp"
#include "world/images/image_files.hpp"

namespace {

onelight::test::CommandResult run(const std::string& args) {
    return onelight::test::runCommand(std::string(ONELIGHT_LAB_EXE) + " " + args);
}

}  // namespace

TEST(LabCli, BrdfAlbedoPrintsCsvThatMatchesTheLibrary) {
    onelight::test::CommandResult r =
        run("brdf-albedo --models ggx_smith,bp_schlick --mu 0.25,1 --gloss 0.5");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    std::istringstream lines(r.output);
    std::string line;
    std::getline(lines, line);
    EXPECT_EQ(line, "model,mu,gloss,scale,bias");
    int rows = 0;
    while (std::getline(lines, line)) {
        char model[32];
        double mu, g, scale, bias;
        ASSERT_EQ(
            std::sscanf(line.c_str(), "%31[^,],%lf,%lf,%lf,%lf", model, &mu, &g, &scale, &bias), 5)
            << line;
        auto expected = onelight::lab::specularAlbedo(onelight::lab::findModel(model), mu, g);
        EXPECT_NEAR(scale, expected.scale, 1e-8) << line;
        EXPECT_NEAR(bias, expected.bias, 1e-8) << line;
        ++rows;
    }
    EXPECT_EQ(rows, 4);
}

TEST(LabCli, BadInputGivesOneClearLineAndExitOne) {
    struct {
        const char* args;
        const char* mustSay;
    } cases[] = {
        {"brdf-albedo --models ggx_smith --mu 0 --gloss 0.5", "--mu: '0' is not a number in (0"},
        {"brdf-albedo --models ggx_smith --mu abc --gloss 0.5", "--mu: 'abc'"},
        {"brdf-albedo --models ggx_smith --mu 0.5 --gloss 1.5", "--gloss: '1.5'"},
        {"brdf-albedo --models ggx_smith --mu 0.5,,1 --gloss 0.5", "--mu: ''"},
        {"brdf-albedo --models nope --mu 0.5 --gloss 0.5", "unknown model 'nope'"},
        {"brdf-albedo --models ggx_smith --mu 0.5", "--gloss LIST is required"},
        {"brdf-albedo --models ggx_smith --mu", "--mu needs a value: expected LIST"},
        {"brdf-albedo --bogus 1", "unexpected argument '--bogus'"},
        {"frobnicate", "unknown command 'frobnicate'"},
    };
    for (auto& c : cases) {
        onelight::test::CommandResult r = run(c.args);
        EXPECT_EQ(r.exitCode, 1) << c.args << "\n" << r.output;
        EXPECT_NE(r.output.find(c.mustSay), std::string::npos) << c.args << "\n" << r.output;
    }
}

TEST(LabCli, QuickReportWritesTablesCsvsAndPlots) {
    std::filesystem::path dir = std::filesystem::temp_directory_path() / "onelight_lab_report_test";
    std::filesystem::remove_all(dir);
    onelight::test::CommandResult r = run("brdf-report --quick -o " + dir.string());
    ASSERT_EQ(r.exitCode, 0) << r.output;
    std::ifstream readme(dir / "README.md");
    std::stringstream text;
    text << readme.rdbuf();
    for (const char* model : {"bp_none", "bp_kelemen", "bp_schlick", "beck_smith", "ggx_smith",
                              "env_blackops", "env_table8", "env_fit"})
        EXPECT_NE(text.str().find(std::string("| ") + model + " |"), std::string::npos) << model;
    for (const char* png : {"models_cost_vs_error.png", "models_cost_vs_albedo_error.png",
                            "env_cost_vs_error.png", "albedo_gloss05.png"}) {
        const onelight::world::DecodedImage image =
            onelight::world::readImageFile((dir / png).string());
        EXPECT_EQ(image.width, 960u);
        EXPECT_EQ(image.height, 600u);
    }
    for (const char* csv : {"models.csv", "models_grid.csv", "env_fresnel.csv"})
        EXPECT_TRUE(std::filesystem::file_size(dir / csv) > 40) << csv;
    std::filesystem::remove_all(dir);
}

// sheet: two EXRs side by side through exposure and the filmic curve; a pixel of radiance L at
// EV100 E reads displayValue(L x exposure) x 255 in the PNG, and the rectangle's means and
// ratio are printed. Images of different sizes are a named error.
TEST(LabCli, SheetPutsExrsSideBySideThroughTheCurve) {
    const std::filesystem::path dir = std::filesystem::temp_directory_path() / "onelight_lab_sheet";
    std::filesystem::create_directories(dir);
    const std::string a = (dir / "a.exr").string(), b = (dir / "b.exr").string();
    const std::string small = (dir / "small.exr").string(), png = (dir / "sheet.png").string();
    onelight::world::writeExrFile(a, 4, 2, std::vector<float>(4 * 2 * 4, 100.0f));
    onelight::world::writeExrFile(b, 4, 2, std::vector<float>(4 * 2 * 4, 200.0f));
    onelight::world::writeExrFile(small, 2, 2, std::vector<float>(2 * 2 * 4, 1.0f));
    onelight::test::CommandResult r =
        run("sheet -o " + png + " --ev100 7 --images " + a + "," + b + " --rect 0,0,4,2");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("(2.0000 of the first)"), std::string::npos) << r.output;
    const onelight::world::DecodedImage sheet = onelight::world::readImageFile(png);
    ASSERT_EQ(sheet.width, 8u);
    ASSERT_EQ(sheet.height, 2u);
    const float exposure = 1.0f / (1.2f * 128.0f);  // exposure_fromEV100(7)
    for (const auto& [x, radiance] : {std::pair{1u, 100.0f}, std::pair{6u, 200.0f}}) {
        const float want = onelight::glsl::displayValue(radiance * exposure) * 255.0f;
        EXPECT_NEAR(float(sheet.rgba[x * 4]), want, 0.6f) << "pixel " << x;
    }
    r = run("sheet -o " + png + " --ev100 7 --images " + a + "," + small);
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_NE(r.output.find("small.exr: 2x2; expected the first image's 4x2"), std::string::npos)
        << r.output;

    // A grid: three images two to a row, each row at its own exposure; the empty cell is white.
    r = run("sheet -o " + png + " --ev100 7,8 --columns 2 --images " + a + "," + b + "," + b);
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const onelight::world::DecodedImage grid = onelight::world::readImageFile(png);
    ASSERT_EQ(grid.width, 8u);
    ASSERT_EQ(grid.height, 4u);
    const float exposure8 = 1.0f / (1.2f * 256.0f);  // exposure_fromEV100(8)
    const float second = onelight::glsl::displayValue(200.0f * exposure8) * 255.0f;
    EXPECT_NEAR(float(grid.rgba[(2 * 8 + 1) * 4]), second, 0.6f);  // row 1, image 2
    EXPECT_EQ(grid.rgba[(2 * 8 + 5) * 4], 255);                    // row 1, no image
    r = run("sheet -o " + png + " --ev100 7,8,9 --columns 2 --images " + a + "," + b + "," + b);
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_NE(r.output.find("--ev100: 3 values; expected one, or one per row (2)"),
              std::string::npos)
        << r.output;
}
