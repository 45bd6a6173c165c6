// `skytrack simulate`: scenario YAML -> plot stream and ground truth (JSON Lines).
#include <cstdint>
#include <cstdio>
#include <optional>
#include <string>

#include <fmt/format.h>

#include "commands.hpp"
#include "skytrack/config/scenario_loader.hpp"
#include "skytrack/io/jsonl_writer.hpp"
#include "skytrack/sim/simulator.hpp"

namespace skytrack::tool {
namespace {

struct SimulateOptions {
  std::string scenario;
  std::string plots;
  std::string truth;
  std::optional<std::uint64_t> seed;
};

int run_simulate(const SimulateOptions& options) {
  auto scenario = config::load_scenario(options.scenario);
  if (!scenario) {
    fmt::print(stderr, "{}\n", scenario.error().message);
    return 2;
  }
  const std::uint64_t seed = options.seed.value_or(scenario->seed);
  const std::string name = scenario->name;
  auto simulator = sim::Simulator::create(std::move(*scenario), seed);
  if (!simulator) {
    fmt::print(stderr, "{}: {}\n", options.scenario, simulator.error().message);
    return 2;
  }
  auto plots = io::JsonLinesWriter::open(options.plots);
  auto truth = io::JsonLinesWriter::open(options.truth);
  if (!plots || !truth) {
    fmt::print(stderr, "{}\n", !plots ? plots.error().message : truth.error().message);
    return 2;
  }
  std::size_t scans = 0, plot_count = 0;
  while (auto batch = simulator->next()) {
    ++scans;
    plot_count += batch->plots.plots.size();
    if (!plots->write(batch->plots) || !truth->write(batch->truth)) {
      fmt::print(stderr, "write failed ({} or {})\n", options.plots, options.truth);
      return 2;
    }
  }
  if (!plots->close() || !truth->close()) {
    fmt::print(stderr, "write failed ({} or {})\n", options.plots, options.truth);
    return 2;
  }
  fmt::print(stderr, "simulated '{}' (seed {}): {} scans, {} plots -> {}, {}\n", name, seed, scans,
             plot_count, options.plots, options.truth);
  return 0;
}

}  // namespace

void add_simulate_command(CLI::App& app, int& exit_code) {
  auto options = std::make_shared<SimulateOptions>();
  CLI::App* cmd = app.add_subcommand("simulate", "Simulate a scenario into plots and truth");
  cmd->add_option("--scenario", options->scenario, "Scenario YAML file")
      ->required()
      ->check(CLI::ExistingFile);
  cmd->add_option("--plots", options->plots, "Output plot stream (JSON Lines)")->required();
  cmd->add_option("--truth", options->truth, "Output ground truth (JSON Lines)")->required();
  cmd->add_option("--seed", options->seed, "Random seed (default: the scenario's)");
  cmd->footer(
      "Example: skytrack simulate --scenario config/scenarios/default.yaml --plots "
      "out/default.plots.jsonl --truth out/default.truth.jsonl\nExit codes: 0 done; 2 "
      "the scenario is invalid or a file cannot be written; 1xx command-line mistakes "
      "(CLI11: 105 a bad value, 106 a required option missing, 109 an unknown "
      "argument).");
  cmd->callback([options, &exit_code] { exit_code = run_simulate(*options); });
}

}  // namespace skytrack::tool
