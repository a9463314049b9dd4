#include "dream/world/barrier_world.h"

#include <stdexcept>
#include <string>

#include "barrier_input.h"

namespace dream::world {

BarrierWorld::BarrierWorld(std::unique_ptr<World> inner, const barriers::UnicycleBarrierParams& params)
    : inner_(std::move(inner)), barrier_(params) {
  if (inner_ == nullptr) throw std::invalid_argument("BarrierWorld: no world to wrap");
  const size_t n = static_cast<size_t>(inner_->num_robots());
  wanted_.assign(n, UnicycleCommand{});
  commanded_.assign(n, false);
}

void BarrierWorld::SetCommand(int robot_id, const UnicycleCommand& command) {
  inner_->SetCommand(robot_id, command);  // checks the id and the numbers
  wanted_[static_cast<size_t>(robot_id)] = command;
  commanded_[static_cast<size_t>(robot_id)] = true;
}

void BarrierWorld::StopRobot(int robot_id) {
  inner_->StopRobot(robot_id);
  wanted_[static_cast<size_t>(robot_id)] = UnicycleCommand{};
  commanded_[static_cast<size_t>(robot_id)] = false;
}

void BarrierWorld::Step() {
  const int n = num_robots();
  if (n == 0) {
    inner_->Step();
    return;
  }
  FillBarrierInput(wanted_, inner_->poses(), &commands_, &pose_matrix_);
  const barriers::BarrierResult safe = barrier_.Apply(commands_, pose_matrix_);
  failed_steps_ += safe.qp_failed;
  steps_changed_ += (safe.commands - commands_).cwiseAbs().maxCoeff() > 1e-9;
  for (int i = 0; i < n; ++i) {
    // A robot without a command stays stopped; the others get the certificate's command.
    if (commanded_[static_cast<size_t>(i)]) {
      inner_->SetCommand(i, UnicycleCommand{safe.commands(0, i), safe.commands(1, i)});
    }
  }
  inner_->Step();
}

const World& SteppingWorldOf(const World& world) {
  const auto* barrier = dynamic_cast<const BarrierWorld*>(&world);
  return barrier != nullptr ? barrier->inner() : world;
}

}  // namespace dream::world
