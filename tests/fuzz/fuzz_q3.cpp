// libFuzzer target: the Quake 3 inputs: the BSP's lumps, and the same bytes as a shader script
// and as an entity lump. Any input must end in a world::Error or a result, never a crash.
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>

#include "world/error.hpp"
#include "world/import/q3/bsp_file.hpp"
#include "world/import/q3/entity_lump.hpp"
#include "world/import/q3/shader_script.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    using namespace onelight::world;
    try {
        (void)q3::parseBsp(std::span<const uint8_t>(data, size), "fuzz.bsp");
    } catch (const Error&) {
    }
    const std::string text(reinterpret_cast<const char*>(data), size);
    try {
        (void)q3::parseShaderScript(text, "fuzz.shader");
    } catch (const Error&) {
    }
    try {
        (void)q3::parseEntities(text, "fuzz.bsp entities");
    } catch (const Error&) {
    }
    return 0;
}
