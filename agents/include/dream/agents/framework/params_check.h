#pragma once

#include <stdexcept>
#include <string>

namespace dream::agents {

// What every params struct's IsValid(std::string* error) does: stop at the
// first bad field, say which and with what value (when the caller asked), and
// answer false. The Check* functions hold the rules many params share, so that
// an IsValid reads as a chain `CheckPositive(...) && CheckMaxSpeed(...) && ...`.

/// Puts `message` in `*error` (when not null) and answers false.
bool FailParams(std::string* error, const std::string& message);

/// `value` finite and > 0, else "<name> must be > 0, got <value>".
bool CheckPositive(std::string* error, const std::string& name, double value);
/// `value` finite and >= 0, else "<name> must be >= 0, got <value>".
bool CheckNonNegative(std::string* error, const std::string& name, double value);
/// `value` >= `minimum`, else "<name> must be >= <minimum>, got <value>".
bool CheckAtLeast(std::string* error, const std::string& name, int value, int minimum);
/// `max_speed_mps` in (0, 0.2], the Robotarium's top speed, else "max_speed_mps must be in (0, 0.2], got <value>".
bool CheckMaxSpeed(std::string* error, double max_speed_mps);
/// min < max on both axes, all finite, else "the arena must be finite with min < max on both axes".
template <typename Vector2>
bool CheckArena(std::string* error, const Vector2& arena_min_m, const Vector2& arena_max_m) {
  if (arena_min_m.allFinite() && arena_max_m.allFinite() && arena_min_m.x() < arena_max_m.x() &&
      arena_min_m.y() < arena_max_m.y()) {
    return true;
  }
  return FailParams(error, "the arena must be finite with min < max on both axes");
}

/// `params` when its IsValid() holds, else std::invalid_argument with IsValid's
/// message: constructors check their params in the member initialiser with it,
/// so that no part is ever built from bad params.
template <typename Params>
const Params& CheckedParams(const Params& params) {
  std::string error;
  if (!params.IsValid(&error)) throw std::invalid_argument(error);
  return params;
}

}  // namespace dream::agents
