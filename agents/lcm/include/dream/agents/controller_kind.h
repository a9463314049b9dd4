#pragma once

#include <functional>
#include <memory>
#include <string>
#include <type_traits>
#include <vector>

#include "dream/agents/agent_parts_config.h"
#include "dream/agents/experiment_builder.h"
#include "dream/config/config_node.h"

namespace dream::agents {

/// What one experiment kind (`controller: {kind: NAME}`) brings to the
/// ControllerFactory: its own config keys, the parts its robots get unless the
/// config says otherwise, and how to build its ExperimentBuilder.
struct ControllerKind {
  std::string name;
  /// Keys of the `controller:` section besides the common kind, robot, sensors, radio.
  std::vector<std::string> keys;
  std::function<AgentPartsConfig(int num_robots)> default_parts = AgentPartsConfig::Defaults;
  /// Graph radios must form a connected, symmetric graph (consensus laws need it).
  bool graph_must_connect = false;
  std::function<std::unique_ptr<ExperimentBuilder>(const config::ConfigNode& section, int num_robots)> make_builder;

  /// The kind of `Builder`, read from its static members: `kKind` (the name),
  /// `Keys()` (its own keys) and, when it has them, `DefaultParts(int)` and
  /// `kGraphMustConnect`; it is built with `Builder(section, num_robots)`.
  template <typename Builder>
  static ControllerKind Of();

 private:
  template <typename B, typename = void>
  struct HasDefaultParts : std::false_type {};
  template <typename B>
  struct HasDefaultParts<B, std::void_t<decltype(B::DefaultParts(0))>> : std::true_type {};
  template <typename B, typename = void>
  struct HasGraphMustConnect : std::false_type {};
  template <typename B>
  struct HasGraphMustConnect<B, std::void_t<decltype(B::kGraphMustConnect)>> : std::true_type {};
};

template <typename Builder>
ControllerKind ControllerKind::Of() {
  static_assert(std::is_base_of_v<ExperimentBuilder, Builder>, "a controller kind's builder is an ExperimentBuilder");
  ControllerKind kind;
  kind.name = Builder::kKind;
  for (const auto& key : Builder::Keys()) kind.keys.emplace_back(key);
  if constexpr (HasDefaultParts<Builder>::value) kind.default_parts = [](int n) { return Builder::DefaultParts(n); };
  if constexpr (HasGraphMustConnect<Builder>::value) kind.graph_must_connect = Builder::kGraphMustConnect;
  kind.make_builder = [](const config::ConfigNode& section, int num_robots) -> std::unique_ptr<ExperimentBuilder> {
    return std::make_unique<Builder>(section, num_robots);
  };
  return kind;
}

}  // namespace dream::agents
