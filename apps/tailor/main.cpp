/// @file
/// Entry point of the `tailor` command-line tool.

#include <spdlog/spdlog.h>

#include <algorithm>
#include <exception>
#include <iostream>

#include "command.hpp"
#include "idle_blas_threads.hpp"
#include "tailor/geometry/error.hpp"
#include "tailor/io/memory_budget.hpp"

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
  stop_idle_blas_threads();
  CLI::App app{"tailor: exact continuous self-collision detection for cloth"};
  app.require_subcommand(1);
  bool verbose = false;
  app.add_flag("-v,--verbose", verbose, "Print debug messages");
  double max_memory_gib = static_cast<double>(tailor::kDefaultMemoryBudget) / (1 << 30);
  app.add_option("--max-memory", max_memory_gib,
                 "Memory budget in GiB for anything sized by the input (files, scene "
                 "resolution); larger inputs are refused")
      ->check(CLI::Range(1.0 / 1024, 1024.0 * 1024))
      ->capture_default_str();
  app.fallthrough();  // global options may also follow the subcommand

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
  tailor::set_memory_budget(static_cast<std::uint64_t>(max_memory_gib * (1 << 30)));
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
