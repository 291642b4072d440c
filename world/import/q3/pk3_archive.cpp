#include "world/import/q3/pk3_archive.hpp"

#include <zip.h>

#include <algorithm>
#include <filesystem>

#include "world/error.hpp"
#include "world/file_read.hpp"

namespace onelight::world::q3 {

struct Pk3Archive::Handle {
    zip_t* zip = nullptr;
    ~Handle() {
        if (zip) zip_discard(zip);
    }
};

Pk3Archive::Pk3Archive(const std::string& path) : path_(path), zip_(std::make_unique<Handle>()) {
    requireRegularFile(path, "a pk3 (zip) archive");
    int error = 0;
    zip_->zip = zip_open(path.c_str(), ZIP_RDONLY, &error);
    if (!zip_->zip) {
        zip_error_t e;
        zip_error_init_with_code(&e, error);
        const std::string why = zip_error_strerror(&e);
        zip_error_fini(&e);
        throw Error(path + ": not a readable pk3 (zip) archive (" + why + ")");
    }
    const zip_int64_t count = zip_get_num_entries(zip_->zip, 0);
    for (zip_int64_t i = 0; i < count; ++i) {
        const char* name = zip_get_name(zip_->zip, zip_uint64_t(i), 0);
        if (!name) continue;
        std::string n(name);
        if (!n.empty() && n.back() != '/') names_.push_back(std::move(n));
    }
}

Pk3Archive::~Pk3Archive() = default;

std::vector<uint8_t> Pk3Archive::read(const std::string& name, size_t limit,
                                      const char* what) const {
    const std::string where = path_ + ":" + clipForMessage(name);
    zip_stat_t stat;
    zip_stat_init(&stat);
    if (zip_stat(zip_->zip, name.c_str(), 0, &stat) != 0 || !(stat.valid & ZIP_STAT_SIZE))
        throw Error(where + ": no such file in the archive");
    if (stat.size > limit)
        throw Error(where + ": " + std::to_string(stat.size) + " bytes uncompressed; expected " +
                    what + " of at most " + std::to_string(limit));
    zip_file_t* file = zip_fopen(zip_->zip, name.c_str(), 0);
    if (!file) throw Error(where + ": cannot open it in the archive");
    std::vector<uint8_t> bytes(size_t(stat.size));
    size_t done = 0;
    std::string damage;
    while (damage.empty()) {
        // In pieces of at most 16 MiB, and one byte past the declared size to see the end:
        // reaching it is where libzip compares the entry's CRC-32 with the archive's.
        uint8_t past = 0;
        const size_t want = std::min<size_t>(bytes.size() - done, size_t(16) << 20);
        uint8_t* into = want ? bytes.data() + done : &past;
        const zip_int64_t got = zip_fread(file, into, want ? want : 1);
        if (got < 0) {
            damage = zip_file_strerror(file);
        } else if (want == 0) {
            if (got > 0)
                damage = "it inflates past its declared " + std::to_string(stat.size) + " bytes";
            break;
        } else if (got == 0) {
            damage = "read " + std::to_string(done) + " of its " + std::to_string(bytes.size()) +
                     " bytes";
        } else {
            done += size_t(got);
        }
    }
    zip_fclose(file);
    if (!damage.empty()) throw Error(where + ": damaged in the archive (" + damage + ")");
    return bytes;
}

std::string fileKey(const std::string& name) {
    std::string key = name;
    for (char& c : key) {
        if (c == '\\') c = '/';
        if (c >= 'A' && c <= 'Z') c = char(c - 'A' + 'a');
    }
    return key;
}

void GameFiles::add(const std::string& pk3Path) {
    archives.push_back(std::make_unique<Pk3Archive>(pk3Path));
    const size_t a = archives.size() - 1;
    for (const std::string& n : archives[a]->names()) files[fileKey(n)] = {a, n};
}

std::vector<std::string> pk3sInLoadOrder(const std::string& folder) {
    std::vector<std::string> pk3s;
    std::error_code ec;
    for (const auto& entry : std::filesystem::directory_iterator(folder, ec)) {
        const std::string key = fileKey(entry.path().filename().string());
        if (key.size() > 4 && key.compare(key.size() - 4, 4, ".pk3") == 0 &&
            entry.is_regular_file(ec))
            pk3s.push_back(entry.path().string());
    }
    std::sort(pk3s.begin(), pk3s.end(), [](const std::string& a, const std::string& b) {
        const std::string ka = fileKey(std::filesystem::path(a).filename().string()),
                          kb = fileKey(std::filesystem::path(b).filename().string());
        return ka != kb ? ka < kb : a < b;
    });
    return pk3s;
}

void GameFiles::addGameFolder(const std::string& folder) {
    for (const std::string& pk3 : pk3sInLoadOrder(folder)) add(pk3);
    addLooseFiles(folder);
}

void GameFiles::addLooseFiles(const std::string& folder) {
    namespace fs = std::filesystem;
    std::error_code ec;
    if (!fs::is_directory(folder, ec)) return;
    std::vector<std::pair<std::string, std::string>> found;  // (key, path)
    for (auto it = fs::recursive_directory_iterator(
             folder, fs::directory_options::skip_permission_denied, ec);
         !ec && it != fs::recursive_directory_iterator(); it.increment(ec)) {
        if (!it->is_regular_file(ec)) continue;
        const std::string relative =
            fs::path(it->path()).lexically_relative(folder).generic_string();
        const std::string key = fileKey(relative);
        if (key.size() > 4 && key.compare(key.size() - 4, 4, ".pk3") == 0) continue;
        if (found.size() >= kMaxLooseFiles)
            throw Error(folder + ": more than " + std::to_string(kMaxLooseFiles) +
                        " loose files; expected a game folder (pk3s, maps/, textures/, scripts/)");
        found.emplace_back(key, it->path().string());
    }
    // A fixed order, so that two names differing only in case resolve the same way every run.
    std::sort(found.begin(), found.end());
    for (auto& [key, path] : found) {
        looseFiles.push_back(path);
        files[key] = {kLoose, std::move(path)};
    }
}

bool GameFiles::has(const std::string& name) const {
    return files.count(fileKey(name)) != 0;
}

std::optional<std::vector<uint8_t>> GameFiles::read(const std::string& name, size_t limit,
                                                    const char* what) const {
    const auto found = files.find(fileKey(name));
    if (found == files.end()) return std::nullopt;
    if (found->second.first == kLoose) return readRegularFile(found->second.second, what, limit);
    return archives[found->second.first]->read(found->second.second, limit, what);
}

std::string GameFiles::where(const std::string& name) const {
    const auto found = files.find(fileKey(name));
    if (found == files.end()) return name;
    if (found->second.first == kLoose) return found->second.second;
    return archives[found->second.first]->path() + ":" + found->second.second;
}

}  // namespace onelight::world::q3
