#pragma once

#include <cmath>
#include <limits>
#include <string>

#include "dream/agents/framework/number_text.h"
#include "dream/robotarium/robotarium_constants.h"

namespace dream::agents {

/// Which numbers a config key takes, said once: checked when a config is read
/// and when params are built, and written into the error ("must be > 0") and
/// the key table of the docs ("> 0").
class FieldRule {
 public:
  /// Any finite number.
  static FieldRule Finite() { return FieldRule(Bound::kNone, 0.0, Bound::kNone, 0.0); }
  /// Finite and > 0.
  static FieldRule Positive() { return FieldRule(Bound::kOpen, 0.0, Bound::kNone, 0.0); }
  /// > 0, infinity included (a distance that means "always").
  static FieldRule PositiveOrInfinite() {
    FieldRule rule(Bound::kOpen, 0.0, Bound::kNone, 0.0);
    rule.infinite_ok_ = true;
    return rule;
  }
  /// Finite and >= 0.
  static FieldRule NonNegative() { return FieldRule(Bound::kClosed, 0.0, Bound::kNone, 0.0); }
  /// >= `low`.
  static FieldRule AtLeast(double low) { return FieldRule(Bound::kClosed, low, Bound::kNone, 0.0); }
  /// In [low, high].
  static FieldRule Within(double low, double high) { return FieldRule(Bound::kClosed, low, Bound::kClosed, high); }
  /// In (low, high].
  static FieldRule AboveUpTo(double low, double high) { return FieldRule(Bound::kOpen, low, Bound::kClosed, high); }
  /// A speed the Robotarium's robots can drive: in (0, 0.2] m/s.
  static FieldRule RobotSpeed() { return AboveUpTo(0.0, robotarium::RobotariumConstants::kMaxLinearVelocityMps); }
  /// In [low, high).
  static FieldRule FromBelow(double low, double high) { return FieldRule(Bound::kClosed, low, Bound::kOpen, high); }

  /// False for Finite(): a rule the docs need not spell out.
  bool bounded() const { return low_ != Bound::kNone || high_ != Bound::kNone; }

  bool Holds(double value) const {
    if (std::isnan(value) || (!std::isfinite(value) && !(infinite_ok_ && value > 0.0))) return false;
    if (low_ == Bound::kOpen && !(value > low_value_)) return false;
    if (low_ == Bound::kClosed && !(value >= low_value_)) return false;
    if (high_ == Bound::kOpen && !(value < high_value_)) return false;
    if (high_ == Bound::kClosed && !(value <= high_value_)) return false;
    return true;
  }

  /// "> 0", ">= 1", "in (0, 0.2]", "finite": what the docs' tables and the errors say.
  std::string Text(bool whole = false) const {
    const auto number = [whole](double v) { return whole ? std::to_string(static_cast<long long>(v)) : NumberText(v); };
    if (low_ == Bound::kNone && high_ == Bound::kNone) return "finite";
    if (high_ == Bound::kNone) {
      return (low_ == Bound::kOpen ? "> " : ">= ") + number(low_value_) + (infinite_ok_ ? " (.inf allowed)" : "");
    }
    if (whole && low_ == Bound::kClosed && high_ == Bound::kClosed)
      return "in " + number(low_value_) + ".." + number(high_value_);
    return std::string("in ") + (low_ == Bound::kOpen ? "(" : "[") + number(low_value_) + ", " + number(high_value_) +
           (high_ == Bound::kOpen ? ")" : "]");
  }

 private:
  enum class Bound { kNone, kOpen, kClosed };
  FieldRule(Bound low, double low_value, Bound high, double high_value)
      : low_(low), high_(high), low_value_(low_value), high_value_(high_value) {}

  Bound low_, high_;
  bool infinite_ok_ = false;
  double low_value_, high_value_;
};

}  // namespace dream::agents
