// libFuzzer target: the .olpak reader, as the runtime reads a package: the core sections, then
// the baked ones (lightmaps, shadow masks, grid, probes, visibility) and the texture stage's.
// Checksums are part of the format, so most mutations stop at a CRC; the seed corpus's packages
// reach the deeper checks, and `-use_value_profile=1` helps the fuzzer past the CRC comparisons.
#include <cstddef>
#include <cstdint>
#include <span>

#include "world/error.hpp"
#include "world/package/baked_sections.hpp"
#include "world/package/package_reader.hpp"
#include "world/package/texture_section.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    using namespace onelight;
    try {
        const package::PackageContents read =
            package::parsePackage(std::span<const uint8_t>(data, size), "fuzz.olpak");
        (void)package::decodeBakedSections(read.bakedSections, read.level, "fuzz.olpak");
        (void)package::decodeTextureSection(read.bakedSections, read.level, "fuzz.olpak");
    } catch (const world::Error&) {
    }
    return 0;
}
