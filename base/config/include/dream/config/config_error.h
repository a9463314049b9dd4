#pragma once

#include <stdexcept>
#include <string>

namespace dream::config {

/// A configuration mistake. what() reads "FILE:LINE: KEY: problem", so the
/// user can jump straight to it.
class ConfigError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace dream::config
