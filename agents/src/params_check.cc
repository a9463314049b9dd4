#include "dream/agents/framework/params_check.h"

#include <cmath>

#include "dream/agents/framework/number_text.h"

namespace dream::agents {

bool FailParams(std::string* error, const std::string& message) {
  if (error != nullptr) *error = message;
  return false;
}

bool CheckPositive(std::string* error, const std::string& name, double value) {
  if (std::isfinite(value) && value > 0.0) return true;
  return FailParams(error, name + " must be > 0, got " + NumberText(value));
}

bool CheckNonNegative(std::string* error, const std::string& name, double value) {
  if (std::isfinite(value) && value >= 0.0) return true;
  return FailParams(error, name + " must be >= 0, got " + NumberText(value));
}

bool CheckAtLeast(std::string* error, const std::string& name, int value, int minimum) {
  if (value >= minimum) return true;
  return FailParams(error, name + " must be >= " + std::to_string(minimum) + ", got " + std::to_string(value));
}

bool CheckMaxSpeed(std::string* error, double max_speed_mps) {
  if (max_speed_mps > 0.0 && max_speed_mps <= 0.2) return true;
  return FailParams(error, "max_speed_mps must be in (0, 0.2], got " + NumberText(max_speed_mps));
}

}  // namespace dream::agents
