#pragma once

#include <string>

namespace dream::workflows {

/// Writes `content` to `path` through a temporary file renamed over it, so a
/// reader sees the old file or the new one, never half of one; unlike
/// sim::WriteFileAtomically it does not sync each file (a sweep writes
/// thousands; SyncFolder syncs them at once). @throws std::runtime_error.
void ReplaceFile(const std::string& path, const std::string& content);

/// Flushes the file system holding `dir` to disk (syncfs); errors ignored.
void SyncFolder(const std::string& dir);

/// The file's first `max_bytes` (all of a small file); empty when unreadable.
std::string ReadFileHead(const std::string& path, size_t max_bytes);
/// The file's last `max_bytes`; empty when unreadable.
std::string ReadFileTail(const std::string& path, size_t max_bytes);

}  // namespace dream::workflows
