#include <cstdio>
#include <fstream>
#include <stdexcept>
#include <system_error>

#include "grids.hpp"

namespace onelight::lab {

void writeFileAtomically(const std::string& path, const std::string& text) {
    std::string tmp = path + ".tmp";
    {
        std::ofstream out(tmp, std::ios::binary);
        out << text;
        out.close();
        if (!out) throw std::runtime_error(path + ": cannot write " + tmp);
    }
    if (std::rename(tmp.c_str(), path.c_str()) != 0)
        throw std::runtime_error(path + ": cannot rename " + tmp + ": " +
                                 std::generic_category().message(errno));
}

}  // namespace onelight::lab
