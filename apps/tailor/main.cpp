/// @file
/// Entry point of the `tailor` command-line tool.

#include <spdlog/spdlog.h>

#include <algorithm>
#include <exception>
#include <iostream>

#include "command.hpp"
#include "tailor/geometry/error.hpp"

namespace tailor::cli {

std::vector<CommandEntry>& command_registry() {
  static std::vector<CommandEntry> registry;
  return registry;
}

CommandRegistration::CommandRegistration(std::string name, CommandSetup setup) {
  command_registry().push_back({std::move(name), std::move(setup)});
}

}  // namespace tailor::cli

int main(int argc, char** argv) {
  using namespace tailor::cli;
  CLI::App app{"tailor: exact continuous self-collision detection for cloth"};
  app.require_subcommand(1);
  bool verbose = false;
  app.add_flag("-v,--verbose", verbose, "Print debug messages");

  auto& registry = command_registry();
  std::sort(registry.begin(), registry.end(),
            [](const CommandEntry& a, const CommandEntry& b) { return a.name < b.name; });
  std::vector<std::function<int()>> runners;
  std::vector<CLI::App*> subcommands;
  for (auto& entry : registry) {
    runners.push_back(entry.setup(app));
    subcommands.push_back(app.get_subcommand(entry.name));
  }

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? kSuccess : kUsageError;
  }
  spdlog::set_pattern("%^%l%$: %v");
  spdlog::set_level(verbose ? spdlog::level::debug : spdlog::level::info);

  try {
    for (std::size_t i = 0; i < subcommands.size(); ++i) {
      if (subcommands[i] != nullptr && subcommands[i]->parsed()) return runners[i]();
    }
  } catch (const tailor::InputError& e) {
    std::cerr << "error: " << e.what() << "\n";
    return kUsageError;
  } catch (const std::exception& e) {
    std::cerr << "error: " << e.what() << "\n";
    return kFailure;
  }
  return kUsageError;
}
