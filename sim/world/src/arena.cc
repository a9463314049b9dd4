#include "dream/world/arena.h"

#include <cmath>

#include "field_check.h"

namespace dream::world {

using field_check::Fail;

bool Arena::IsValid(std::string* error) const {
  if (!std::isfinite(x_min_m)) return Fail(error, "arena.x_min_m", x_min_m, "a finite number of metres");
  if (!std::isfinite(y_min_m)) return Fail(error, "arena.y_min_m", y_min_m, "a finite number of metres");
  if (!std::isfinite(x_max_m) || x_max_m <= x_min_m) {
    return Fail(error, "arena.x_max_m", x_max_m,
                "finite and > arena.x_min_m (" + field_check::FormatValue(x_min_m) + ") m");
  }
  if (!std::isfinite(y_max_m) || y_max_m <= y_min_m) {
    return Fail(error, "arena.y_max_m", y_max_m,
                "finite and > arena.y_min_m (" + field_check::FormatValue(y_min_m) + ") m");
  }
  return true;
}

}  // namespace dream::world
