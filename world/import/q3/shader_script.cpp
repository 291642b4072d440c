#include "world/import/q3/shader_script.hpp"

#include <cmath>
#include <cstdlib>

#include "world/error.hpp"
#include "world/file_read.hpp"

namespace onelight::world::q3 {
namespace {

std::string lower(std::string s) {
    for (char& c : s)
        if (c >= 'A' && c <= 'Z') c = char(c - 'A' + 'a');
    return s;
}

// Tokens of a script: words or quoted strings, "{" and "}", with their lines; comments skipped.
struct Token {
    std::string text;
    int line = 0;
    bool newline = false;  // the first token of its line
};

std::vector<Token> tokenize(const std::string& s, const std::string& file) {
    std::vector<Token> out;
    int line = 1;
    bool lineStart = true;
    for (size_t i = 0; i < s.size();) {
        const char c = s[i];
        if (c == '\n') {
            ++line;
            lineStart = true;
            ++i;
        } else if (c == ' ' || c == '\t' || c == '\r') {
            ++i;
        } else if (c == '/' && i + 1 < s.size() && s[i + 1] == '/') {
            while (i < s.size() && s[i] != '\n') ++i;
        } else if (c == '/' && i + 1 < s.size() && s[i + 1] == '*') {
            const int start = line;
            i += 2;
            while (i + 1 < s.size() && !(s[i] == '*' && s[i + 1] == '/')) {
                if (s[i] == '\n') ++line;
                ++i;
            }
            if (i + 1 >= s.size())
                throw Error(file + ":" + std::to_string(start) + ": a /* comment is never closed");
            i += 2;
        } else if (c == '{' || c == '}') {
            out.push_back({std::string(1, c), line, lineStart});
            lineStart = false;
            ++i;
        } else if (c == '"') {
            const size_t end = s.find('"', i + 1);
            if (end == std::string::npos || s.find('\n', i) < end)
                throw Error(file + ":" + std::to_string(line) + ": a quote is never closed");
            out.push_back({s.substr(i + 1, end - i - 1), line, lineStart});
            lineStart = false;
            i = end + 1;
        } else {
            size_t end = i;
            while (end < s.size() && s[end] != ' ' && s[end] != '\t' && s[end] != '\r' &&
                   s[end] != '\n' && s[end] != '{' && s[end] != '}')
                ++end;
            out.push_back({s.substr(i, end - i), line, lineStart});
            lineStart = false;
            i = end;
        }
    }
    return out;
}

struct Parser {
    const std::vector<Token>& tokens;
    const std::string& file;
    size_t at = 0;

    [[nodiscard]] bool done() const { return at >= tokens.size(); }
    [[noreturn]] void fail(int line, const std::string& what) const {
        throw Error(file + ":" + std::to_string(line) + ": " + what);
    }
    // The rest of the current line's words (a keyword's arguments).
    std::vector<std::string> arguments() {
        std::vector<std::string> out;
        while (!done() && !tokens[at].newline && tokens[at].text != "{" && tokens[at].text != "}")
            out.push_back(tokens[at++].text);
        return out;
    }
    // A number as q3map2 reads it (atof): its leading number, 0 when it has none (a script
    // of the game writes an image's name where a number belongs, and q3map2 takes 0).
    static float number(const std::string& word) {
        const float v = std::strtof(word.c_str(), nullptr);
        return std::isfinite(v) ? v : 0.0f;
    }

    ShaderStage stage(int open) {
        ShaderStage s;
        while (!done() && tokens[at].text != "}") {
            const Token& t = tokens[at++];
            if (t.text == "{") fail(t.line, "a '{' inside a stage; expected its keywords or '}'");
            const std::string key = lower(t.text);
            const std::vector<std::string> args = arguments();
            if ((key == "map" || key == "clampmap") && !args.empty())
                s.map = args[0];
            else if (key == "animmap" && args.size() >= 2)
                s.map = args[1];
            else if (key == "tcgen" && !args.empty())
                s.tcGen = lower(args[0]);
            else if (key == "blendfunc") {
                for (const std::string& a : args) {
                    if (!s.blendFunc.empty()) s.blendFunc += ' ';
                    s.blendFunc += lower(a);
                }
            } else if (key == "alphafunc" && !args.empty())
                s.alphaFunc = lower(args[0]);
        }
        if (done()) fail(open, "a stage's '{' is never closed");
        ++at;  // "}"
        return s;
    }

    ShaderScript shader() {
        const Token& name = tokens[at++];
        if (name.text == "{" || name.text == "}")
            fail(name.line,
                 "'" + clipForMessage(name.text) + "' where a shader's name was expected");
        if (done() || tokens[at].text != "{")
            fail(name.line, "shader '" + clipForMessage(name.text) + "' has no '{' after its name");
        const int open = tokens[at++].line;
        ShaderScript s;
        s.name = name.text;
        s.file = file;
        s.line = name.line;
        while (!done() && tokens[at].text != "}") {
            const Token& t = tokens[at];
            if (t.text == "{") {
                ++at;
                s.stages.push_back(stage(t.line));
                continue;
            }
            ++at;
            const std::string key = lower(t.text);
            const std::vector<std::string> args = arguments();
            const auto need = [&](size_t n) {
                if (args.size() < n)
                    fail(t.line, clipForMessage(t.text) + " has " + std::to_string(args.size()) +
                                     " values; expected " + std::to_string(n));
            };
            if (key == "surfaceparm") {
                need(1);
                s.surfaceParms.insert(lower(args[0]));
            } else if (key == "qer_editorimage") {
                need(1);
                s.editorImage = args[0];
            } else if (key == "q3map_lightimage") {
                need(1);
                s.lightImage = args[0];
            } else if (key == "q3map_surfacelight") {
                need(1);
                s.surfaceLight = number(args[0]);
            } else if (key == "q3map_skylight") {
                need(1);
                s.skyLight = number(args[0]);
                // q3map2 reads the iterations on the same line; a missing one is 0, and so is
                // one that is not a count (a float past int's range would be undefined).
                const float iterations = args.size() > 1 ? number(args[1]) : 0.0f;
                s.skyLightIterations =
                    iterations >= 0.0f && iterations <= 1e6f ? int(iterations) : 0;
            } else if (key == "q3map_sun" || key == "q3map_sunext") {
                need(6);
                ShaderSun sun;
                sun.color = {number(args[0]), number(args[1]), number(args[2])};
                sun.intensity = number(args[3]);
                sun.degrees = number(args[4]);
                sun.elevation = number(args[5]);
                s.sun = sun;
            } else if (key == "cull") {
                need(1);
                const std::string mode = lower(args[0]);
                s.cullNone = mode == "none" || mode == "disable" || mode == "twosided";
            }
            // Every other keyword is the game renderer's (deformVertexes, sort, ...): skipped.
        }
        if (done()) fail(open, "shader '" + clipForMessage(s.name) + "': its '{' is never closed");
        ++at;  // "}"
        return s;
    }
};

}  // namespace

const ShaderStage* ShaderScript::colorStage() const {
    for (const ShaderStage& s : stages) {
        const std::string map = lower(s.map);
        if (map.empty() || map[0] == '$' || s.tcGen == "environment" || s.tcGen == "lightmap")
            continue;
        return &s;
    }
    return nullptr;
}

std::vector<ShaderScript> parseShaderScript(const std::string& text, const std::string& file) {
    const std::vector<Token> tokens = tokenize(text, file);
    Parser p{tokens, file};
    std::vector<ShaderScript> out;
    while (!p.done()) {
        if (tokens[p.at].text == "}") p.fail(tokens[p.at].line, "a '}' closes nothing");
        out.push_back(p.shader());
    }
    return out;
}

}  // namespace onelight::world::q3
