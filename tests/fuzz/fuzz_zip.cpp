// libFuzzer target: pk3 (zip) archives through the reader the Quake 3 import uses: every entry
// listed and read under a bound, inflated in pieces and checked against its CRC. libzip opens
// files, so each input is written to a file of this process first. Any input must end in a
// world::Error or the entries' bytes, never a crash or an allocation past the bound.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <string>

#include "world/error.hpp"
#include "world/import/q3/pk3_archive.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    using namespace onelight::world;
    static const std::string path = "/tmp/onelight-fuzz-zip-" + std::to_string(::getpid()) + ".pk3";
    std::FILE* f = std::fopen(path.c_str(), "wb");
    if (!f) return 0;
    const bool written = std::fwrite(data, 1, size, f) == size;
    std::fclose(f);
    if (!written) return 0;
    try {
        q3::GameFiles files;
        files.add(path);
        for (const auto& [key, where] : files.files) {
            try {
                (void)files.read(key, size_t(1) << 20, "a fuzzed entry");
            } catch (const Error&) {
            }
        }
    } catch (const Error&) {
    }
    return 0;
}
