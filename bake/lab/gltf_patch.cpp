#include "gltf_patch.hpp"

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <stdexcept>

#include "grids.hpp"
#include "world/file_write.hpp"

namespace onelight::lab {

bool canPatchLevel(const std::string& level) {
    return std::filesystem::path(level).extension() == ".gltf";
}

std::string writePatchedLevel(const std::string& level, const std::string& key,
                              const std::string& value) {
    std::ifstream in(level);
    if (!in) throw std::runtime_error(level + ": cannot read");
    nlohmann::json doc;
    try {
        doc = nlohmann::json::parse(in);
    } catch (const std::exception& e) {
        throw std::runtime_error(level + ": not JSON: " + e.what());
    }
    if (!doc.is_object()) throw std::runtime_error(level + ": not a glTF object");
    if (!doc.contains("nodes")) doc["nodes"] = nlohmann::json::array();
    if (!doc["nodes"].is_array()) throw std::runtime_error(level + ": nodes is not an array");
    const size_t node = doc["nodes"].size();
    doc["nodes"].push_back(
        {{"name", "level_report_" + key}, {"extras", {{"onelight", {{key, value}}}}}});
    const size_t scene =
        doc.contains("scene") && doc["scene"].is_number_unsigned() ? doc["scene"].get<size_t>() : 0;
    if (!doc.contains("scenes") || !doc["scenes"].is_array() || scene >= doc["scenes"].size())
        throw std::runtime_error(level + ": no scene " + std::to_string(scene));
    nlohmann::json& nodes = doc["scenes"][scene]["nodes"];
    if (nodes.is_null()) nodes = nlohmann::json::array();
    nodes.push_back(node);
    const std::filesystem::path path = std::filesystem::path(level);
    const std::string out = (path.parent_path() / (path.stem().string() + ".level-report-" + key +
                                                   "-" + value + ".gltf"))
                                .string();
    world::writeFileAtomically(out, doc.dump());
    return out;
}

}  // namespace onelight::lab
