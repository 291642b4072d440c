// libFuzzer target: Quake 3 models (MD3). Any input must end in a world::Error or a model whose
// every index lies inside its surface, never a crash.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <span>

#include "world/error.hpp"
#include "world/import/q3/md3_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    using namespace onelight::world;
    try {
        const q3::Md3Model m = q3::parseMd3(std::span<const uint8_t>(data, size), "fuzz.md3");
        for (const q3::Md3Surface& s : m.surfaces) {
            for (uint32_t i : s.indices)
                if (i >= s.vertexCount) std::abort();
            if (s.positions.size() != size_t(s.vertexCount) * m.frames.size()) std::abort();
        }
    } catch (const Error&) {
    }
    return 0;
}
