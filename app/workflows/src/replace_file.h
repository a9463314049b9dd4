#pragma once

#include <string>

namespace dream::workflows {

/// Writes `content` to `path` through a temporary file renamed over it, so a
/// reader sees the old file or the new one, never half of one; unlike
/// files::WriteFileAtomically (Durability::kSynced) it does not sync the file to disk: a sweep
/// writes thousands (configs, exit records), and a file lost to a crash
/// makes its run one that resume redoes. @throws std::runtime_error.
void ReplaceFile(const std::string& path, const std::string& content);

/// The file's first `max_bytes` (all of a small file); empty when unreadable
/// or not a regular file (a FIFO is not waited on).
std::string ReadFileHead(const std::string& path, size_t max_bytes);
/// The file's last `max_bytes`; empty when unreadable.
std::string ReadFileTail(const std::string& path, size_t max_bytes);

}  // namespace dream::workflows
