#include "dream/agent_host/hrvo_config.h"

#include "dream/config/name_suggestion.h"

namespace dream::agent_host {

agents::HrvoRobotParams ReadHrvoRobotParams(const config::ConfigNode& section, agents::HrvoRobotParams defaults) {
  agents::HrvoRobotParams params = defaults;
  const config::ConfigNode node = section.Optional("hrvo");
  if (!node.IsDefined()) return params;
  node.RejectUnknownKeys({"variant", "safety_radius_m", "check_boundaries", "boundary_horizon_s"});
  if (node.Has("variant")) {
    const std::string variant = node.Required("variant").AsString();
    if (variant == "exact") {
      params.variant = agents::HrvoVariant::kExact;
    } else if (variant == "thesis") {
      params.variant = agents::HrvoVariant::kThesis;
    } else {
      node.Required("variant").Fail("unknown HRVO variant '" + variant + "'" +
                                    config::DidYouMean(variant, {"exact", "thesis"}) + "; allowed: exact, thesis");
    }
  }
  params.hrvo.safety_radius_m = node.GetDouble("safety_radius_m", params.hrvo.safety_radius_m);
  params.hrvo.check_boundaries = node.GetBool("check_boundaries", params.hrvo.check_boundaries);
  params.hrvo.boundary_horizon_s = node.GetDouble("boundary_horizon_s", params.hrvo.boundary_horizon_s);
  std::string error;
  if (!params.IsValid(&error)) node.FailAtField(error);
  return params;
}

}  // namespace dream::agent_host
