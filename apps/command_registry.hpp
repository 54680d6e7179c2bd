#pragma once
// Each subcommand lives in its own apps/command_*.cpp and registers itself here, so the
// composition root (main.cpp) does not change when a command is added.
#include <CLI/CLI.hpp>
#include <functional>
#include <string>

namespace cosmos::cli {

using CommandInstaller = std::function<void(CLI::App& root)>;

struct CommandRegistration {
  CommandRegistration(std::string name, CommandInstaller install);
};

void install_commands(CLI::App& root);

}  // namespace cosmos::cli
