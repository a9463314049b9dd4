#include "command_line.h"

#include <algorithm>
#include <utility>

#include "dream/config/name_suggestion.h"

namespace dream::cli {

CommandLine::CommandLine(const std::string& description, const std::string& name) : app_(description, name) {}

CLI::App* CommandLine::AddCommand(const std::string& name, const std::string& description, Action action,
                                  CLI::App* parent) {
  CLI::App* command = (parent != nullptr ? parent : &app_)->add_subcommand(name, description);
  commands_.push_back({command, std::move(action)});
  return command;
}

CLI::App* CommandLine::AddGroup(const std::string& name, const std::string& description) {
  CLI::App* group = app_.add_subcommand(name, description);
  group->require_subcommand(1);
  return group;
}

void CommandLine::Parse(int argc, char** argv) {
  argc_ = argc;
  argv_ = argv;
  app_.parse(argc, argv);
}

CommandLine::Action CommandLine::ChosenAction() const {
  // The last added of those parsed: a command's own subcommands (dream sweep
  // status) are added after it.
  for (auto it = commands_.rbegin(); it != commands_.rend(); ++it) {
    if (it->app->parsed()) return it->action;
  }
  return {};
}

std::string CommandLine::ParsedCommandName() const {
  std::string name = app_.get_name();
  for (const CLI::App* at = &app_; !at->get_subcommands().empty();) {
    at = at->get_subcommands().front();
    name += " " + at->get_name();
  }
  return name;
}

std::string CommandLine::SuggestionAfterFailedParse() const {
  const CLI::App* command = &app_;
  while (!command->get_subcommands().empty()) command = command->get_subcommands().front();
  std::vector<std::string> options;
  for (const CLI::Option* option : command->get_options()) {
    for (const std::string& name : option->get_lnames()) options.push_back("--" + name);
  }
  std::vector<std::string> subcommands;  // a group's (dream log's) commands
  for (const CLI::App* subcommand : command->get_subcommands({})) subcommands.push_back(subcommand->get_name());
  for (int i = 1; i < argc_; ++i) {
    const std::string word = argv_[i];
    std::string suggestion;
    if (word.rfind("--", 0) == 0 && word.size() > 2) {
      const std::string name = word.substr(0, word.find('='));
      if (std::find(options.begin(), options.end(), name) == options.end()) {
        suggestion = config::DidYouMean(name, options);
      }
    } else if (!subcommands.empty() && word[0] != '-') {
      suggestion = config::DidYouMean(word, subcommands);
    }
    if (!suggestion.empty()) return suggestion;
  }
  return "";
}

std::string CommandLine::ScriptArgumentsHint() const {
  for (int i = 1; i < argc_; ++i) {
    const std::string word = argv_[i];
    if (word.size() > 3 && word.compare(word.size() - 3, 3, ".py") == 0) {
      return "; a Robotarium script (" + word +
             ") takes no arguments of its own under dream (docs/robotarium-scripts.md#not-yet-supported)";
    }
  }
  return "";
}

}  // namespace dream::cli
