#pragma once

#include <string>

namespace dream::workflows {

/// Writes `content` to `path` through a temporary file renamed over it, so a
/// reader sees the old file or the new one, never half of one; unlike
/// files::WriteFileAtomically (Durability::kSynced) it does not sync the file to disk: a sweep
/// writes thousands (configs, exit records), and a file lost to a crash
/// makes its run one that resume redoes. The temporary file is made
/// exclusively beside `path` under an unguessable name (files::TemporaryFile:
/// a new file, never one planted there, nor a link followed). @throws std::runtime_error.
void ReplaceFile(const std::string& path, const std::string& content);

/// The file's last `max_bytes`; empty when missing, unreadable or not a regular
/// file (a FIFO is never waited on).
std::string ReadFileTail(const std::string& path, size_t max_bytes);

}  // namespace dream::workflows
