// A package finds its image files wherever the level was compiled or baked from: both
// `onelight-bake compile` and a full bake write image references relative to the package's
// folder, so a level named by a relative path from another working folder, written into a third
// folder, still loads with every image decoded (a glTF sample of the shared assets; skipped
// without them).
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <string>

#include "assets/level_assets.hpp"
#include "test_scene.hpp"

namespace {

namespace fs = std::filesystem;
using namespace onelight;

TEST(PackageImages, ImageReferencesFollowThePackageFromAnyWorkingFolder) {
    const fs::path gltf = fs::path(ONELIGHT_SHARED_ASSETS) / "TextureSettingsTest" / "glTF" /
                          "TextureSettingsTest.gltf";
    if (!fs::exists(gltf)) GTEST_SKIP() << "the shared assets are absent: " << gltf;
    const fs::path out = fs::path(test::outputDir()) / "package_images";
    fs::remove_all(out);
    fs::create_directories(out / "work");
    // From out/work, the level by a relative path, each package into out/.
    const fs::path relative = fs::relative(fs::absolute(gltf), out / "work");
    for (const std::string command : {"compile", ""}) {
        const fs::path package = out / (command.empty() ? "baked.olpak" : "compiled.olpak");
        const std::string line =
            "cd '" + (out / "work").string() + "' && '" + ONELIGHT_BAKE_PATH + "' " + command +
            " '" + relative.string() + "' -o '" + package.string() + "'" +
            (command.empty() ? " --quality draft --quiet" : "") + " > /dev/null";
        ASSERT_EQ(std::system(line.c_str()), 0) << line;
        // The texture stage read every image from the level's folder, whatever the working
        // folder: its mips are in the package, one set per material.
        const assets::LoadedLevel level = assets::loadLevel(package.string());
        ASSERT_TRUE(level.hasProcessedTextures) << command;
        ASSERT_FALSE(level.processedTextures.textures.empty());
        EXPECT_EQ(level.processedTextures.materials.size(), level.level.materials.size());
        for (const world::ProcessedTexture& texture : level.processedTextures.textures)
            EXPECT_GT(texture.width, 0u) << texture.name;
    }
}

}  // namespace
