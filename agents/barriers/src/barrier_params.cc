#include <cmath>
#include <sstream>

#include "dream/barriers/single_integrator_barrier_params.h"
#include "dream/barriers/unicycle_barrier_params.h"
#include "dream/robotarium/robotarium_constants.h"

namespace dream::barriers {
namespace {

using robotarium::RobotariumConstants;

bool CheckPositive(const char* name, double value, std::string* error) {
  if (std::isfinite(value) && value > 0.0) return true;
  std::ostringstream text;
  text << name << " = " << value << ": must be a positive number";
  if (error != nullptr) *error = text.str();
  return false;
}

bool CheckBoundary(const std::optional<BoundaryBox>& boundary, std::string* error) {
  if (!boundary) return true;
  const BoundaryBox& b = *boundary;
  const bool finite =
      std::isfinite(b.x_min_m) && std::isfinite(b.x_max_m) && std::isfinite(b.y_min_m) && std::isfinite(b.y_max_m);
  if (finite && b.x_min_m < b.x_max_m && b.y_min_m < b.y_max_m) return true;
  std::ostringstream text;
  text << "boundary = [" << b.x_min_m << ", " << b.x_max_m << ", " << b.y_min_m << ", " << b.y_max_m
       << "]: must be finite [x_min, x_max, y_min, y_max] with x_min < x_max and y_min < y_max";
  if (error != nullptr) *error = text.str();
  return false;
}

}  // namespace

SingleIntegratorBarrierParams SingleIntegratorBarrierParams::Rps() { return SingleIntegratorBarrierParams{}; }

SingleIntegratorBarrierParams SingleIntegratorBarrierParams::RpsWithBoundary() {
  SingleIntegratorBarrierParams params;
  params.boundary = BoundaryBox{-1.7, 1.7, -1.1, 1.1};
  return params;
}

bool SingleIntegratorBarrierParams::IsValid(std::string* error) const {
  return CheckPositive("safety_radius_m", safety_radius_m, error) &&
         CheckPositive("barrier_gain", barrier_gain, error) &&
         CheckPositive("magnitude_limit_mps", magnitude_limit_mps, error) && CheckBoundary(boundary, error);
}

UnicycleBarrierParams UnicycleBarrierParams::Rps() {
  UnicycleBarrierParams params;
  params.safety_radius_m = 0.15;
  params.barrier_gain = 100.0;
  params.projection_distance_m = 0.05;
  params.magnitude_limit_mps = 0.2;
  return params;
}

UnicycleBarrierParams UnicycleBarrierParams::RpsWithBoundary() {
  UnicycleBarrierParams params;
  params.boundary = BoundaryBox{RobotariumConstants::kArenaXMinMeters, RobotariumConstants::kArenaXMaxMeters,
                                RobotariumConstants::kArenaYMinMeters, RobotariumConstants::kArenaYMaxMeters};
  return params;
}

bool UnicycleBarrierParams::IsValid(std::string* error) const {
  return CheckPositive("safety_radius_m", safety_radius_m, error) &&
         CheckPositive("barrier_gain", barrier_gain, error) &&
         CheckPositive("projection_distance_m", projection_distance_m, error) &&
         CheckPositive("magnitude_limit_mps", magnitude_limit_mps, error) && CheckBoundary(boundary, error);
}

}  // namespace dream::barriers
