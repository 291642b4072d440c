#include "world/file_write.hpp"

#include <atomic>
#include <cerrno>
#include <filesystem>
#include <system_error>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include "world/error.hpp"
#include "world/file_read.hpp"

namespace onelight::world {

namespace {

std::string reason(int error) {
    return std::generic_category().message(error);
}

// Unique to this process and this call: two threads or two processes writing one path each have
// their own temporary, and the last rename wins whole.
std::string temporaryPathFor(const std::string& path) {
    static std::atomic<uint64_t> calls{0};
    return path + ".tmp." + std::to_string(::getpid()) + "." + std::to_string(calls++);
}

void makeFolderOf(const std::string& path) {
    const std::filesystem::path folder = std::filesystem::path(path).parent_path();
    if (folder.empty()) return;
    std::error_code ec;
    std::filesystem::create_directories(folder, ec);
    if (ec)
        throw Error(path + ": cannot create its folder " + folder.string() + " (" + ec.message() +
                    ")");
}

}  // namespace

void makeFolder(const std::string& folder, const std::string& from) {
    std::error_code ec;
    if (std::filesystem::is_directory(folder, ec)) return;
    std::filesystem::create_directories(folder, ec);
    if (ec || !std::filesystem::is_directory(folder, ec))
        throw Error(from + " '" + clipForMessage(folder) + "': cannot make that folder (" +
                    (ec ? ec.message() : std::string("a file is in the way")) +
                    "); expected a folder, or a path where one can be made");
}

void writeFileAtomicallyWith(const std::string& path,
                             const std::function<void(const std::string& temporary)>& write) {
    if (path.empty()) throw Error("an output file with an empty name");
    makeFolderOf(path);
    const std::string temporary = temporaryPathFor(path);
    try {
        write(temporary);
        struct stat written {};
        if (::stat(temporary.c_str(), &written) != 0)
            throw Error(path + ": " + temporary + " was not written (" + reason(errno) + ")");
        if (!S_ISREG(written.st_mode))
            throw Error(path + ": " + temporary + " is not a regular file");
        if (::rename(temporary.c_str(), path.c_str()) != 0)
            throw Error(path + ": cannot rename " + temporary + " into place (" + reason(errno) +
                        ")");
    } catch (...) {
        ::unlink(temporary.c_str());
        throw;
    }
}

void writeFileAtomically(const std::string& path, std::span<const uint8_t> bytes) {
    writeFileAtomicallyWith(path, [&](const std::string& temporary) {
        const int fd = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
        if (fd < 0) throw Error(path + ": cannot create " + temporary + " (" + reason(errno) + ")");
        size_t done = 0;
        while (done < bytes.size()) {
            const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
            if (n < 0 && errno == EINTR) continue;
            if (n <= 0) {
                const int error = n < 0 ? errno : EIO;
                ::close(fd);
                throw Error(path + ": cannot write " + temporary + " (" + reason(error) + ")");
            }
            done += size_t(n);
        }
        if (::close(fd) != 0)
            throw Error(path + ": cannot write " + temporary + " (" + reason(errno) + ")");
    });
}

void writeFileAtomically(const std::string& path, std::string_view bytes) {
    writeFileAtomically(path, std::span<const uint8_t>(
                                  reinterpret_cast<const uint8_t*>(bytes.data()), bytes.size()));
}

}  // namespace onelight::world
