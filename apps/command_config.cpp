// `cosmos config docs`: docs/parameters.md, every parameter with its default, description and
// range, generated from the parameter structs (apps/parameter_docs.hpp).
#include <CLI/CLI.hpp>
#include <cstdio>

#include "apps/command_registry.hpp"
#include "apps/parameter_docs.hpp"

namespace cosmos::cli {
namespace {

void install(CLI::App& root) {
  CLI::App* config = root.add_subcommand("config", "The cell's parameters");
  config->require_subcommand(1);
  CLI::App* docs = config->add_subcommand(
      "docs", "Print docs/parameters.md: every parameter, its default, meaning and range");
  docs->callback([] { std::fputs(parameters_markdown().c_str(), stdout); });
}

const CommandRegistration registration("config", install);

}  // namespace
}  // namespace cosmos::cli
