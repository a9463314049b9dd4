#include "dream/run_config/barrier_config.h"

#include <optional>
#include <string>
#include <vector>

namespace dream::run_config {

// `barriers:` (config/README.md#barriers). Each key's default is rps's for the
// kind; a key the kind does not take, or a key with kind none, is a mistake.
BarrierConfig BarrierConfig::Read(const config::ConfigNode& root) {
  BarrierConfig barriers;
  const config::ConfigNode node = root.Optional("barriers");
  if (!node.IsDefined()) return barriers;
  if (!node.IsMap()) node.Fail("must be a map (kind, apply_in, safety_radius_m, ...), got '" + node.AsString() + "'");
  node.RejectUnknownKeys({"kind", "apply_in", "safety_radius_m", "barrier_gain", "projection_distance_m",
                          "magnitude_limit_mps", "boundary_m"});
  using Kind = BarrierConfig::Kind;
  using ApplyIn = BarrierConfig::ApplyIn;
  barriers.kind = node.GetChoice<Kind>(
      "kind", "none", "barrier kind",
      {{"none", Kind::kNone}, {"unicycle", Kind::kUnicycle}, {"single_integrator", Kind::kSingleIntegrator}});
  barriers.apply_in = node.GetChoice<ApplyIn>("apply_in", "world", "place to apply barriers",
                                              {{"world", ApplyIn::kWorld}, {"controller", ApplyIn::kController}});
  if (barriers.kind == Kind::kNone) {
    for (const std::string& key : node.Keys()) {
      if (key != "kind") {
        node.FailAt(key,
                    "barriers with kind none (the default) take no other key; set kind: unicycle or "
                    "single_integrator, or remove it");
      }
    }
    return barriers;
  }
  if (barriers.kind == Kind::kSingleIntegrator) {
    if (barriers.apply_in == ApplyIn::kWorld) {
      node.FailAt("apply_in",
                  "the world drives unicycles (v, w): a single-integrator certificate filters a "
                  "controller's single-integrator velocities, so it needs apply_in: controller; in "
                  "the world use kind: unicycle");
    }
    if (node.Has("projection_distance_m")) {
      node.FailAt("projection_distance_m", "only kind unicycle projects a point ahead of the robot");
    }
  }
  const bool unicycle = barriers.kind == Kind::kUnicycle;
  double radius = unicycle ? barriers.unicycle.safety_radius_m : barriers.single_integrator.safety_radius_m;
  double gain = unicycle ? barriers.unicycle.barrier_gain : barriers.single_integrator.barrier_gain;
  double limit = unicycle ? barriers.unicycle.magnitude_limit_mps : barriers.single_integrator.magnitude_limit_mps;
  std::optional<barriers::BoundaryBox> boundary =
      unicycle ? barriers.unicycle.boundary : barriers.single_integrator.boundary;
  auto positive = [&node](const char* key, double fallback) {
    const double value = node.GetDouble(key, fallback);
    if (!(value > 0.0)) node.FailAt(key, "must be > 0, got " + node.Required(key).AsString());
    return value;
  };
  radius = positive("safety_radius_m", radius);
  gain = positive("barrier_gain", gain);
  limit = positive("magnitude_limit_mps", limit);
  if (node.Has("boundary_m")) {
    const config::ConfigNode b = node.Required("boundary_m");
    if (!b.IsSequence() && b.AsString() == "none") {
      boundary.reset();
    } else {
      const std::vector<double> v = b.AsDoubles();
      if (v.size() != 4 || !(v[0] < v[1] && v[2] < v[3])) {
        b.Fail("must be [x_min, x_max, y_min, y_max] with x_min < x_max and y_min < y_max (metres), or none");
      }
      boundary = barriers::BoundaryBox{v[0], v[1], v[2], v[3]};
    }
  }
  if (unicycle) {
    barriers.unicycle.safety_radius_m = radius;
    barriers.unicycle.barrier_gain = gain;
    barriers.unicycle.magnitude_limit_mps = limit;
    barriers.unicycle.projection_distance_m =
        positive("projection_distance_m", barriers.unicycle.projection_distance_m);
    barriers.unicycle.boundary = boundary;
  } else {
    barriers.single_integrator.safety_radius_m = radius;
    barriers.single_integrator.barrier_gain = gain;
    barriers.single_integrator.magnitude_limit_mps = limit;
    barriers.single_integrator.boundary = boundary;
  }
  return barriers;
}

const char* BarrierConfig::KindName(Kind kind) {
  switch (kind) {
    case Kind::kUnicycle:
      return "unicycle";
    case Kind::kSingleIntegrator:
      return "single_integrator";
    case Kind::kNone:
      break;
  }
  return "none";
}

const char* BarrierConfig::ApplyInName(ApplyIn apply_in) {
  return apply_in == ApplyIn::kController ? "controller" : "world";
}

}  // namespace dream::run_config
