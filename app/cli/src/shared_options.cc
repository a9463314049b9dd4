#include "shared_options.h"

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <system_error>
#include <utility>

namespace dream::cli {

CLI::Validator StepCount() {
  return CLI::Validator(
      [](const std::string& text) {
        return text.find_first_not_of("0123456789") == std::string::npos &&
                       text.find_first_not_of('0') != std::string::npos
                   ? std::string()
                   : "must be a whole number >= 1, got " + text;
      },
      "INT>=1");
}

CLI::Validator Seconds(bool zero_allowed) {
  const std::string rule = zero_allowed ? ">= 0" : "> 0";
  return CLI::Validator(
      [zero_allowed, rule](const std::string& text) {
        char* end = nullptr;
        const double value = std::strtod(text.c_str(), &end);
        const bool number = !text.empty() && end == text.c_str() + text.size() && std::isfinite(value);
        return number && (zero_allowed ? value >= 0.0 : value > 0.0)
                   ? std::string()
                   : "must be a number of seconds " + rule + ", got " + text;
      },
      zero_allowed ? "SECONDS>=0" : "SECONDS>0");
}

CLI::Validator SeedValue() {
  return CLI::Validator(
      [](const std::string& text) {
        bool fits = !text.empty() && text.size() <= 18 && text.find_first_not_of("0123456789") == std::string::npos;
        return fits ? std::string() : "must be a whole number from 0 to 999999999999999999, got " + text;
      },
      "INT>=0");
}

CLI::Validator KeyValue() {
  return CLI::Validator(
      [](const std::string& text) {
        const size_t equals = text.find('=');
        return equals != std::string::npos && equals > 0
                   ? std::string()
                   : "expected KEY=VALUE such as controller.max_speed_mps=0.1, got " + text;
      },
      "KEY=VALUE");
}

CLI::Option* AddRunLogArgument(CLI::App* command, const std::string& name, std::string* path) {
  return command->add_option(name, *path, "A run folder (its run.lcmlog) or an .lcmlog file")->required();
}

void AddRunFolderOptions(CLI::App* command, std::string* out_dir, bool* overwrite, const std::string& default_dir) {
  command->add_option(
      "--out", *out_dir,
      "Output folder for the run (default " + default_dir + ", or " + default_dir +
          "_2, _3, ... when that\nalready holds a run); refused when it holds a run, unless --overwrite");
  command->add_flag("--overwrite", *overwrite, "Replace the run already in the output folder");
}

void AddOverrideOptions(CLI::App* command, long long* seed, std::vector<std::string>* sets) {
  command->add_option("--seed", *seed, "Override the config's seed (initial poses and every noise source)")
      ->check(SeedValue());
  command
      ->add_option("--set", *sets,
                   "KEY=VALUE: override one config key (dotted: controller.max_speed_mps=0.1,\n"
                   "controller.sensors.0.noise_std=0.01); repeat for more keys")
      ->allow_extra_args(false)
      ->check(KeyValue());
}

CommandLine::CommandWithArgs<RunArgs> AddRunCommand(CommandLine& line, const std::string& name,
                                                    const std::string& description,
                                                    std::function<int(const RunArgs&)> run, const char* url_help) {
  const auto [command, args] = line.AddCommand<RunArgs>(name, description, std::move(run));
  command->add_option("config", args->config_path, "Run config (YAML), e.g. config/go_to_goal.yaml")->required();
  AddRunFolderOptions(command, &args->out_dir, &args->overwrite, "runs/<name>");
  AddOverrideOptions(command, &args->seed, &args->sets);
  command->add_option("--lcm-url", args->lcm_url, url_help);
  command->add_option("--steps", args->steps, "Override the config's step limit")->check(StepCount());
  command->add_option("--mode", args->mode, "Override the world mode")->check(CLI::IsMember({"lockstep", "realtime"}));
  command->add_flag("--all-steps", args->all_steps, "Run every step even when all robots report done (benchmarks)");
  command
      ->add_option("--pace", args->pace,
                   "Simulated seconds per wall second, to watch the run (1: real time, 4: four times faster,\n"
                   "0: as fast as it goes); lockstep stays lockstep, only no faster. Default: 0 (1 with --view)")
      ->check(CLI::Range(0.0, 1000.0));
  return {command, args};
}

void AddAgentOptions(CLI::App* command, AgentArgs* args) {
  command->add_option("config", args->config_path, "Run config (YAML)")->required();
  command->add_option("--robots", args->robots, "Robots to drive: all, 3, 0,2,5 or 0-4")->capture_default_str();
  command->add_option("--lcm-url", args->lcm_url, "LCM URL (default $LCM_DEFAULT_URL)");
  command->add_option("--idle-timeout", args->idle_timeout_s, "Give up after this many seconds without poses")
      ->check(Seconds(false))
      ->capture_default_str();
  // The world's overrides (dream launch passes them on): agents must build
  // the robots of the same config.
  AddOverrideOptions(command, &args->seed, &args->sets);
  command->add_option("--report", args->report_path,
                      "At exit, write what these agents refused (bad messages per channel, other runs seen, "
                      "steps out of sequence) to this JSON file; dream launch merges them into summary.json");
}

}  // namespace dream::cli
