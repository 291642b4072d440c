// Quake 3's pk3 files (zip archives) read through libzip, and the game's virtual file system
// over several of them and the game folders' loose files: names compare case-insensitively, and
// a later source wins. A game folder is searched as the engine searches it (ioquake3's
// FS_AddGameDirectory): its pk3s in case-insensitive alphabetical order (pak0 .. pakN, a later
// one wins), then the folder's loose files, which win over every pk3 of the folder.
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
    /// The bytes of `name` (as stored), `what` it holds (for messages): refused from its
    /// declared size past `limit` bytes before anything is allocated, inflated in pieces and
    /// refused if it inflates past that size, and read to its end, where libzip checks it against
    /// the archive's CRC-32. Throws
    /// world::Error naming the archive and the entry.
    [[nodiscard]] std::vector<uint8_t> read(const std::string& name, size_t limit,
                                            const char* what) const;

private:
    std::string path_;
    struct Handle;
    std::unique_ptr<Handle> zip_;
    std::vector<std::string> names_;
};

/// Lower case (ASCII), with '\\' as '/': a key of the virtual file system.
[[nodiscard]] std::string fileKey(const std::string& name);

/// The pk3s directly in `folder`, in the order the game loads them (case-insensitive
/// alphabetical: a later one wins). Empty when the folder does not exist.
[[nodiscard]] std::vector<std::string> pk3sInLoadOrder(const std::string& folder);

/// The largest file of each kind read from a game (docs/limits.md): a map, a shader script and a
/// model (MD3; the game's largest real ones are under 1 MiB) (a map's source .map:
/// kMaxMapSourceBytes; images: kMaxEncodedImageBytes).
inline constexpr size_t kMaxMapBytes = size_t(1) << 30;
inline constexpr size_t kMaxShaderScriptBytes = size_t(16) << 20;
inline constexpr size_t kMaxModelBytes = size_t(64) << 20;

/// The most loose files a game folder may hold (its tree, pk3s left out).
inline constexpr size_t kMaxLooseFiles = 200000;

/// Several pk3s and loose folders as one tree.
struct GameFiles {
    static constexpr size_t kLoose = size_t(-1);  // the "archive" of a loose file
    std::vector<std::unique_ptr<Pk3Archive>> archives;
    // key -> (archive, stored name), or (kLoose, the file's path on disk)
    std::map<std::string, std::pair<size_t, std::string>> files;
    std::vector<std::string> looseFiles;  // every loose file's path, for SourceLevel::inputFiles

    /// One pk3; its files win over those added before. Throws world::Error naming it when it is
    /// not a readable zip.
    void add(const std::string& pk3Path);
    /// A game folder: its pk3s in the game's order, then its loose files (addLooseFiles).
    void addGameFolder(const std::string& folder);
    /// The regular files under `folder` (pk3s left out), winning over everything added before.
    /// Throws world::Error naming the folder past kMaxLooseFiles.
    void addLooseFiles(const std::string& folder);
    [[nodiscard]] bool has(const std::string& name) const;
    /// The bytes of `name`, or nothing when no archive holds it; `limit` and `what` as
    /// Pk3Archive::read's (a loose file: readRegularFile's).
    [[nodiscard]] std::optional<std::vector<uint8_t>> read(const std::string& name, size_t limit,
                                                           const char* what) const;
    /// "archive.pk3:stored/name" for messages.
    [[nodiscard]] std::string where(const std::string& name) const;
};

}  // namespace onelight::world::q3
