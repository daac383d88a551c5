// The `brdfkit` command line: one executable, git-style subcommands.
#include <malloc.h>

#include <algorithm>
#include <cstdio>
#include <iostream>
#include <string>

#include "brdfkit/core/error.h"
#include "brdfkit/core/text.h"
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

// Every error ends as this one line on stderr. The message goes through printable(): names from
// files and arguments may hold NUL or control bytes, which must neither cut the line short nor
// reach the terminal raw.
int print_error(const std::string& prefix, const std::string& message, int exit_code) {
  std::cerr << prefix << ": " << brdfkit::printable(message) << "\n";
  return exit_code;
}

// A parser error (unknown option, missing value, not a number) in one line naming the subcommand;
// the full help is one --help away and would bury the message.
int print_usage_error(const std::vector<CLI::App*>& subs, const CLI::ParseError& e, int argc, char** argv) {
  std::string prefix = "brdfkit", message = e.what();
  for (const CLI::App* sub : subs)
    if (sub->parsed()) prefix += " " + sub->get_name();
  if (prefix == "brdfkit" && argc > 1 && argv[1][0] != '-') {
    std::vector<std::string> names;
    for (const CLI::App* sub : subs) names.push_back(sub->get_name());
    message = "'" + std::string(argv[1]) + "' is not a subcommand (" + CLI::detail::join(names, ", ") + ")";
  }
  return print_error(prefix, message + "; see " + prefix + " --help", 2);
}

// A fit allocates and frees its per-block buffers (hundreds of KB to MB each) on every evaluation.
// Above glibc's mmap threshold each one is mapped afresh and every page faults in again: 1.2 s of a
// 9.7 s fit's CPU (colodur_napoli's SGD-Bagher fit, system time 1.34 → 0.15 s). Serving them from
// the heap, and not trimming it between evaluations, reuses the same pages; peak RSS is unchanged.
void keep_freed_blocks() {
  constexpr int kThreshold = 32 << 20;  // glibc's largest mmap threshold (mallopt(3))
  mallopt(M_MMAP_THRESHOLD, kThreshold);
  mallopt(M_TRIM_THRESHOLD, 2 * kThreshold);
}

}  // namespace brdfkit::cli

int main(int argc, char** argv) {
  using namespace brdfkit::cli;
  keep_freed_blocks();
  CLI::App app{"brdfkit: fit, check, sample and compare analytic BRDF models on measured reflectance"};
  app.set_version_flag("--version", std::string("brdfkit ") + BRDFKIT_VERSION);
  app.require_subcommand(1);
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
    std::vector<CLI::App*> subs;
    for (auto& [sub, run] : runs) subs.push_back(sub);
    return print_usage_error(subs, e, argc, argv);
  }
  try {
    for (auto& [sub, run] : runs)
      if (sub->parsed()) return run();
  } catch (const brdfkit::SettingError& e) {
    return print_error("brdfkit", flag_of(e.setting()) + ": " + e.detail(), 2);
  } catch (const brdfkit::InputError& e) {
    return print_error("brdfkit", e.what(), 2);
  } catch (const std::exception& e) {
    return print_error("brdfkit", std::string("internal error: ") + e.what(), 1);
  }
  return 2;
}
