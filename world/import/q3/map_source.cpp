#include "world/import/q3/map_source.hpp"

#include "world/error.hpp"

namespace onelight::world::q3 {
namespace {

struct SourceCursor {
    const std::string& text;
    const std::string& where;
    size_t at = 0;
    int line = 1;

    [[noreturn]] void fail(int atLine, const std::string& what) const {
        throw Error(where + ": line " + std::to_string(atLine) + ": " + what);
    }
    // Past spaces, line ends and // comments.
    void skipSpace() {
        while (at < text.size()) {
            const char c = text[at];
            if (c == '\n') {
                ++line;
                ++at;
            } else if (c == ' ' || c == '\t' || c == '\r') {
                ++at;
            } else if (c == '/' && at + 1 < text.size() && text[at + 1] == '/') {
                while (at < text.size() && text[at] != '\n') ++at;
            } else {
                return;
            }
        }
    }
    [[nodiscard]] bool done() const { return at >= text.size(); }
    [[nodiscard]] char peek() const { return text[at]; }

    // A quoted string (the cursor at its opening quote), without its quotes.
    std::string quoted() {
        const int start = line;
        const size_t end = text.find('"', at + 1);
        if (end == std::string::npos) fail(start, "a quote is never closed");
        std::string s = text.substr(at + 1, end - at - 1);
        for (char ch : s)
            if (ch == '\n') ++line;
        at = end + 1;
        return s;
    }

    // A block in braces inside an entity (the cursor at its '{'): brush, brushDef or patch.
    void skipBlock() {
        const int start = line;
        int depth = 0;
        while (!done()) {
            const char c = peek();
            if (c == '"') {
                (void)quoted();
                continue;
            }
            if (c == '{') {
                if (++depth > kMaxMapSourceDepth - 1)
                    fail(line, "blocks nested deeper than " + std::to_string(kMaxMapSourceDepth) +
                                   " levels; expected brushes and patches inside entities");
            } else if (c == '}') {
                ++at;
                if (--depth == 0) return;
                continue;
            } else if (c == '/' && at + 1 < text.size() && text[at + 1] == '/') {
                skipSpace();
                continue;
            } else if (c == '\n') {
                ++line;
            }
            ++at;
        }
        fail(start, "a brush or patch opened here is never closed with '}'");
    }
};

}  // namespace

std::vector<MapEntity> parseMapSource(const std::string& text, const std::string& where) {
    if (text.size() > kMaxMapSourceBytes)
        throw Error(where + ": " + std::to_string(text.size()) + " bytes; expected at most " +
                    std::to_string(kMaxMapSourceBytes) + " for a .map source");
    std::vector<MapEntity> out;
    SourceCursor c{text, where};
    for (c.skipSpace(); !c.done(); c.skipSpace()) {
        if (c.peek() != '{') c.fail(c.line, "expected '{' to open an entity");
        if (out.size() == kMaxMapSourceEntities)
            c.fail(c.line, "more than " + std::to_string(kMaxMapSourceEntities) + " entities");
        MapEntity e;
        e.line = c.line;
        ++c.at;
        for (c.skipSpace(); !c.done() && c.peek() != '}'; c.skipSpace()) {
            if (c.peek() == '{') {
                c.skipBlock();
                continue;
            }
            if (c.peek() != '"') c.fail(c.line, "expected a quoted key, a brush or '}'");
            const int keyLine = c.line;
            std::string key = c.quoted();
            c.skipSpace();
            if (c.done() || c.peek() != '"')
                c.fail(keyLine, "key \"" + key + "\" has no quoted value");
            e.keys[key] = c.quoted();
        }
        if (c.done()) c.fail(e.line, "an entity opened here is never closed with '}'");
        ++c.at;
        out.push_back(std::move(e));
    }
    return out;
}

}  // namespace onelight::world::q3
