#pragma once

#include <cstdint>
#include <string>

namespace dream::files {

/// What ReadFileText reads at most unless told otherwise: far above any config,
/// summary.json, manifest or Python module DREAM writes or reads, far below
/// what would exhaust memory when a path names something else.
inline constexpr std::uintmax_t kMaxTextFileBytes = std::uintmax_t{64} << 20;

/// The whole content of the regular file at `path`, of at most `max_bytes`.
/// A FIFO, device or folder is refused rather than waited on or read forever.
/// @throws std::runtime_error naming the path (and the size, when too large)
///         when it cannot be read.
std::string ReadFileText(const std::string& path, std::uintmax_t max_bytes = kMaxTextFileBytes);

}  // namespace dream::files
