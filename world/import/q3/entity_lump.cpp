#include "world/import/q3/entity_lump.hpp"

#include <cmath>
#include <cstdlib>

#include "world/error.hpp"

namespace onelight::world::q3 {
namespace {

struct Cursor {
    const std::string& text;
    size_t at = 0;
    int line = 1;
    void skipSpace() {
        while (at < text.size() &&
               (text[at] == ' ' || text[at] == '\t' || text[at] == '\r' || text[at] == '\n')) {
            if (text[at] == '\n') ++line;
            ++at;
        }
    }
};

std::string quoted(Cursor& c, const std::string& where) {
    if (c.at >= c.text.size() || c.text[c.at] != '"')
        throw Error(where + ": entities line " + std::to_string(c.line) +
                    ": expected a quoted key or '}'");
    const size_t end = c.text.find('"', c.at + 1);
    if (end == std::string::npos)
        throw Error(where + ": entities line " + std::to_string(c.line) +
                    ": a quote is never closed");
    std::string s = c.text.substr(c.at + 1, end - c.at - 1);
    for (char ch : s)
        if (ch == '\n') ++c.line;
    c.at = end + 1;
    return s;
}

}  // namespace

std::string MapEntity::get(const std::string& key, const std::string& fallback) const {
    const auto found = keys.find(key);
    return found == keys.end() ? fallback : found->second;
}

std::vector<MapEntity> parseEntities(const std::string& text, const std::string& where) {
    std::vector<MapEntity> out;
    Cursor c{text};
    for (c.skipSpace(); c.at < text.size(); c.skipSpace()) {
        if (text[c.at] != '{')
            throw Error(where + ": entities line " + std::to_string(c.line) +
                        ": expected '{' to open an entity");
        MapEntity e;
        e.line = c.line;
        ++c.at;
        for (c.skipSpace(); c.at < text.size() && text[c.at] != '}'; c.skipSpace()) {
            std::string key = quoted(c, where);
            c.skipSpace();
            e.keys[key] = quoted(c, where);
        }
        if (c.at >= text.size())
            throw Error(where + ": entities line " + std::to_string(e.line) +
                        ": an entity is never closed with '}'");
        ++c.at;
        out.push_back(std::move(e));
    }
    return out;
}

namespace {

std::vector<float> numbers(const MapEntity& e, const std::string& key, const std::string& where) {
    const std::string text = e.get(key);
    std::vector<float> out;
    const char* p = text.c_str();
    while (*p) {
        char* end = nullptr;
        const float v = std::strtof(p, &end);
        if (end == p) {
            if (*p == ' ' || *p == '\t') {
                ++p;
                continue;
            }
            throw Error(where + ": entities line " + std::to_string(e.line) + ": \"" + key +
                        "\" is '" + text + "'; expected numbers");
        }
        if (!std::isfinite(v))
            throw Error(where + ": entities line " + std::to_string(e.line) + ": \"" + key +
                        "\" is not finite");
        out.push_back(v);
        p = end;
    }
    return out;
}

}  // namespace

float numberKey(const MapEntity& e, const std::string& key, float fallback,
                const std::string& where) {
    if (!e.keys.count(key)) return fallback;
    const std::vector<float> v = numbers(e, key, where);
    if (v.empty()) return fallback;
    if (v.size() != 1)
        throw Error(where + ": entities line " + std::to_string(e.line) + ": \"" + key +
                    "\" holds " + std::to_string(v.size()) + " numbers; expected one");
    return v[0];
}

glm::vec3 vectorKey(const MapEntity& e, const std::string& key, glm::vec3 fallback,
                    const std::string& where) {
    if (!e.keys.count(key)) return fallback;
    const std::vector<float> v = numbers(e, key, where);
    if (v.empty()) return fallback;
    if (v.size() != 3)
        throw Error(where + ": entities line " + std::to_string(e.line) + ": \"" + key +
                    "\" holds " + std::to_string(v.size()) + " numbers; expected three");
    return {v[0], v[1], v[2]};
}

float firstNumberKey(const MapEntity& e, const std::string& key, float fallback,
                     const std::string& where, bool* more) {
    if (!e.keys.count(key)) return fallback;
    const std::vector<float> v = numbers(e, key, where);
    if (v.empty()) return fallback;
    if (more) *more = *more || v.size() > 1;
    return v[0];
}

}  // namespace onelight::world::q3
