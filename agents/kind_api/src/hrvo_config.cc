#include "dream/kind_api/hrvo_config.h"

#include "dream/kind_api/field_reader.h"

namespace dream::kind_api {

agents::HrvoRobotParams ReadHrvoRobotParams(const config::ConfigNode& section, agents::HrvoRobotParams defaults) {
  agents::HrvoRobotParams params = defaults;
  FieldReader(section, 0).Section("hrvo", params, "");
  std::string error;
  if (!params.IsValid(&error)) section.Required("hrvo").FailAtField(error);
  return params;
}

}  // namespace dream::kind_api
