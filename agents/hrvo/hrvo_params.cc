#include "dream/agents/hrvo/hrvo_params.h"

#include <cmath>
#include <sstream>

namespace dream::agents {
namespace {

bool Fail(std::string* error, const char* field, double value, const char* range) {
  if (error != nullptr) {
    std::ostringstream out;
    out << "HrvoParams." << field << " = " << value << " is outside " << range;
    *error = out.str();
  }
  return false;
}

bool InRange(double value, double lo_exclusive, double hi_inclusive) {
  return std::isfinite(value) && value > lo_exclusive && value <= hi_inclusive;
}

}  // namespace

bool HrvoParams::IsValid(std::string* error) const {
  if (!InRange(safety_radius_m, 0.0, 10.0)) return Fail(error, "safety_radius_m", safety_radius_m, "(0, 10] m");
  if (!InRange(max_speed_mps, 0.0, 10.0)) return Fail(error, "max_speed_mps", max_speed_mps, "(0, 10] m/s");
  if (!std::isfinite(x_min_m)) return Fail(error, "x_min_m", x_min_m, "finite values");
  if (!std::isfinite(x_max_m) || !(x_max_m > x_min_m)) return Fail(error, "x_max_m", x_max_m, "(x_min_m, inf) m");
  if (!std::isfinite(y_min_m)) return Fail(error, "y_min_m", y_min_m, "finite values");
  if (!std::isfinite(y_max_m) || !(y_max_m > y_min_m)) return Fail(error, "y_max_m", y_max_m, "(y_min_m, inf) m");
  if (!InRange(boundary_horizon_s, 0.0, 100.0)) {
    return Fail(error, "boundary_horizon_s", boundary_horizon_s, "(0, 100] s");
  }
  return true;
}

}  // namespace dream::agents
