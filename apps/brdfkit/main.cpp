// The `brdfkit` command line: one executable, git-style subcommands.
#include <algorithm>
#include <cstdio>
#include <iostream>
#include <string>

#include "brdfkit/core/error.h"
#include "command.h"

namespace brdfkit::cli {

std::vector<RegisteredCommand>& registered_commands() {
  static std::vector<RegisteredCommand> commands;
  return commands;
}

CommandRegistration::CommandRegistration(std::string name, CommandSetup setup) {
  registered_commands().push_back({std::move(name), std::move(setup)});
}

// A setting's flag: its name with '-' for '_' (fit_options.h binds the flags that way).
std::string flag_of(std::string setting) {
  std::replace(setting.begin(), setting.end(), '_', '-');
  return "--" + setting;
}

}  // namespace brdfkit::cli

int main(int argc, char** argv) {
  using namespace brdfkit::cli;
  CLI::App app{"brdfkit: fit, check, sample and compare analytic BRDF models on measured reflectance"};
  app.set_version_flag("--version", std::string("brdfkit ") + BRDFKIT_VERSION);
  app.require_subcommand(1);
  app.failure_message(CLI::FailureMessage::help);
  auto& commands = registered_commands();
  std::sort(commands.begin(), commands.end(), [](auto& a, auto& b) { return a.name < b.name; });
  std::vector<std::pair<CLI::App*, std::function<int()>>> runs;
  for (auto& cmd : commands) {
    const size_t before = app.get_subcommands({}).size();
    auto run = cmd.setup(app);
    runs.emplace_back(app.get_subcommands({})[before], std::move(run));
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    app.exit(e);  // prints the message and usage on stderr
    return 2;
  }
  try {
    for (auto& [sub, run] : runs)
      if (sub->parsed()) return run();
  } catch (const brdfkit::SettingError& e) {
    std::cerr << "brdfkit: " << flag_of(e.setting()) << ": " << e.detail() << "\n";
    return 2;
  } catch (const brdfkit::InputError& e) {
    std::cerr << "brdfkit: " << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "brdfkit: internal error: " << e.what() << "\n";
    return 1;
  }
  return 2;
}
