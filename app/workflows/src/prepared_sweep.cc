#include "dream/workflows/prepared_sweep.h"

#include <set>

#include "dream/run_config/startup_drive_check.h"
#include "dream/world/printf_text.h"

#include <filesystem>
#include <map>
#include <optional>
#include <set>
#include <utility>
#include <stdexcept>

#include "dream/config_overrides/config_override.h"
#include "dream/config_overrides/config_text.h"
#include "dream/agent_host/controller_factory.h"
#include "dream/agent_host/controller_registry.h"
#include "dream/config/config_error.h"
#include "dream/files/file_text.h"
#include "dream/files/output_folder.h"
#include "dream/workflows/seed_list.h"
#include "replace_file.h"
#include "swept_config_text.h"

namespace dream::workflows {
namespace {

namespace fs = std::filesystem;

/// What `dream run` checks before it starts: the run config and the
/// controller section (which also loads the plugins the config names).
/// @throws config::ConfigError.
run_config::RunConfig CheckRunConfig(const config::ConfigNode& root) {
  run_config::RunConfig config = run_config::LoadRunConfig(root);
  const agent_host::ControllerFactory factory(config);
  return config;
}

/// The file of the controller's kind (its ControllerKind::file_key: a python
/// controller's module) that `root` names by a relative path: that path, and
/// the file it names (resolved from the base config's folder as `dream run`
/// resolves it), which is set into `root` so the checks find it while the run
/// folders do not exist yet. Nothing for kinds without a file and absolute
/// paths.
struct ModuleSource {
  fs::path relative;
  fs::path source;
  std::string key;  ///< of the controller section
};
std::optional<ModuleSource> KindFileSource(YAML::Node& root, const std::string& base_config_path,
                                           const agent_host::ControllerRegistry& kinds) {
  YAML::Node controller = root["controller"];
  if (!controller.IsMap() || !controller["kind"].IsScalar()) return std::nullopt;
  const kind_api::ControllerKind* kind = kinds.Find(controller["kind"].Scalar());
  if (kind == nullptr || kind->file_key.empty() || !controller[kind->file_key].IsScalar()) return std::nullopt;
  const fs::path module(controller[kind->file_key].Scalar());
  if (module.is_absolute()) return std::nullopt;
  const fs::path source = (fs::absolute(base_config_path).parent_path() / module).lexically_normal();
  controller[kind->file_key] = source.string();
  return ModuleSource{module.lexically_normal(), source, kind->file_key};
}

}  // namespace

struct PreparedSweep::RunConfigMaker {
  const SweepSettings& settings;
  const std::string& base_text;
  YAML::Node parsed_base;
  std::shared_ptr<const agent_host::ControllerRegistry> kinds;
  fs::path out;
  std::set<SweepPlan::Run::Values> checked_as_written;
  std::map<std::string, std::shared_ptr<const ModuleCopy>> module_texts;
  SweptConfigText texts;
  std::set<std::string> driven_start_poses;  ///< start poses whose drive was tried
};

PreparedSweep::PreparedSweep(const SweepSettings& settings, const run_config::RunConfig& base,
                             const std::string& out_dir)
    : plan_(SweepPlan::FromRuns({}, {})), base_name_(base.name) {
  const std::string base_text = settings.BaseConfigText();
  std::vector<uint64_t> seeds;
  try {
    seeds = settings.seeds.empty() ? std::vector<uint64_t>{base.seed} : ParseSeedList(settings.seeds);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument("--seeds " + settings.seeds + ": " + e.what());
  }
  seeds_text_ = settings.seeds.empty() ? std::to_string(base.seed) : settings.seeds;
  seed_count_ = seeds.size();
  std::vector<config_overrides::SweepParameter> parameters;
  for (const std::string& set : settings.sets) parameters.push_back(config_overrides::SweepParameter::Parse(set));
  std::vector<config_overrides::SweepParameter> zipped;
  for (const std::string& zip : settings.zips) zipped.push_back(config_overrides::SweepParameter::Parse(zip));
  for (const auto* swept : {&parameters, &zipped}) {
    for (const config_overrides::SweepParameter& parameter : *swept) {
      if (parameter.key == "steps" && settings.steps > 0) {
        throw std::invalid_argument("--steps and a swept steps=... both set the step limit; give one");
      }
    }
  }
  plan_ = SweepPlan(seeds, parameters, zipped);

  RunConfigMaker maker{settings,
                       base_text,
                       SweepPlan::ParseBase(base_text, settings.config_path),
                       agent_host::ControllerRegistry::ForConfig(base),
                       fs::path(out_dir),
                       {},
                       {},
                       {},
                       {}};
  for (const SweepPlan::Run& run : plan_.runs()) PrepareRun(maker, run);
}

void PreparedSweep::PrepareRun(RunConfigMaker& maker, const SweepPlan::Run& run) {
  const SweepSettings& settings = maker.settings;
  const auto make_config = [&](bool with_lines) {
    // Parsed once, cloned per run: 10,000 runs must plan in seconds (yaml-cpp's parser was most of it).
    YAML::Node root = with_lines ? SweepPlan::MakeRunConfig(maker.base_text, settings.config_path, run)
                                 : SweepPlan::MakeRunConfig(maker.parsed_base, settings.config_path, run);
    // In the file, not on dream run's command line: the run folder's config alone repeats the run.
    if (settings.steps > 0) {
      config_overrides::ApplyConfigOverride(root, "steps", std::to_string(settings.steps), settings.config_path);
    }
    return root;
  };
  YAML::Node root = make_config(false);
  const std::optional<ModuleSource> module_source = KindFileSource(root, settings.config_path, *maker.kinds);
  const std::string where = "run " + run.name + " (" + run.Label() + "): ";
  // Checked in memory against the base file; a mistake is checked again on a
  // fresh parse, so its error points at the key's line there.
  run_config::RunConfig checked;
  try {
    checked = CheckRunConfig(config::ConfigNode(root, settings.config_path, ""));
  } catch (const config::ConfigError& e) {
    YAML::Node with_lines = make_config(true);
    KindFileSource(with_lines, settings.config_path, *maker.kinds);
    try {
      CheckRunConfig(config::ConfigNode(with_lines, settings.config_path, ""));
    } catch (const config::ConfigError& located) {
      throw config::ConfigError(where + located.what());
    }
    throw config::ConfigError(where + e.what());
  }
  max_steps_ = std::max<long long>(max_steps_, checked.sim.max_steps);
  CheckStartupDrive(checked, where, &maker.driven_start_poses);
  const fs::path run_config = maker.out / "runs" / run.name / "config.yaml";
  const std::string header = "Generated by dream sweep from " + settings.config_path + ": " + run.Label() +
                             ".\nRun again (replacing this run with the same one): dream run " + run_config.string() +
                             " --out " + (maker.out / "runs" / run.name).string() + " --overwrite";
  // Then the file as written, as `dream run` will read it: once per set of
  // parameter values, as the seeds only change two plain scalars (seed, name).
  if (maker.checked_as_written.insert(run.parameters).second) {
    try {
      CheckRunConfig(config::ConfigNode::LoadString(config_overrides::ConfigText(root, header), run_config.string()));
    } catch (const config::ConfigError& e) {
      throw config::ConfigError(where + "the generated config: " + e.what());
    }
  }
  std::shared_ptr<const ModuleCopy> module;
  if (module_source && fs::is_regular_file(module_source->source)) {
    // Written with the module's own relative path: the run folder's copy.
    const std::string relative = module_source->relative.string();
    std::shared_ptr<const ModuleCopy>& shared = maker.module_texts[module_source->source.string() + "\n" + relative];
    if (!shared) {
      shared =
          std::make_shared<const ModuleCopy>(ModuleCopy{relative, files::ReadFileText(module_source->source.string())});
    }
    module = shared;
    root["controller"][module_source->key] = relative;
  }
  config_texts_.push_back(maker.texts.Text(root, header, run.parameters));
  modules_.push_back(std::move(module));
}

void PreparedSweep::CheckStartupDrive(const run_config::RunConfig& config, const std::string& where,
                                      std::set<std::string>* driven) {
  // Once per distinct start poses (and start mode): runs that differ only in a controller key start alike.
  std::string key = std::to_string(static_cast<int>(config.start)) + (config.sim_only ? "s" : "l") +
                    std::to_string(config.lab_safe_spacing_m);
  for (const world::Pose2& pose : config.initial_poses) {
    key += world::PrintfText(" %.17g %.17g %.17g", pose.x_m, pose.y_m, pose.theta_rad);
  }
  if (!driven->insert(key).second) return;
  const run_config::StartupDriveCheck check = run_config::StartupDriveCheck::Of(config);
  if (const std::string refusal = check.Refusal(); !refusal.empty()) throw config::ConfigError(where + refusal);
  if (!check.AllSettled()) startup_warnings_.push_back(where + check.Message());
}

void PreparedSweep::WriteRun(const SweepFolder& folder, size_t index) const {
  const SweepPlan::Run& run = plan_.runs().at(index);
  const std::string dir = folder.RunDir(run.name);
  std::error_code error;
  const bool made = fs::create_directory(dir, error);
  if (error) throw std::runtime_error("cannot create " + dir + ": " + error.message());
  // A folder left by an earlier sweep: its outputs must not pass for this run's.
  if (!made) folder.ClearRun(run.name);
  ReplaceFile(dir + "/config.yaml", config_texts_[index]);
  if (const std::shared_ptr<const ModuleCopy>& module = modules_[index]) {
    files::OutputFolder(dir).WriteFileInSubfolders(module->relative_path, module->text);
  }
}

}  // namespace dream::workflows
