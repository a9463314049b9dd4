#include "dream/hrvo_circle/kind.h"

#include "dream/hrvo_circle/hrvo_circle_builder.h"

namespace dream::hrvo_circle {

kind_api::ControllerKind Kind() { return kind_api::ControllerKind::Of<HrvoCircleBuilder>(); }

}  // namespace dream::hrvo_circle
