#pragma once

#include <string>

namespace dream::testing {

/// The source tree the tests were built from (configs, docs, tests/data), without a trailing '/'.
/// Its path is compiled into source_tree.cc alone: a clone in another folder compiles that one
/// file anew and takes every other test object from ccache (the path would change them all).
std::string SourceDir();

}  // namespace dream::testing
