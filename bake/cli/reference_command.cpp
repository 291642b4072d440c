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
#include <tuple>

#include <tbb/global_control.h>

#include "bake/cli/cli_common.hpp"
#include "bake/cli/subcommands.hpp"
#include "bake/reference/frame_poses.hpp"
#include "bake/reference/path_tracer.hpp"
#include "bake/reference/seen_only.hpp"
#include "world/compile/static_split.hpp"
#include "world/error.hpp"
#include "world/file_read.hpp"
#include "world/images/image_files.hpp"
#include "world/import/level_import.hpp"

namespace onelight::bake {
namespace {

int renderFromCommandLine(const world::ParsedOptions& parsed);

}  // namespace

const world::CommandTable& referenceCommandTable() {
    static const world::CommandTable table = [] {
        world::CommandTable t;
        t.program = "onelight-bake reference";
        t.synopsis = "onelight-bake reference LEVEL --camera NAME --spp N -o OUT.exr [OPTIONS]";
        t.summary =
            "path-traces the camera's view: linear radiance in cd/m^2, no exposure, no tonemap\n "
            " " +
            kLevelMeaning;
        t.options = {
            world::textOption("--camera", "NAME", "the level's camera to render",
                              world::kRequiredOption),
            world::integerOption("--spp", "N", 1, 1 << 24, "paths per pixel",
                                 world::kRequiredOption),
            world::textOption("-o", "PATH", "the EXR to write", world::kRequiredOption),
            world::sizeOption("--size", 1, 16384, "image size",
                              "720 rows at the camera's aspect, else 1280x720"),
            world::realOption("--sky", "CD_PER_M2", 0.0, 1e9, "a uniform sky's radiance",
                              "the level's extras.onelight.sky, or 0"),
            world::integerOption("--threads", "N", 1, 1024, "worker threads", "every core"),
            world::integerOption("--seed", "N", 0, 4294967295.0,
                                 "the paths' seed: another seed, an independent estimate", "0"),
            world::textOption("--poses", "FRAME.json",
                              "trace the dynamic objects where this capture of the level drew "
                              "them (`onelight --capture`'s JSON)",
                              "none: the static level alone"),
            world::flagOption("--item-shadows",
                              "with --poses, the items occlude light as solid objects do",
                              "seen by camera rays alone, as the frame draws them: no shadow, "
                              "and no light of the level's blocked"),
            patchLevelOption()};
        t.positionalName = "level";
        t.minPositionals = t.maxPositionals = 1;
        return t;
    }();
    return table;
}

std::string referenceUsage() {
    return world::formatHelp(referenceCommandTable());
}

int runReferenceCommand(const std::vector<std::string>& arguments) {
    return runCommandLine(referenceCommandTable(), arguments, &renderFromCommandLine);
}

namespace {

int renderFromCommandLine(const world::ParsedOptions& parsed) {
    const std::string input = parsed.positionals.at(0), output = parsed.text("-o"),
                      cameraName = parsed.text("--camera");
    const uint32_t spp = uint32_t(parsed.integer("--spp"));
    const uint32_t seed = parsed.has("--seed") ? uint32_t(parsed.integer("--seed")) : 0u;
    const std::string posesPath = parsed.has("--poses") ? parsed.text("--poses") : std::string();
    const bool itemShadows = parsed.has("--item-shadows");
    const int threads = parsed.has("--threads") ? int(parsed.integer("--threads")) : 0;
    uint32_t width = 0, height = 0;
    if (parsed.has("--size")) std::tie(width, height) = parsed.size("--size");
    const float sky =
        parsed.has("--sky") ? float(parsed.real("--sky")) : -1.0f;  // < 0: the level's
    world::Quake3Options quake3;
    if (parsed.has("--patch-level")) quake3.patchLevel = uint32_t(parsed.integer("--patch-level"));
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
        world::SplitLevel split = world::splitStaticDynamic(source);
        // Seen by camera rays alone (seen_only.hpp): the level's surfaces that light passes, and
        // the frame's items (drawn without shadows, occluding no baked light) unless
        // --item-shadows; its other dynamic objects as solid as the level.
        world::StaticGeometry seen;
        appendShadowlessSurfaces(split.staticGeometry, source.materials, seen);
        if (!posesPath.empty())
            appendPosedDynamicMeshes(split, readFramePoses(posesPath), posesPath,
                                     split.staticGeometry, itemShadows ? nullptr : &seen);
        const SceneMaterials materials = loadSceneMaterials(source);
        const BakeScene scene(device, split.staticGeometry, materials);
        std::unique_ptr<const BakeScene> seenOnly;
        if (!seen.triangles.empty())
            seenOnly =
                std::make_unique<const BakeScene>(device, seen, seenOnlyMaterials(materials));
        const BakeLights lights =
            makeLevelLights(scene, source, LightSizes{},
                            sky >= 0.0f ? std::optional(glm::vec3(sky)) : std::nullopt);
        RayCounts rays;
        Progress progress("reference", height, true);
        const ReferenceImage image = renderReference(scene, lights, *camera, width, height, spp, {},
                                                     &progress, rays, seed, seenOnly.get());
        progress.finish();
        world::writeRgbExrFile(output, image.width, image.height, image.rgb);
        std::printf("reference %s: %ux%u, %u spp, %llu rays, %.2f Mrays/s\n", output.c_str(), width,
                    height, spp, static_cast<unsigned long long>(rays.total()),
                    double(rays.total()) / progress.seconds() * 1e-6);
        return 0;
    });
}

}  // namespace
}  // namespace onelight::bake
