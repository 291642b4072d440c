#include "world/import/level_import.hpp"

#include "world/import/gltf_import.hpp"

namespace onelight::world {

SourceLevel importLevel(const std::string& spec, const Quake3Options& quake3) {
    return isQuake3Map(spec) ? importQuake3(spec, quake3) : importGltf(spec);
}

}  // namespace onelight::world
