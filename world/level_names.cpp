#include "world/level_names.hpp"

#include <filesystem>

namespace onelight::world {
namespace {

std::string lower(std::string s) {
    for (char& c : s)
        if (c >= 'A' && c <= 'Z') c = char(c - 'A' + 'a');
    return s;
}

}  // namespace

bool isQuake3Map(const std::string& level) {
    const std::string l = lower(level);
    if (l.size() >= 4 && l.compare(l.size() - 4, 4, ".bsp") == 0) return true;
    if (l.find(".pk3:") != std::string::npos) return true;
    return !level.empty() && level.find('/') == std::string::npos &&
           std::filesystem::path(level).extension().empty();
}

std::string defaultPackagePath(const std::string& level) {
    if (!isQuake3Map(level))
        return std::filesystem::path(level).replace_extension(".olpak").string();
    const size_t colon = level.rfind(':');
    const std::string map = colon == std::string::npos ? level : level.substr(colon + 1);
    return std::filesystem::path(map).filename().replace_extension(".olpak").string();
}

}  // namespace onelight::world
