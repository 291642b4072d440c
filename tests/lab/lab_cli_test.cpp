// onelight-lab as a user runs it: output format, agreement with the library, bad input.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "albedo.hpp"
#include "capture/capture.hpp"
#include "run_command.hpp"

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
        {"brdf-albedo --models ggx_smith --mu 0.5", "missing option --gloss"},
        {"brdf-albedo --models ggx_smith --mu", "--mu: expected a value"},
        {"brdf-albedo --bogus 1", "unknown option '--bogus'"},
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
            onelight::capture::readPng((dir / png).string());
        EXPECT_EQ(image.width, 960u);
        EXPECT_EQ(image.height, 600u);
    }
    for (const char* csv : {"models.csv", "models_grid.csv", "env_fresnel.csv"})
        EXPECT_TRUE(std::filesystem::file_size(dir / csv) > 40) << csv;
    std::filesystem::remove_all(dir);
}
