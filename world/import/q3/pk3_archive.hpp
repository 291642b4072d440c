// Quake 3's pk3 files (zip archives) read through libzip, and the game's virtual file system
// over several of them: names compare case-insensitively, and a later archive wins, as the
// engine loads pak0 .. pakN in order.
#pragma once

#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace onelight::world::q3 {

/// One open pk3. Throws world::Error naming the file when it is not a readable zip.
class Pk3Archive {
public:
    explicit Pk3Archive(const std::string& path);
    ~Pk3Archive();
    Pk3Archive(const Pk3Archive&) = delete;
    Pk3Archive& operator=(const Pk3Archive&) = delete;

    [[nodiscard]] const std::string& path() const { return path_; }
    /// Every file's name as stored (directories left out).
    [[nodiscard]] const std::vector<std::string>& names() const { return names_; }
    /// The bytes of `name` (as stored). Throws world::Error on a damaged entry.
    [[nodiscard]] std::vector<uint8_t> read(const std::string& name) const;

private:
    std::string path_;
    struct Handle;
    std::unique_ptr<Handle> zip_;
    std::vector<std::string> names_;
};

/// Lower case (ASCII), with '\\' as '/': a key of the virtual file system.
[[nodiscard]] std::string fileKey(const std::string& name);

/// Several pk3s as one tree.
struct GameFiles {
    std::vector<std::unique_ptr<Pk3Archive>> archives;
    std::map<std::string, std::pair<size_t, std::string>> files;  // key -> (archive, stored name)

    void add(const std::string& pk3Path);
    [[nodiscard]] bool has(const std::string& name) const;
    /// The bytes of `name`, or nothing when no archive holds it.
    [[nodiscard]] std::optional<std::vector<uint8_t>> read(const std::string& name) const;
    /// "archive.pk3:stored/name" for messages.
    [[nodiscard]] std::string where(const std::string& name) const;
};

}  // namespace onelight::world::q3
