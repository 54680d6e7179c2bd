// cosmos: the command-line front end of COSMOS-Cell. Every failure on bad input ends in one
// line on stderr naming the file, key or device and the reason, and a non-zero exit.
#include <CLI/CLI.hpp>
#include <iostream>
#include <map>

#include "apps/command_registry.hpp"
#include "core/input_error.hpp"
#include "cosmos_build_info.hpp"

namespace cosmos::cli {
namespace {
std::map<std::string, CommandInstaller>& registry() {
  static std::map<std::string, CommandInstaller> commands;
  return commands;
}
}  // namespace

CommandRegistration::CommandRegistration(std::string name, CommandInstaller install) {
  registry().emplace(std::move(name), std::move(install));
}

void install_commands(CLI::App& root) {
  for (auto& [name, install] : registry()) install(root);
}

}  // namespace cosmos::cli

int main(int argc, char** argv) {
  CLI::App app{"COSMOS-Cell: free-form part recognition from range data (Dorai's COSMOS)"};
  // `cosmos` alone is someone finding their way: the help, not an error.
  app.require_subcommand(0, 1);
  app.set_version_flag("--version",
                       std::string("cosmos ") + cosmos::build_info::kVersion + " (" +
                           cosmos::build_info::kGitCommit + ")",
                       "print the version and the git commit it was built from");
  // Usage errors are one line too (CLI11 would add a "Run with --help" line).
  app.failure_message(
      [](const CLI::App*, const CLI::Error& error) { return std::string(error.what()) + "\n"; });
  cosmos::cli::install_commands(app);
  try {
    app.parse(argc, argv);
    if (app.get_subcommands().empty()) std::cout << app.help();
  } catch (const CLI::ParseError& error) {
    return app.exit(error);
  } catch (const cosmos::InputError& error) {
    std::cerr << "cosmos: " << error.what() << "\n";
    return 1;
  } catch (const std::exception& error) {
    std::cerr << "cosmos: error: " << error.what() << "\n";
    return 2;
  }
  return 0;
}
