#pragma once

#include <deque>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "dream/kind_api/controller_kind.h"
#include "dream/config/controller_config.h"

namespace dream::agent_host {

/// The experiment kinds a ControllerFactory can build: the built-in ones and
/// those that controller plugins add (docs/writing-a-controller.md). Safe to
/// use from several threads. No registry is global and changed behind a
/// caller's back: a run's registry is made for its config (ForConfig), and a
/// factory keeps the one it was given.
class ControllerRegistry {
 public:
  /// The built-in kinds, made once and never changed after.
  static const ControllerRegistry& BuiltIns();
  /// A new registry: the built-in kinds, then the kinds of the plugins
  /// `config` names, loaded in order (ControllerPluginLoader).
  /// @throws config::ConfigError "FILE:LINE: plugins[i]: PATH: reason".
  static std::shared_ptr<const ControllerRegistry> ForConfig(const config::ControllerConfig& config);
  /// The kind `config`'s section names, from ForConfig(config) (which it
  /// keeps alive), so a tool asks the kind what it is (where its robots run,
  /// its file) without building its agents; nullptr when the section names no
  /// kind or an unknown one (ControllerFactory says why).
  /// @throws config::ConfigError as ForConfig does.
  static std::shared_ptr<const kind_api::ControllerKind> KindOf(const config::ControllerConfig& config);

  /// An empty registry (a plugin registers into one first, so a plugin that
  /// fails half way adds nothing).
  ControllerRegistry() = default;
  ControllerRegistry(const ControllerRegistry&) = delete;
  ControllerRegistry& operator=(const ControllerRegistry&) = delete;

  /// Adds `kind`; `origin` says where it came from in later error messages.
  /// @throws std::invalid_argument when the name is empty, `make_builder` is
  ///         missing, or a kind of that name is already registered.
  void Add(kind_api::ControllerKind kind, const std::string& origin = "");
  /// Adds every kind of `other`, or none when any name is taken.
  /// @throws std::invalid_argument naming the kind and both origins.
  void AddAll(const ControllerRegistry& other, const std::string& origin);

  /// The kind called `name`, or nullptr. The pointer stays valid for the
  /// registry's lifetime.
  const kind_api::ControllerKind* Find(const std::string& name) const;
  /// Names in registration order.
  std::vector<std::string> Names() const;

 private:
  struct Entry {
    kind_api::ControllerKind kind;
    std::string origin;
  };
  const Entry* FindLocked(const std::string& name) const;

  mutable std::mutex mutex_;
  std::deque<Entry> entries_;  // a deque: Find's pointers survive later additions
};

}  // namespace dream::agent_host
