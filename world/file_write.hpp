// Writing output files whole or not at all: the one atomic write of the project. Every output
// (packages, captures, images, glTF fixtures, reports, scripts) is written to a temporary file
// beside its path and renamed over it as the last step, so a reader never sees half a file and
// a failure leaves neither the target nor the temporary behind.
#pragma once

#include <cstdint>
#include <functional>
#include <span>
#include <string>
#include <string_view>

namespace onelight::world {

/// Writes `bytes` to `path` through a temporary file in the same folder (`path.tmp.PID.N`,
/// unique to this process and call, so two writers of one path never share a temporary) and a
/// rename over `path`, which is replaced whole. Makes `path`'s folder when it is missing. On any
/// failure removes the temporary and throws world::Error naming `path` and the reason (the
/// system's message); `path` is then as it was.
/// Makes the folder `folder` and its parents unless it is one already. Throws world::Error naming
/// it and `from` (where the path came from, e.g. "--capture-dir") when it cannot: a file in the
/// way, no permission.
void makeFolder(const std::string& folder, const std::string& from);

void writeFileAtomically(const std::string& path, std::span<const uint8_t> bytes);
void writeFileAtomically(const std::string& path, std::string_view bytes);

/// As writeFileAtomically, for a writer that wants a file name (tinyexr): `write` is called
/// with the temporary path and writes the whole file there, throwing world::Error on failure.
/// The temporary is renamed over `path` when `write` returns; whatever `write` throws is
/// passed on, the temporary removed.
void writeFileAtomicallyWith(const std::string& path,
                             const std::function<void(const std::string& temporary)>& write);

}  // namespace onelight::world
