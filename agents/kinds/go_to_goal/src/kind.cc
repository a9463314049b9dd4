#include "dream/go_to_goal/kind.h"

#include "dream/go_to_goal/go_to_goal_builder.h"

namespace dream::go_to_goal {

kind_api::ControllerKind Kind() { return kind_api::ControllerKind::Of<GoToGoalBuilder>(); }

}  // namespace dream::go_to_goal
