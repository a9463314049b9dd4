#pragma once

#include <CLI/CLI.hpp>

#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace dream::cli {

/// The `dream` command line: the CLI11 app, and for each subcommand the
/// action that runs when it is chosen. Each command's file declares its own
/// options and action (DeclareXxxCommand in commands.h), so main() only
/// parses and dispatches.
class CommandLine {
 public:
  /// What a chosen command does; returns the process's exit code.
  using Action = std::function<int()>;

  CommandLine(const std::string& description, const std::string& name);
  CommandLine(const CommandLine&) = delete;
  CommandLine& operator=(const CommandLine&) = delete;

  /// The whole app, for global flags, --help and parse errors.
  CLI::App& app() { return app_; }

  /// Adds subcommand `name` under `parent` (the app when null) that runs
  /// `action` when chosen. Commands appear in `dream --help` in the order
  /// they are added.
  CLI::App* AddCommand(const std::string& name, const std::string& description, Action action,
                       CLI::App* parent = nullptr);
  /// A command added with options: `args` is what its options fill in.
  template <typename Args>
  struct CommandWithArgs {
    CLI::App* app;
    Args* args;
  };

  /// Adds subcommand `name` whose options fill a new `Args` (the action
  /// keeps it alive: CLI11 writes into it while parsing) and that calls
  /// `run` with it when chosen.
  template <typename Args>
  CommandWithArgs<Args> AddCommand(const std::string& name, const std::string& description,
                                   std::function<int(const Args&)> run, CLI::App* parent = nullptr) {
    auto args = std::make_shared<Args>();
    CLI::App* app = AddCommand(
        name, description, [args, run = std::move(run)] { return run(*args); }, parent);
    return {app, args.get()};
  }

  /// Adds a subcommand that only groups others (dream log): one of them is required.
  CLI::App* AddGroup(const std::string& name, const std::string& description);

  /// Parses the words typed and keeps them for argc()/argv().
  /// @throws CLI::ParseError as CLI::App::parse does.
  void Parse(int argc, char** argv);
  /// The words given to Parse, for a command that hands them on (dream agent
  /// replaces itself with dream-agent and the same words).
  int argc() const { return argc_; }
  char** argv() const { return argv_; }

  /// The action of the command Parse chose; empty when none was.
  Action ChosenAction() const;
  /// "dream log info": the command words a parse got to, failed or not, for a
  /// pointer to the right --help.
  std::string ParsedCommandName() const;
  /// After a failed parse: " (did you mean '--overwrite'?)" when one of the
  /// words given is an unknown --option that looks like a typo of an option
  /// of the command the parse got to (or, under a group such as dream log, a
  /// typo of one of its commands), else "".
  std::string SuggestionAfterFailedParse() const;
  /// After "argument was not expected": when a word given is a Python
  /// script, that dream passes a script no arguments of its own; else "".
  std::string ScriptArgumentsHint() const;

 private:
  struct Command {
    CLI::App* app;
    Action action;
  };

  CLI::App app_;
  std::vector<Command> commands_;
  int argc_ = 0;
  char** argv_ = nullptr;
};

}  // namespace dream::cli
