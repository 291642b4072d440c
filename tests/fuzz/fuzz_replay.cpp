// libFuzzer target: replay scripts. Any input must end in a ScriptError or a script, never a
// crash; a script that parses keeps every documented limit.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string_view>

#include "replay/replay_script.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    using namespace onelight::replay;
    try {
        const Script script =
            parseScript(std::string_view(reinterpret_cast<const char*>(data), size), "fuzz.replay");
        for (const Command& c : script.commands) {
            if (!(c.time >= 0.0 && c.time <= kMaxScriptSeconds)) std::abort();
            for (float v : c.values)
                if (!std::isfinite(v)) std::abort();
        }
        if (script.commands.size() > kMaxScriptCommands) std::abort();
    } catch (const ScriptError&) {
    }
    return 0;
}
