#include <cstdint>
#include <exception>
#include <string>

#include "dream/config/config_error.h"
#include "dream/config/config_node.h"
#include "dream/config/run_config.h"
#include "fuzz_targets.h"

namespace dream::fuzz {

void RunConfigTarget(const uint8_t* data, size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    (void)config::LoadRunConfig(config::ConfigNode::LoadString(text, "fuzz.yaml"));
  } catch (const config::ConfigError& e) {
    if (std::string(e.what()).rfind("fuzz.yaml", 0) != 0) Finding("a config error without its file: " + std::string(e.what()));
  } catch (const std::exception& e) {
    Finding("a config refused by something else than a ConfigError: " + std::string(e.what()));
  }
}

}  // namespace dream::fuzz
