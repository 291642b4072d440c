#include "file_read.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>

#include "world/error.hpp"

namespace onelight::world {

namespace {

// Closes a descriptor on every path out.
struct FileDescriptor {
    int fd = -1;
    ~FileDescriptor() {
        if (fd >= 0) ::close(fd);
    }
};

// Opens `path` for reading into `file` and returns its size; throws when it is not a regular
// file of at most maxBytes.
uint64_t openRegularFile(FileDescriptor& file, const std::string& path, const char* expected,
                         uint64_t maxBytes) {
    // O_NONBLOCK: opening a FIFO must not wait for a writer; fstat then refuses it.
    file.fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
    if (file.fd < 0)
        throw Error(path + ": cannot open (" + std::strerror(errno) + "); expected " + expected);
    struct stat info {};
    if (::fstat(file.fd, &info) != 0 || !S_ISREG(info.st_mode)) {
        const char* kind = S_ISDIR(info.st_mode)    ? "a directory"
                           : S_ISFIFO(info.st_mode) ? "a FIFO"
                           : S_ISCHR(info.st_mode)  ? "a character device"
                           : S_ISBLK(info.st_mode)  ? "a block device"
                           : S_ISSOCK(info.st_mode) ? "a socket"
                                                    : "not a regular file";
        throw Error(path + ": is " + kind + "; expected " + expected + " (a regular file)");
    }
    const uint64_t size = uint64_t(info.st_size);
    if (size > maxBytes)
        throw Error(path + ": " + std::to_string(size) + " bytes; expected " + expected +
                    " of at most " + std::to_string(maxBytes) + " bytes");
    return size;
}

}  // namespace

void requireRegularFile(const std::string& path, const char* expected, uint64_t maxBytes) {
    FileDescriptor file;
    openRegularFile(file, path, expected, maxBytes);
}

std::vector<uint8_t> readRegularFile(const std::string& path, const char* expected,
                                     uint64_t maxBytes) {
    FileDescriptor file;
    const uint64_t size = openRegularFile(file, path, expected, maxBytes);
    std::vector<uint8_t> bytes(size);
    size_t done = 0;
    while (done < bytes.size()) {
        const ssize_t n = ::read(file.fd, bytes.data() + done, bytes.size() - done);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0)
            throw Error(path + ": read failed after " + std::to_string(done) + " of " +
                        std::to_string(size) + " bytes (" +
                        (n < 0 ? std::strerror(errno) : "the file shrank") + ")");
        done += size_t(n);
    }
    return bytes;
}

bool sameFile(const std::string& a, const std::string& b) {
    struct stat sa {
    }, sb{};
    if (::stat(a.c_str(), &sa) != 0 || ::stat(b.c_str(), &sb) != 0) return false;
    return sa.st_dev == sb.st_dev && sa.st_ino == sb.st_ino;
}

void refuseOutputOverInput(const std::string& output, const std::vector<std::string>& inputs) {
    for (const std::string& input : inputs)
        if (!input.empty() && sameFile(output, input))
            throw Error(output + ": the output is the input " + input +
                        "; expected a different output path (nothing was written)");
}

std::string clipForMessage(std::string_view text, size_t maxChars) {
    std::string out;
    const size_t shown = std::min(text.size(), maxChars);
    out.reserve(shown + 32);
    for (size_t i = 0; i < shown; ++i) {
        const unsigned char c = static_cast<unsigned char>(text[i]);
        out += (c < 0x20 || c == 0x7f) ? '?' : char(c);
    }
    if (shown < text.size()) out += "... (" + std::to_string(text.size()) + " characters)";
    return out;
}

std::string oneLineMessage(std::string_view message) {
    constexpr size_t kLongest = 128, kHead = 32, kTail = 64;
    std::string out;
    out.reserve(std::min<size_t>(message.size(), 1024));
    size_t at = 0;
    while (at < message.size()) {
        const size_t space = message.find(' ', at);
        const size_t end = space == std::string_view::npos ? message.size() : space;
        const std::string_view word = message.substr(at, end - at);
        const auto shown = [](std::string_view part) {
            std::string s(part);
            for (char& c : s)
                if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) c = '?';
            return s;
        };
        if (word.size() > kLongest)
            out += shown(word.substr(0, kHead)) + "..." + shown(word.substr(word.size() - kTail)) +
                   " (" + std::to_string(word.size()) + " characters)";
        else
            out += shown(word);
        if (end < message.size()) out += ' ';
        at = end + 1;
    }
    return out;
}

}  // namespace onelight::world
