// libFuzzer target: `onelight`'s command line. The input is split at NUL bytes into arguments;
// any argv must end in a world::Error or a parsed command line, never a crash, and what parses
// keeps its documented ranges.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <vector>

#include "game/command_line.hpp"
#include "world/error.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    std::vector<std::string> words{"onelight"};
    std::string word;
    for (size_t i = 0; i < size; ++i) {
        if (data[i] == 0) {
            words.push_back(word);
            word.clear();
        } else {
            word += char(data[i]);
        }
    }
    words.push_back(word);
    std::vector<char*> argv;
    for (std::string& w : words) argv.push_back(w.data());
    try {
        const onelight::game::CommandLine cl =
            onelight::game::parseCommandLine(int(argv.size()), argv.data());
        if (!cl.help && (cl.width < 1 || cl.width > 16384 || cl.height < 1 || cl.height > 16384))
            std::abort();
        if (cl.renderScale != 0.0f && !(cl.renderScale >= 0.25f && cl.renderScale <= 1.0f))
            std::abort();
    } catch (const onelight::world::Error&) {
    }
    return 0;
}
