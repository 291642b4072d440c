// libFuzzer target: the Quake 3 text formats beyond the BSP: a map's source .map (the parser
// that recovers the light entities q3map2 stripped), a shader script, and q3map2's recorded
// command line as worldspawn holds it. Any input must end in a world::Error or a result, never
// a crash.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "world/error.hpp"
#include "world/import/q3/entity_lump.hpp"
#include "world/import/q3/map_source.hpp"
#include "world/import/q3/q3map2_command_line.hpp"
#include "world/import/q3/shader_script.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    using namespace onelight::world;
    const std::string text(reinterpret_cast<const char*>(data), size);
    try {
        const std::vector<q3::MapEntity> entities = q3::parseMapSource(text, "fuzz.map");
        for (const q3::MapEntity& e : entities) {
            try {
                (void)q3::numberKey(e, "light", 300.0f, "fuzz.map");
                (void)q3::vectorKey(e, "origin", {}, "fuzz.map");
            } catch (const Error&) {
            }
        }
    } catch (const Error&) {
    }
    try {
        (void)q3::parseShaderScript(text, "fuzz.shader");
    } catch (const Error&) {
    }
    q3::MapEntity worldspawn;
    worldspawn.keys["_q3map2_cmdline"] = text;
    const q3::Q3map2LightOptions options = q3::readQ3map2LightOptions({worldspawn}, "fuzz.bsp");
    (void)options.summary();
    (void)q3::compensateShownByPages(std::vector<uint8_t>(data, data + size));
    return 0;
}
