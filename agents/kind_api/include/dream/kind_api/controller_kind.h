#pragma once

#include <Eigen/Core>
#include <functional>
#include <memory>
#include <nlohmann/json_fwd.hpp>
#include <string>
#include <type_traits>
#include <vector>

#include "dream/kind_api/agent_parts_config.h"
#include "dream/kind_api/experiment_builder.h"
#include "dream/kind_api/own_step_metrics.h"
#include "dream/kind_api/robot_class_builder.h"
#include "dream/kind_api/run_poses.h"
#include "dream/agents/fields/field_table.h"
#include "dream/config/config_node.h"
#include "dream/config/controller_config.h"

namespace dream::kind_api {

/// What one experiment kind (`controller: {kind: NAME}`) brings to the
/// ControllerFactory: its own config keys, the parts its robots get unless the
/// config says otherwise, how to build its ExperimentBuilder, and where its
/// robots run. Made from a Robot subclass alone (OfRobot) or from an
/// ExperimentBuilder (Of). The tools ask a run's kind these things (through
/// the registry), never its name.
struct ControllerKind {
  /// Where a kind's robots run.
  enum class Runtime {
    /// C++ agents::Robots from the kind's ExperimentBuilder, hosted by an
    /// agent_host::AgentHost; a Robotarium submission can only replay them.
    kCpp,
    /// The Python runtime (python/dream/), built there from `runtime_spec`:
    /// in a process of its own on the bus (dream::python_host), or shipped in a
    /// Robotarium submission (the export's controller strategy); the run's own
    /// metrics and goal come from that runtime too (own_metrics, goals_before_run).
    kPython,
  };

  std::string name;
  /// Keys of the `controller:` section besides the common kind, robot, sensors, radio.
  std::vector<std::string> keys;
  std::function<AgentPartsConfig(int num_robots)> default_parts = AgentPartsConfig::Defaults;
  /// Graph radios must form a connected, symmetric graph (consensus laws need it).
  bool graph_must_connect = false;
  /// The kind checks the section's other keys itself, so the factory does not
  /// refuse them (the `python` kind: the Python class declares its keys).
  bool checks_own_keys = false;
  std::function<std::unique_ptr<ExperimentBuilder>(const config::ConfigNode& section, int num_robots)> make_builder;
  Runtime runtime = Runtime::kCpp;
  /// For Runtime::kPython: the controller spec the runtime builds every robot
  /// from, as JSON (docs/python-runtime-contract.md), for a run's config.
  /// @throws config::ConfigError as the factory does.
  std::function<std::string(const config::ControllerConfig& config)> runtime_spec;
  /// The key of the section naming the kind's own file by a path that a run
  /// folder, an export, an import and a sweep keep beside their copy of the
  /// config (the python kind's `module`: config::FileBesideConfig); empty: none.
  std::string file_key;
  /// The kind's rows of the key table in config/README.md (`| key | default | meaning |`), made
  /// from the builder's field list when it has one (`Builder::Section`); empty otherwise.
  std::function<std::string()> key_table;
  /// The kind's own metrics of a finished run, besides its builder's
  /// ExperimentMetrics (the python kind: its class's metrics(), goal() and
  /// goal_points(), computed in the Python runtime), as the document
  /// {"metrics": {name: value}, "goal": {"met", "completion_step", "detail"}
  /// or null, "goal_points": [[[x, y], ...] per robot]}: the tools add its
  /// goal, its goal points and the figures no other metric already names to
  /// summary.json's metrics. `runtime_dir`: the folder of the runtime the
  /// kind's robots run in (the Python runtime, process::DataFiles), never
  /// empty (a caller without one asks for no own metrics). Empty: none.
  /// @throws std::runtime_error naming what failed (a module's file and line).
  std::function<nlohmann::json(const config::ControllerConfig& config, const RunPoses& poses,
                               const std::string& runtime_dir)>
      own_metrics;
  /// The same figures followed step by step while a run runs (the view's
  /// plots): after the last step, once computed, own_metrics' "metrics" for
  /// those steps (each series' last value). `runtime_dir` as for own_metrics.
  /// Empty: none (a kind whose own metrics only a finished run has).
  /// @throws std::runtime_error naming what failed to start.
  std::function<std::unique_ptr<OwnStepMetrics>(const config::ControllerConfig& config, const std::string& runtime_dir)>
      own_step_metrics;
  /// The points each robot should reach, known from the config before a run,
  /// for a kind whose builder draws none (ExperimentBuilder::GoalsToDraw):
  /// what pictures and the view draw (the python kind: its class's
  /// goal_points()). `runtime_dir` as for own_metrics. Empty: none.
  /// @throws std::runtime_error naming what failed.
  std::function<std::vector<std::vector<Eigen::Vector2d>>(const config::ControllerConfig& config,
                                                          const std::string& runtime_dir)>
      goals_before_run;

  /// The kind of `Builder`, read from its static members: `kKind` (the name),
  /// `Keys()` (its own keys) and, when it has them, `DefaultParts(int)` and
  /// `kGraphMustConnect`; it is built with `Builder(section, num_robots)`.
  template <typename Builder>
  static ControllerKind Of();

  /// The kind `name` whose robots are `RobotClass`, built by
  /// RobotClassBuilder (see there for the constructors it takes), with no
  /// metrics of its own. `keys` are the robot's own keys of the section
  /// (any other key is an error naming file, line and key). Like Of(), it
  /// reads `DefaultParts(int)` and `kGraphMustConnect` from RobotClass when
  /// it has them.
  ///     registry.Add(ControllerKind::OfRobot<OrbitRobot>("orbit", {"radius_m", "speed_mps"}));
  template <typename RobotClass>
  static ControllerKind OfRobot(std::string name, std::vector<std::string> keys);

 private:
  // Copies the optional static members of `T` (a builder or a robot class).
  template <typename T>
  static void ReadOptionalMembers(ControllerKind* kind);

  template <typename B, typename = void>
  struct HasDefaultParts : std::false_type {};
  template <typename B>
  struct HasDefaultParts<B, std::void_t<decltype(B::DefaultParts(0))>> : std::true_type {};
  template <typename B, typename = void>
  struct HasSection : std::false_type {};
  template <typename B>
  struct HasSection<B, std::void_t<typename B::Section>> : std::true_type {};
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
  ReadOptionalMembers<Builder>(&kind);
  kind.make_builder = [](const config::ConfigNode& section, int num_robots) -> std::unique_ptr<ExperimentBuilder> {
    return std::make_unique<Builder>(section, num_robots);
  };
  if constexpr (HasSection<Builder>::value)
    kind.key_table = [] { return agents::KeyTableOf<typename Builder::Section>(); };
  return kind;
}

template <typename RobotClass>
ControllerKind ControllerKind::OfRobot(std::string name, std::vector<std::string> keys) {
  ControllerKind kind;
  kind.name = std::move(name);
  kind.keys = std::move(keys);
  ReadOptionalMembers<RobotClass>(&kind);
  kind.make_builder = [](const config::ConfigNode& section, int num_robots) -> std::unique_ptr<ExperimentBuilder> {
    return std::make_unique<RobotClassBuilder<RobotClass>>(section, num_robots);
  };
  return kind;
}

template <typename T>
void ControllerKind::ReadOptionalMembers(ControllerKind* kind) {
  if constexpr (HasDefaultParts<T>::value) kind->default_parts = [](int n) { return T::DefaultParts(n); };
  if constexpr (HasGraphMustConnect<T>::value) kind->graph_must_connect = T::kGraphMustConnect;
}

}  // namespace dream::kind_api
