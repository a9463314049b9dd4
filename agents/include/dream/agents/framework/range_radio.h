#pragma once

#include "dream/agents/framework/radio.h"

namespace dream::agents {

/// Hears every robot within `range_m` (centre to centre) at the current step.
class RangeRadio final : public Radio {
 public:
  /// @throws std::invalid_argument unless range_m > 0.
  explicit RangeRadio(double range_m);
  bool CanHear(int self_id, int sender_id, const WorldSnapshot& world) const override;

 private:
  double range_m_;
};

}  // namespace dream::agents
