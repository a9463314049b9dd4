#include "swept_config_text.h"

#include "dream/config_overrides/config_text.h"

namespace dream::workflows {
namespace {

/// What ConfigText emits for `key: value` as one entry of a top-level map.
std::string EntryText(const YAML::Node& key, const YAML::Node& value) {
  YAML::Emitter out;
  out.SetIndent(2);
  out << YAML::BeginMap << YAML::Key << key << YAML::Value << value << YAML::EndMap;
  return out.c_str();
}

/// The keys a sweep sets per seed: emitted afresh for every run.
bool ChangesPerSeed(const std::string& key) { return key == "seed" || key == "name"; }

}  // namespace

std::string SweptConfigText::Text(const YAML::Node& config, const std::string& header, const ParameterValues& values) {
  const auto found = kept_.find(values);
  if (found != kept_.end()) {
    if (found->second.reusable) {
      std::string text = FromKept(config, header, found->second);
      if (!text.empty()) return text;
    }
    return config_overrides::ConfigText(config, header);
  }
  const std::string whole = config_overrides::ConfigText(config, header);
  KeptEntries kept;
  if (config.IsMap()) {
    std::string joined;
    for (const auto& entry : config) {
      const std::string text = EntryText(entry.first, entry.second);
      joined += (joined.empty() ? "" : "\n") + text;
      const std::string key = entry.first.IsScalar() ? entry.first.Scalar() : std::string();
      kept.key_and_text.emplace_back(key, ChangesPerSeed(key) ? std::string() : text);
    }
    kept.reusable = config_overrides::CommentLines(header) + joined + "\n" == whole;
  }
  kept_.emplace(values, std::move(kept));
  return whole;
}

std::string SweptConfigText::FromKept(const YAML::Node& config, const std::string& header, const KeptEntries& kept) {
  if (config.size() != kept.key_and_text.size()) return {};
  std::string joined;
  size_t index = 0;
  for (const auto& entry : config) {
    const auto& [key, text] = kept.key_and_text[index++];
    if (!entry.first.IsScalar() || entry.first.Scalar() != key) return {};
    joined += (joined.empty() ? "" : "\n") + (ChangesPerSeed(key) ? EntryText(entry.first, entry.second) : text);
  }
  return config_overrides::CommentLines(header) + joined + "\n";
}

}  // namespace dream::workflows
