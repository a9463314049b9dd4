#pragma once

#include <CLI/CLI.hpp>

#include <functional>
#include <string>
#include <vector>

#include "command_line.h"
#include "commands.h"
#include "dream/files/run_log_path.h"

namespace dream::cli {

/// --steps: a whole number >= 1, with a message that says so (CLI::PositiveNumber
/// would take 2.5 and quote a 300-digit range). Shared by every command that
/// runs steps (run, sim, launch, lab-replay, sweep).
CLI::Validator StepCount();

/// A duration in seconds: finite and > 0 (or >= 0 with `zero_allowed`), with
/// a message that says so instead of CLI11's 300-digit range.
CLI::Validator Seconds(bool zero_allowed);

/// --seed: 0 or more, at most 18 digits (the config keeps seeds as signed
/// 64-bit numbers), with a message that says so.
CLI::Validator SeedValue();

/// --set (and sweep's --set/--zip): KEY=VALUE with a non-empty key, a usage
/// error (exit 2) otherwise, naming what was typed.
CLI::Validator KeyValue();

/// The required argument `name` of the commands that read one run's log
/// (log info, log echo, replay, render): a run folder or an .lcmlog file.
CLI::Option* AddRunLogArgument(CLI::App* command, const std::string& name, std::string* path);

/// The log that argument names (files::RunLogPath).
using files::RunLogPath;

/// --out DIR and --overwrite of the commands that write a run folder
/// (RunFolderChoice): `default_dir` is what --help names as the default.
void AddRunFolderOptions(CLI::App* command, std::string* out_dir, bool* overwrite, const std::string& default_dir);

/// --seed N and --set KEY=VALUE (repeatable), which OverriddenConfig applies.
void AddOverrideOptions(CLI::App* command, long long* seed, std::vector<std::string>* sets);

/// Adds a command that runs an experiment (run, sim, launch): they share
/// their options; only the help of --lcm-url differs, as each picks its own
/// default bus. Returns the command and its arguments, for options of its own.
CommandLine::CommandWithArgs<RunArgs> AddRunCommand(CommandLine& line, const std::string& name,
                                                    const std::string& description,
                                                    std::function<int(const RunArgs&)> run, const char* url_help);

/// The options of `dream agent`, which the dream-agent executable it hands
/// over to must parse the same way.
void AddAgentOptions(CLI::App* command, AgentArgs* args);

}  // namespace dream::cli
