#include "source_tree.h"

namespace dream::testing {

std::string SourceDir() { return DREAM_SOURCE_DIR; }

}  // namespace dream::testing
