#include "dream/agent_host/hrvo_config.h"

#include "dream/agent_host/field_reader.h"

namespace dream::agent_host {

agents::HrvoRobotParams ReadHrvoRobotParams(const config::ConfigNode& section, agents::HrvoRobotParams defaults) {
  agents::HrvoRobotParams params = defaults;
  FieldReader(section, 0).Section("hrvo", params, "");
  std::string error;
  if (!params.IsValid(&error)) section.Required("hrvo").FailAtField(error);
  return params;
}

}  // namespace dream::agent_host
