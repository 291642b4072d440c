// onelight-bake reference LEVEL --camera NAME --spp N -o out.exr [OPTIONS]
// (referenceUsage lists them with their defaults).
// The path-traced ground truth of a camera's view: linear radiance in cd/m^2, every light at
// full strength, no exposure, no tonemap.
#include <cmath>
#include <cstdio>
#include <exception>
#include <memory>
#include <optional>
#include <string>

#include <tbb/global_control.h>

#include "bake/cli/cli_common.hpp"
#include "bake/cli/subcommands.hpp"
#include "bake/reference/path_tracer.hpp"
#include "world/compile/static_split.hpp"
#include "world/error.hpp"
#include "world/file_read.hpp"
#include "world/images/image_files.hpp"
#include "world/import/level_import.hpp"

namespace onelight::bake {
std::string referenceUsage() {
    return formatUsage(
        "onelight-bake reference LEVEL --camera NAME --spp N -o OUT.exr [OPTIONS]",
        "path-traces the camera's view: linear radiance in cd/m^2, no exposure, no tonemap\n  " +
            kLevelMeaning,
        {{"--camera NAME", "the level's camera to render", kRequired},
         {"--spp N", "paths per pixel", kRequired},
         {"-o PATH", "the EXR to write", kRequired},
         {"--size WxH", "image size, 1..16384 each",
          "720 rows at the camera's aspect, else 1280x720"},
         {"--sky CD_PER_M2", "a uniform sky's radiance", "the level's extras.onelight.sky, or 0"},
         {"--threads N", "worker threads", "every core"},
         {"--seed N", "the paths' seed, 0..2^32-1: another seed, an independent estimate", "0"},
         patchLevelOption(),
         {"-h, --help", "this help", ""}});
}

int runReferenceCommand(const std::vector<std::string>& arguments) {
    if (printedHelp(arguments, referenceUsage())) return 0;
    std::string input, output, cameraName;
    uint32_t width = 0, height = 0, spp = 0, seed = 0;
    int threads = 0;
    float sky = -1.0f;  // < 0: the level's sky
    world::Quake3Options quake3;
    try {
        for (size_t i = 0; i < arguments.size(); ++i) {
            const std::string& a = arguments[i];
            const bool hasValue = i + 1 < arguments.size();
            if (a == "-o" && hasValue) {
                output = arguments[++i];
            } else if (a == "--camera" && hasValue) {
                cameraName = arguments[++i];
            } else if (a == "--size" && hasValue) {
                const std::string s = arguments[++i];
                const size_t x = s.find('x');
                if (x == std::string::npos) throw std::invalid_argument("--size " + s);
                width = static_cast<uint32_t>(std::stoul(s.substr(0, x)));
                height = static_cast<uint32_t>(std::stoul(s.substr(x + 1)));
                if (width == 0 || height == 0 || width > 16384 || height > 16384)
                    throw std::invalid_argument("--size " + s);
            } else if (a == "--spp" && hasValue) {
                spp = static_cast<uint32_t>(std::stoul(arguments[++i]));
            } else if (a == "--threads" && hasValue) {
                threads = std::stoi(arguments[++i]);
            } else if (a == "--seed" && hasValue) {
                double v = 0.0;
                if (!parseNumber(arguments[++i], 0, 4294967295.0, v) || v != std::floor(v))
                    throw std::invalid_argument("--seed " + arguments[i] +
                                                "; expected an integer in [0, 2^32 - 1]");
                seed = static_cast<uint32_t>(v);
            } else if (a == "--sky" && hasValue) {
                sky = std::stof(arguments[++i]);
                if (!(sky >= 0.0f) || !std::isfinite(sky)) throw std::invalid_argument("--sky");
            } else if (a == "--patch-level" && hasValue) {
                if (!parsePatchLevel(arguments[++i], quake3))
                    throw std::invalid_argument("--patch-level " + arguments[i] +
                                                "; expected an integer in [1, 64]");
            } else if (!a.empty() && a[0] != '-' && input.empty()) {
                input = a;
            } else {
                throw std::invalid_argument("unexpected argument '" + a + "'");
            }
        }
    } catch (const std::exception& e) {
        std::fprintf(stderr, "onelight-bake reference: bad argument (%s)\n%s", e.what(),
                     referenceUsage().c_str());
        return 2;
    }
    if (input.empty() || output.empty() || cameraName.empty() || spp == 0) {
        std::fprintf(stderr,
                     "onelight-bake reference: a level, --camera, --spp and -o are required\n%s",
                     referenceUsage().c_str());
        return 2;
    }
    std::unique_ptr<tbb::global_control> limit;
    if (threads > 0)
        limit = std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism,
                                                      static_cast<size_t>(threads));
    return runReportingErrors(input, [&] {
        const world::SourceLevel source = world::importLevel(input, quake3);
        world::refuseOutputOverInput(output, source.inputFiles);
        const world::Camera* camera = nullptr;
        for (const world::Camera& c : source.cameras)
            if (c.name == cameraName) camera = &c;
        if (!camera) {
            std::string names;
            for (const world::Camera& c : source.cameras) names += " " + c.name;
            throw world::Error(input + ": no camera named '" + cameraName + "' (cameras:" +
                               (names.empty() ? std::string(" none") : names) + ")");
        }
        if (width == 0) {
            height = 720;
            width = camera->aspectRatio > 0.0f
                        ? static_cast<uint32_t>(std::lround(720.0f * camera->aspectRatio))
                        : 1280;
        }
        const EmbreeDevice device;
        const world::SplitLevel split = world::splitStaticDynamic(source);
        const BakeScene scene(device, split.staticGeometry, loadSceneMaterials(source));
        const BakeLights lights =
            makeLevelLights(scene, source, LightSizes{},
                            sky >= 0.0f ? std::optional(glm::vec3(sky)) : std::nullopt);
        RayCounts rays;
        Progress progress("reference", height, true);
        const ReferenceImage image =
            renderReference(scene, lights, *camera, width, height, spp, {}, &progress, rays, seed);
        progress.finish();
        world::writeRgbExrFile(output, image.width, image.height, image.rgb);
        std::printf("reference %s: %ux%u, %u spp, %llu rays, %.2f Mrays/s\n", output.c_str(), width,
                    height, spp, static_cast<unsigned long long>(rays.total()),
                    double(rays.total()) / progress.seconds() * 1e-6);
        return 0;
    });
}

}  // namespace onelight::bake
