#include "dream/files/atomic_file.h"

#include "dream/files/temporary_file.h"

namespace dream::files {

void WriteFileAtomically(const std::string& path, const std::string& content, Durability durability) {
  TemporaryFile file(path);
  file.Write(content);
  if (durability == Durability::kSynced) file.Sync();
  file.Commit();
}

}  // namespace dream::files
