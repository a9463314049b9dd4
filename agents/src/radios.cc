// Radios, the communication graph and the mailbox: small pieces of one idea.
#include <cmath>
#include <queue>
#include <stdexcept>

#include "dream/agents/framework/graph_radio.h"
#include "dream/agents/framework/mailbox.h"
#include "dream/agents/framework/noise_source.h"
#include "dream/agents/framework/number_text.h"
#include "dream/agents/framework/range_radio.h"
#include "dream/agents/framework/role_radio.h"

namespace dream::agents {

RangeRadio::RangeRadio(double range_m) : range_m_(range_m) {
  if (!(range_m > 0.0) || !std::isfinite(range_m)) {
    throw std::invalid_argument("range_m must be > 0, got " + NumberText(range_m));
  }
}

bool RangeRadio::CanHear(int self_id, int sender_id, const WorldSnapshot& world) const {
  if (self_id == sender_id || sender_id < 0 || sender_id >= world.num_robots()) return false;
  const auto a = world.poses[static_cast<size_t>(self_id)].head<2>();
  const auto b = world.poses[static_cast<size_t>(sender_id)].head<2>();
  return (a - b).norm() <= range_m_;
}

CommunicationGraph::CommunicationGraph(Eigen::MatrixXd adjacency, int num_robots, bool require_symmetric,
                                       bool require_connected)
    : adjacency_(std::move(adjacency)) {
  const auto n = adjacency_.rows();
  if (n != num_robots || adjacency_.cols() != num_robots) {
    throw std::invalid_argument("must be " + std::to_string(num_robots) + "x" + std::to_string(num_robots) +
                                " (one row and column per robot), got " + std::to_string(n) + "x" +
                                std::to_string(adjacency_.cols()));
  }
  for (Eigen::Index i = 0; i < n; ++i) {
    for (Eigen::Index j = 0; j < n; ++j) {
      if (!std::isfinite(adjacency_(i, j))) {
        throw std::invalid_argument("entry (" + std::to_string(i) + ", " + std::to_string(j) + ") is not finite");
      }
      if (require_symmetric && adjacency_(i, j) != adjacency_(j, i)) {
        throw std::invalid_argument("must be symmetric, but entry (" + std::to_string(i) + ", " + std::to_string(j) +
                                    ") is " + NumberText(adjacency_(i, j)) + " and (" + std::to_string(j) + ", " +
                                    std::to_string(i) + ") is " + NumberText(adjacency_(j, i)));
      }
    }
    if (adjacency_(i, i) != 0.0) {
      throw std::invalid_argument("diagonal entry (" + std::to_string(i) + ", " + std::to_string(i) +
                                  ") must be 0: a robot does not link to itself");
    }
  }
  if (require_connected && n > 0) {
    std::vector<bool> reached(static_cast<size_t>(n), false);
    std::queue<Eigen::Index> frontier;
    frontier.push(0);
    reached[0] = true;
    while (!frontier.empty()) {
      const Eigen::Index i = frontier.front();
      frontier.pop();
      for (Eigen::Index j = 0; j < n; ++j) {
        if ((adjacency_(i, j) != 0.0 || adjacency_(j, i) != 0.0) && !reached[static_cast<size_t>(j)]) {
          reached[static_cast<size_t>(j)] = true;
          frontier.push(j);
        }
      }
    }
    for (Eigen::Index i = 0; i < n; ++i) {
      if (!reached[static_cast<size_t>(i)]) {
        throw std::invalid_argument("the graph is not connected: robot " + std::to_string(i) +
                                    " cannot be reached from robot 0, so consensus cannot include it");
      }
    }
  }
}

GraphRadio::GraphRadio(CommunicationGraph graph) : graph_(std::move(graph)) {}

bool GraphRadio::CanHear(int self_id, int sender_id, const WorldSnapshot& world) const {
  (void)world;
  if (self_id == sender_id || sender_id < 0 || sender_id >= graph_.size() || self_id >= graph_.size()) return false;
  return graph_.Linked(sender_id, self_id);
}

RoleRadio::RoleRadio(Role role, CommunicationGraph graph) : role_(role), graph_(std::move(graph)) {}

bool RoleRadio::CanHear(int self_id, int sender_id, const WorldSnapshot& world) const {
  (void)world;
  if (role_ == Role::kLeader) return false;
  if (self_id == sender_id || sender_id < 0 || sender_id >= graph_.size() || self_id >= graph_.size()) return false;
  return graph_.Linked(sender_id, self_id);
}

bool RadioLinkParams::IsValid(std::string* error) const {
  if (!(loss_probability >= 0.0 && loss_probability < 1.0)) {
    if (error != nullptr) *error = "loss_probability must be in [0, 1), got " + NumberText(loss_probability);
    return false;
  }
  if (delay_steps < 0) {
    if (error != nullptr) *error = "delay_steps must be >= 0, got " + std::to_string(delay_steps);
    return false;
  }
  return true;
}

Mailbox::Mailbox(const RadioLinkParams& params, uint64_t seed) : params_(params), seed_(seed) {
  std::string error;
  if (!params_.IsValid(&error)) throw std::invalid_argument(error);
}

void Mailbox::Post(RadioMessage message) {
  if (params_.loss_probability > 0.0) {
    const uint64_t draw =
        NoiseSource::MixSeed(seed_, static_cast<uint64_t>(message.sender_id), static_cast<uint64_t>(message.sent_step));
    if (static_cast<double>(draw >> 11) * 0x1.0p-53 < params_.loss_probability) {
      ++lost_;
      return;
    }
  }
  auto& messages = by_sender_[message.sender_id];
  messages[message.sent_step] = std::move(message);
  // Keep what a delay could still need, plus the newest audible one.
  while (messages.size() > static_cast<size_t>(params_.delay_steps) + 2) messages.erase(messages.begin());
}

std::vector<RadioMessage> Mailbox::Heard(const Radio& radio, int self_id, const WorldSnapshot& world) const {
  std::vector<RadioMessage> heard;
  if (!radio.receives()) return heard;
  const int64_t newest_audible = world.step - 1 - params_.delay_steps;
  for (const auto& [sender, messages] : by_sender_) {
    if (!radio.CanHear(self_id, sender, world)) continue;
    auto it = messages.upper_bound(newest_audible);
    if (it == messages.begin()) continue;
    heard.push_back(std::prev(it)->second);
  }
  return heard;
}

}  // namespace dream::agents
