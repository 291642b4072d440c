// onelight-make-demo-level FOLDER: writes the demo level's glTF (demo.gltf + demo.bin).
#include <cstdio>
#include <exception>
#include <string>

#include "demo_level.hpp"
#include "world/file_read.hpp"

int main(int argc, char** argv) {
    if (argc != 2) {
        std::fprintf(stderr, "usage: onelight-make-demo-level FOLDER\n");
        return 1;
    }
    try {
        std::printf("%s\n", onelight::game::writeDemoLevel(argv[1]).c_str());
    } catch (const std::exception& e) {
        std::fprintf(
            stderr, "onelight-make-demo-level: %s\n",
            onelight::world::oneLineMessage(std::string(argv[1]) + ": " + e.what()).c_str());
        return 1;
    }
    return 0;
}
