#include "dream/agent_host/controller_registry.h"

#include <stdexcept>

#include "built_in_kinds.h"
#include "dream/agent_host/controller_plugin_loader.h"

namespace dream::agent_host {
namespace {

constexpr const char* kBuiltIn = "built in";

std::string Described(const std::string& origin) { return origin.empty() ? std::string("unnamed") : origin; }

void AddBuiltIns(ControllerRegistry& registry) { AddBuiltInKinds(registry, kBuiltIn); }

}  // namespace

const ControllerRegistry& ControllerRegistry::BuiltIns() {
  static const ControllerRegistry& registry = *[] {
    auto* built_ins = new ControllerRegistry();  // never destroyed: kinds outlive every static user
    AddBuiltIns(*built_ins);
    return built_ins;
  }();
  return registry;
}

std::shared_ptr<const ControllerRegistry> ControllerRegistry::ForConfig(const config::ControllerConfig& config) {
  auto registry = std::make_shared<ControllerRegistry>();
  registry->AddAll(BuiltIns(), kBuiltIn);
  ControllerPluginLoader::AddKinds(config, registry.get());
  return registry;
}

std::shared_ptr<const kind_api::ControllerKind> ControllerRegistry::KindOf(const config::ControllerConfig& config) {
  const config::ConfigNode name = config.controller.Optional("kind");
  if (!name.IsDefined() || name.IsMap() || name.IsSequence()) return nullptr;
  std::shared_ptr<const ControllerRegistry> registry = ForConfig(config);
  const kind_api::ControllerKind* kind = registry->Find(name.AsString());
  if (kind == nullptr) return nullptr;
  return {std::move(registry), kind};  // shares the registry's ownership
}

void ControllerRegistry::Add(kind_api::ControllerKind kind, const std::string& origin) {
  if (kind.name.empty()) throw std::invalid_argument("a controller kind needs a name");
  if (!kind.make_builder) throw std::invalid_argument("controller kind '" + kind.name + "' has no make_builder");
  if (!kind.default_parts) throw std::invalid_argument("controller kind '" + kind.name + "' has no default_parts");
  const std::lock_guard<std::mutex> lock(mutex_);
  if (const Entry* taken = FindLocked(kind.name)) {
    throw std::invalid_argument("controller kind '" + kind.name + "' is registered twice (" + Described(taken->origin) +
                                " and " + Described(origin) + ")");
  }
  entries_.push_back({std::move(kind), origin});
}

void ControllerRegistry::AddAll(const ControllerRegistry& other, const std::string& origin) {
  if (&other == this) return;
  const std::scoped_lock lock(mutex_, other.mutex_);
  for (const Entry& entry : other.entries_) {
    if (const Entry* taken = FindLocked(entry.kind.name)) {
      throw std::invalid_argument("controller kind '" + entry.kind.name + "' is already registered (" +
                                  Described(taken->origin) + ")");
    }
  }
  for (const Entry& entry : other.entries_) entries_.push_back({entry.kind, origin});
}

const kind_api::ControllerKind* ControllerRegistry::Find(const std::string& name) const {
  const std::lock_guard<std::mutex> lock(mutex_);
  const Entry* entry = FindLocked(name);
  return entry == nullptr ? nullptr : &entry->kind;
}

std::vector<std::string> ControllerRegistry::Names() const {
  const std::lock_guard<std::mutex> lock(mutex_);
  std::vector<std::string> names;
  for (const Entry& entry : entries_) names.push_back(entry.kind.name);
  return names;
}

const ControllerRegistry::Entry* ControllerRegistry::FindLocked(const std::string& name) const {
  for (const Entry& entry : entries_) {
    if (entry.kind.name == name) return &entry;
  }
  return nullptr;
}

}  // namespace dream::agent_host
