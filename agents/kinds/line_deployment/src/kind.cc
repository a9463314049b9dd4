#include "dream/line_deployment/kind.h"

#include "dream/line_deployment/line_deployment_builder.h"

namespace dream::line_deployment {

kind_api::ControllerKind Kind() { return kind_api::ControllerKind::Of<LineDeploymentBuilder>(); }

}  // namespace dream::line_deployment
