#pragma once

#include <optional>
#include <string>

#include "dream/barriers/boundary_box.h"

namespace dream::barriers {

/// The parameters of rps's `create_si_barrier_certificate` (no boundary) and
/// `create_si_barrier_certificate_with_boundary`; the defaults are rps V2's.
struct SingleIntegratorBarrierParams {
  double safety_radius_m = 0.15;
  double barrier_gain = 100.0;
  double magnitude_limit_mps = 0.2;
  /// None: no wall constraints (`create_si_barrier_certificate`).
  std::optional<BoundaryBox> boundary;

  /// `create_si_barrier_certificate()`'s defaults.
  static SingleIntegratorBarrierParams Rps();
  /// `create_si_barrier_certificate_with_boundary()`'s defaults: its boundary
  /// is [-1.7, 1.7, -1.1, 1.1], 0.1 m beyond the arena, as rps has it.
  static SingleIntegratorBarrierParams RpsWithBoundary();

  /// False with a message naming the parameter and its value.
  bool IsValid(std::string* error) const;
};

}  // namespace dream::barriers
