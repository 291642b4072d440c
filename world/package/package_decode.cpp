#include "world/package/package_decode.hpp"

namespace onelight::package {

DecodedPackage decodePackage(std::span<const uint8_t> bytes, const std::string& name) {
    DecodedPackage out;
    out.contents = parsePackage(bytes, name);
    out.baked = decodeBakedSections(out.contents.bakedSections, out.contents.level, name);
    out.textures = decodeTextureSection(out.contents.bakedSections, out.contents.level, name);
    return out;
}

}  // namespace onelight::package
