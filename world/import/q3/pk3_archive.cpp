#include "world/import/q3/pk3_archive.hpp"

#include <zip.h>

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

std::vector<uint8_t> Pk3Archive::read(const std::string& name) const {
    zip_stat_t stat;
    zip_stat_init(&stat);
    if (zip_stat(zip_->zip, name.c_str(), 0, &stat) != 0 || !(stat.valid & ZIP_STAT_SIZE))
        throw Error(path_ + ":" + name + ": no such file in the archive");
    if (stat.size > (zip_uint64_t(1) << 31))
        throw Error(path_ + ":" + name + ": " + std::to_string(stat.size) +
                    " bytes; expected at most 2 GiB");
    zip_file_t* file = zip_fopen(zip_->zip, name.c_str(), 0);
    if (!file) throw Error(path_ + ":" + name + ": cannot open it in the archive");
    std::vector<uint8_t> bytes(size_t(stat.size));
    const zip_int64_t got = bytes.empty() ? 0 : zip_fread(file, bytes.data(), bytes.size());
    zip_fclose(file);
    if (got != zip_int64_t(bytes.size()))
        throw Error(path_ + ":" + name + ": damaged in the archive (read " + std::to_string(got) +
                    " of " + std::to_string(bytes.size()) + " bytes)");
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

bool GameFiles::has(const std::string& name) const {
    return files.count(fileKey(name)) != 0;
}

std::optional<std::vector<uint8_t>> GameFiles::read(const std::string& name) const {
    const auto found = files.find(fileKey(name));
    if (found == files.end()) return std::nullopt;
    return archives[found->second.first]->read(found->second.second);
}

std::string GameFiles::where(const std::string& name) const {
    const auto found = files.find(fileKey(name));
    if (found == files.end()) return name;
    return archives[found->second.first]->path() + ":" + found->second.second;
}

}  // namespace onelight::world::q3
