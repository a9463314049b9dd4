#pragma once

#include <yaml-cpp/yaml.h>

#include <map>
#include <string>
#include <utility>
#include <vector>

namespace dream::workflows {

/// The text of each run's config in a sweep, as config_overrides::ConfigText
/// writes it, without emitting the whole config for every seed: the runs of
/// one set of parameter values differ only in `seed` and `name`, so the text of
/// every other top-level entry is kept from the first run of that set. The
/// first run's text is compared with ConfigText's, and any set where the two
/// differ (anchors shared between entries, say) is emitted whole every time.
class SweptConfigText {
 public:
  using ParameterValues = std::vector<std::pair<std::string, std::string>>;

  /// ConfigText(config, header) for a run with `values`.
  std::string Text(const YAML::Node& config, const std::string& header, const ParameterValues& values);

 private:
  struct KeptEntries {
    bool reusable = false;
    std::vector<std::pair<std::string, std::string>> key_and_text;  ///< in the config's order
  };

  /// The config's text from `kept`, or empty when its keys are not kept's.
  static std::string FromKept(const YAML::Node& config, const std::string& header, const KeptEntries& kept);

  std::map<ParameterValues, KeptEntries> kept_;
};

}  // namespace dream::workflows
