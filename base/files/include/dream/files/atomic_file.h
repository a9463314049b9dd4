#pragma once

#include <string>

namespace dream::files {

/// Writes `content` to `path` atomically: a temporary file in the same folder,
/// synced, then renamed over `path`. Readers see the old file or the new one,
/// never half of it. @throws std::runtime_error naming the path on failure.
void WriteFileAtomically(const std::string& path, const std::string& content);

}  // namespace dream::files
