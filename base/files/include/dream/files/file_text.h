#pragma once

#include <string>

namespace dream::files {

/// The whole content of the file at `path`.
/// @throws std::runtime_error naming the path when it cannot be read.
std::string ReadFileText(const std::string& path);

}  // namespace dream::files
