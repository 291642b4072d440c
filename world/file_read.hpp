// Reading input files safely: only regular files (a FIFO would block forever, /dev/zero never
// ends, a directory is no file), never more than a stated size, and errors that name the file.
// Every input path of the compiler, the baker, the runtime and the game reads through here.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace onelight::world {

/// Largest input file read whole: glTF JSON, glb, buffers, images, packages, maps, pk3s.
constexpr uint64_t kMaxInputFileBytes = uint64_t(2) << 30;  // 2 GiB

/// The bytes of the regular file `path`, at most `maxBytes`. Throws world::Error naming the
/// file and `expected` (e.g. "a .olpak package") when it is missing, not a regular file, larger
/// than `maxBytes`, or cannot be read.
std::vector<uint8_t> readRegularFile(const std::string& path, const char* expected,
                                     uint64_t maxBytes = kMaxInputFileBytes);

/// Throws as readRegularFile does when `path` is not a readable regular file of at most
/// `maxBytes` (for files a library opens itself, such as a pk3 through libzip).
void requireRegularFile(const std::string& path, const char* expected,
                        uint64_t maxBytes = kMaxInputFileBytes);

/// Whether `a` and `b` name the same existing file (device and inode; a hard or symbolic link
/// counts). False when either does not exist.
bool sameFile(const std::string& a, const std::string& b);

/// Throws world::Error when `output` names the same file as one of `inputs`: a command must
/// never overwrite what it reads. `tool` prefixes nothing; the message names both paths.
void refuseOutputOverInput(const std::string& output, const std::vector<std::string>& inputs);

/// `text` for an error message: at most `maxChars` characters (then "..." and the full length),
/// control characters shown as '?', so that a message stays one short line.
std::string clipForMessage(std::string_view text, size_t maxChars = 80);

/// A message as a command prints it: one line (control characters, a newline among them, shown
/// as '?'), every word (a run without spaces: a path, a token, a name) longer than 128
/// characters shown by its first 32 and last 64 with its length after (an ordinary path stays
/// whole; a 5000-character name keeps its end, where a file's name is), the same text otherwise.
/// The last guard of the one-short-line rule for every command's top-level error.
std::string oneLineMessage(std::string_view message);

}  // namespace onelight::world
