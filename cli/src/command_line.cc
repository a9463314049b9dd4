#include "command_line.h"

#include <utility>

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
  for (const Command& command : commands_) {
    if (command.app->parsed()) return command.action;
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

}  // namespace dream::cli
