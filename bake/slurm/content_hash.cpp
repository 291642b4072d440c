#include "bake/slurm/content_hash.hpp"

#include <cstdio>

#include "world/file_read.hpp"

namespace onelight::bake::slurm {

uint64_t hashBytes(std::span<const uint8_t> bytes, uint64_t hash) {
    for (const uint8_t b : bytes) {
        hash ^= b;
        hash *= 0x100000001b3ull;  // FNV-1a 64 prime
    }
    return hash;
}

uint64_t hashText(std::string_view text, uint64_t hash) {
    return hashBytes(std::span(reinterpret_cast<const uint8_t*>(text.data()), text.size()), hash);
}

uint64_t hashFiles(const std::vector<std::string>& paths) {
    uint64_t hash = kHashSeed;
    for (const std::string& path : paths) {
        const std::vector<uint8_t> bytes = world::readRegularFile(path, "a file of the level");
        hash = hashText(std::to_string(bytes.size()) + ":", hash);
        hash = hashBytes(bytes, hash);
    }
    return hash;
}

std::string hashHex(uint64_t hash) {
    char text[17];
    std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(hash));
    return text;
}

}  // namespace onelight::bake::slurm
