// When the game rebakes a glTF level (game/level_source.cpp): only when its package is missing
// or older than the level or the baker. A stand-in baker (a shell script) records its calls and
// writes the package, so the test sees each decision without a real bake.
#include <gtest/gtest.h>

#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <string>

#include "level_source.hpp"
#include "tests/support/error_message.hpp"

namespace {

namespace fs = std::filesystem;

struct Fixture {
    fs::path dir, level, package, baker, calls;
    Fixture() {
        dir = fs::temp_directory_path() / ("onelight_level_source_" + std::to_string(::getpid()));
        fs::remove_all(dir);
        fs::create_directories(dir);
        level = dir / "level.gltf";
        package = dir / "level.olpak";
        baker = dir / "fake-bake";
        calls = dir / "calls.txt";
        std::ofstream(level) << "{}";
        // Records its arguments; writes the package named after -o.
        std::ofstream(baker) << "#!/bin/sh\necho \"$*\" >> '" << calls.string()
                             << "'\nwhile [ $# -gt 1 ]; do [ \"$1\" = -o ] && echo pak > \"$2\"; "
                                "shift; done\nexit 0\n";
        fs::permissions(baker, fs::perms::owner_all);
    }
    ~Fixture() { fs::remove_all(dir); }
    std::string callLines() const {
        std::ifstream in(calls);
        std::string all, line;
        while (std::getline(in, line)) all += line + "\n";
        return all;
    }
    int callCount() const {
        std::ifstream in(calls);
        int n = 0;
        for (std::string line; std::getline(in, line);) ++n;
        return n;
    }
    void age(const fs::path& p, int seconds) const {
        fs::last_write_time(p, fs::file_time_type::clock::now() - std::chrono::seconds(seconds));
    }
};

TEST(LevelSource, RebakesOnlyWhenThePackageIsOlderThanTheLevelOrTheBaker) {
    const Fixture f;
    // Missing package: compile, then bake.
    EXPECT_EQ(onelight::game::resolveLevelPackageWith(f.level, f.baker), f.package.string());
    EXPECT_EQ(f.callCount(), 2);

    // Newer than both: used as it is.
    f.age(f.level, 100);
    f.age(f.baker, 100);
    EXPECT_EQ(onelight::game::resolveLevelPackageWith(f.level, f.baker), f.package.string());
    EXPECT_EQ(f.callCount(), 2);

    // A rebuilt baker makes it stale.
    f.age(f.package, 200);
    f.age(f.level, 300);
    EXPECT_EQ(onelight::game::resolveLevelPackageWith(f.level, f.baker), f.package.string());
    EXPECT_EQ(f.callCount(), 4);

    // So does an edited level.
    f.age(f.package, 200);
    f.age(f.baker, 300);
    f.age(f.level, 100);
    EXPECT_EQ(onelight::game::resolveLevelPackageWith(f.level, f.baker), f.package.string());
    EXPECT_EQ(f.callCount(), 6);

    // No baker and a stale package: a clear error naming the level and the baker.
    f.age(f.package, 200);
    const std::string error = onelight::test::errorMessage([&] {
        (void)onelight::game::resolveLevelPackageWith(f.level, (f.dir / "absent").string());
    });
    EXPECT_NE(error.find("level.gltf: needs compiling"), std::string::npos) << error;
}

// A Quake 3 map (a bare name): its package is NAME.olpak in the current folder, baked at draft
// quality unless --quality says otherwise, and left alone while newer than the baker.
TEST(LevelSource, AQuake3MapBakesAtDraftIntoTheCurrentFolder) {
    const Fixture f;
    const fs::path before = fs::current_path();
    fs::current_path(f.dir);
    EXPECT_EQ(onelight::game::resolveLevelPackageWith("somemap", f.baker.string()),
              "somemap.olpak");
    EXPECT_EQ(f.callLines(),
              "compile somemap -o somemap.olpak\nsomemap -o somemap.olpak --quality draft\n");
    EXPECT_EQ(onelight::game::resolveLevelPackageWith("somemap", f.baker.string()),
              "somemap.olpak");
    EXPECT_EQ(f.callCount(), 2);  // fresh: no bake
    fs::remove(f.dir / "somemap.olpak");
    EXPECT_EQ(onelight::game::resolveLevelPackageWith("pak1.pk3:maps/other.bsp", f.baker.string(),
                                                      "high"),
              "other.olpak");
    EXPECT_NE(f.callLines().find("pak1.pk3:maps/other.bsp -o other.olpak --quality high"),
              std::string::npos)
        << f.callLines();
    fs::current_path(before);
}

// A plain .bsp file is a Quake 3 map as the docs say (onelight MAP.bsp): compiled and baked at
// draft into NAME.olpak in the current folder, and baked again once the .bsp is newer.
TEST(LevelSource, APlainBspFileIsAQuake3Map) {
    const Fixture f;
    const fs::path before = fs::current_path();
    fs::current_path(f.dir);
    fs::create_directories(f.dir / "maps");
    const fs::path map = f.dir / "maps" / "plain.bsp";
    std::ofstream(map) << "IBSP";
    EXPECT_EQ(onelight::game::resolveLevelPackageWith(map.string(), f.baker.string()),
              "plain.olpak");
    EXPECT_EQ(f.callLines(), "compile " + map.string() + " -o plain.olpak\n" + map.string() +
                                 " -o plain.olpak --quality draft\n");
    f.age(f.baker, 100);
    f.age(f.dir / "plain.olpak", 50);
    f.age(map, 200);
    EXPECT_EQ(onelight::game::resolveLevelPackageWith(map.string(), f.baker.string()),
              "plain.olpak");
    EXPECT_EQ(f.callCount(), 2);  // fresh
    f.age(map, 10);               // q3map2 wrote it again
    EXPECT_EQ(onelight::game::resolveLevelPackageWith(map.string(), f.baker.string()),
              "plain.olpak");
    EXPECT_EQ(f.callCount(), 4);
    fs::current_path(before);
}

}  // namespace
