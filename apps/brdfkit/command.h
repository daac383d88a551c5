#pragma once
// Git-style subcommands: each cmd_*.cpp registers itself here at static-initialization time,
// so adding a command touches no other file.
#include <CLI/CLI.hpp>
#include <functional>
#include <string>
#include <vector>

namespace brdfkit::cli {

// Adds the subcommand to `app` and returns the callback to run when it was chosen.
using CommandSetup = std::function<std::function<int()>(CLI::App& app)>;

struct CommandRegistration {
  CommandRegistration(std::string name, CommandSetup setup);
};

struct RegisteredCommand {
  std::string name;
  CommandSetup setup;
};
std::vector<RegisteredCommand>& registered_commands();

}  // namespace brdfkit::cli
