// 64-bit content hashes (FNV-1a over 64-bit words, content_hash.cpp): what a Slurm work folder
// records of the level and of each shard's package, to tell a finished shard from a stale or
// damaged one. Not cryptographic: they catch edits and corruption, not an adversary.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace onelight::bake::slurm {

constexpr uint64_t kHashSeed = 0xcbf29ce484222325ull;  // FNV-1a 64 offset basis

/// The hash of `bytes`, continuing from `hash`.
[[nodiscard]] uint64_t hashBytes(std::span<const uint8_t> bytes, uint64_t hash = kHashSeed);
[[nodiscard]] uint64_t hashText(std::string_view text, uint64_t hash = kHashSeed);

/// The hash of the files' contents in order (each file's size and the hash of its bytes, read a
/// megabyte at a time): the level as the import read it (SourceLevel::inputFiles). Throws
/// world::Error naming an unreadable file.
[[nodiscard]] uint64_t hashFiles(const std::vector<std::string>& paths);

/// 16 lower-case hex digits.
[[nodiscard]] std::string hashHex(uint64_t hash);

}  // namespace onelight::bake::slurm
