// libFuzzer target: glTF and glb import (our checks, then tinygltf, then the importer and the
// level limits). Any input must end in a world::Error or a level, never a crash.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "world/error.hpp"
#include "world/import/gltf_import.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    try {
        (void)onelight::world::importGltfBytes(std::vector<uint8_t>(data, data + size),
                                               "/nonexistent/fuzz.gltf");
    } catch (const onelight::world::Error&) {
    }
    return 0;
}
