#pragma once

#include <optional>
#include <string>

#include "dream/barriers/boundary_box.h"

namespace dream::barriers {

/// The parameters of rps's `create_uni_barrier_certificate` (no boundary; the
/// one `Robotarium.initialize()` drives the robots onto their start poses
/// with) and `create_uni_barrier_certificate_with_boundary` (the one the
/// examples and most scripts use); the defaults are rps V2's.
struct UnicycleBarrierParams {
  double safety_radius_m = 0.12;
  double barrier_gain = 150.0;
  /// The point ahead of each robot the single-integrator barrier keeps apart.
  double projection_distance_m = 0.03;
  double magnitude_limit_mps = 0.2;
  /// None: no wall constraints (`create_uni_barrier_certificate`).
  std::optional<BoundaryBox> boundary;

  /// `create_uni_barrier_certificate()`: radius 0.15, gain 100, projection 0.05, limit 0.2.
  static UnicycleBarrierParams Rps();
  /// `create_uni_barrier_certificate_with_boundary()`: radius 0.12, gain 150,
  /// projection 0.03, limit 0.2, the arena [-1.6, 1.6, -1.0, 1.0].
  static UnicycleBarrierParams RpsWithBoundary();

  /// False with a message naming the parameter and its value.
  bool IsValid(std::string* error) const;
};

}  // namespace dream::barriers
