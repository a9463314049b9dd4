#pragma once

#include <string>

namespace dream::files {

/// Whether WriteFileAtomically syncs the file before the rename. kSynced: the
/// file is whole after a power cut (summaries, realism files, exports).
/// kRenamedOnly: a reader still never sees half of it, but a crash may lose
/// it; for files written by the thousand (a sweep's configs and exit records)
/// whose loss only makes a run one that resume redoes.
enum class Durability { kSynced, kRenamedOnly };

/// Writes `content` to `path` atomically: a new temporary file beside it,
/// created exclusively under an unguessable name (files::TemporaryFile: a link
/// planted in a shared folder is never written through), then renamed over
/// `path`. Readers see the old file or the new one, never half of it.
/// @throws std::runtime_error naming the path on failure.
void WriteFileAtomically(const std::string& path, const std::string& content,
                         Durability durability = Durability::kSynced);

}  // namespace dream::files
