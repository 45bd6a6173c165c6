// skytrack-extended-mc: paper 002's experiment (one object, bounded noise) and the same three
// estimators on Gaussian noise and on several objects in clutter; prints Markdown tables.
// Run by tools/experiments/extended-mc.sh; see docs/extended.md.
#include <chrono>
#include <cstdint>
#include <string>

#include <fmt/core.h>
#include <CLI/CLI.hpp>

#include "multi_scenario.hpp"
#include "paper_scenario.hpp"

namespace xmc = skytrack::extended::experiment;

namespace {

void print_single_table(const xmc::PaperScenario& base, const Eigen::Matrix2d& bayes_noise,
                        int runs, std::uint64_t seed, bool literal) {
  fmt::print(
      "| noise | filter | position ARMSE [m] | velocity ARMSE [m/s] | mean GWD eq. 50 "
      "[m^2] | mean GWD root [m] | {} runs [ms] |\n",
      runs);
  fmt::print("|---|---|---|---|---|---|---|\n");
  for (xmc::NoiseKind noise : {xmc::NoiseKind::kBounded, xmc::NoiseKind::kGaussian}) {
    xmc::PaperScenario scenario = base;
    scenario.noise = noise;
    for (const xmc::FilterSetup& filter : xmc::paper_filters(scenario, bayes_noise, literal)) {
      const auto start = std::chrono::steady_clock::now();
      const xmc::McResult r = xmc::run_paper_monte_carlo(scenario, filter, runs, seed);
      const double ms =
          std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
              .count();
      fmt::print(
          "| {} | {} | {:.4f} | {:.4f} | {:.1f} | {:.2f} | {:.1f} |\n",
          noise == xmc::NoiseKind::kBounded ? "bounded (uniform in E(0,U))" : "Gaussian N(0,U/4)",
          filter.name, r.armse_position, r.armse_velocity, r.mean_gwd_squared, r.mean_gwd, ms);
    }
  }
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Paper 002's extended-object experiment and the multi-object comparison"};
  int runs = 100;
  std::uint64_t seed = 1;
  std::string table = "all";
  std::string bayes = "bound";
  double mean_plots = 10.0;
  bool literal = false;
  app.add_option("--runs", runs, "Monte Carlo runs")->check(CLI::PositiveNumber);
  app.add_option("--seed", seed, "first seed");
  app.add_option("--table", table, "single, multi or all")
      ->check(CLI::IsMember({"single", "multi", "all"}));
  app.add_option("--bayes-noise", bayes,
                 "R of the Bayesian filters: bound (R = U, the paper's one printed matrix) or "
                 "moment (R = U/4, the covariance of the uniform noise)")
      ->check(CLI::IsMember({"bound", "moment"}));
  app.add_option("--mean-plots", mean_plots, "Poisson mean of an object's plots per scan");
  app.add_flag("--literal-smf", literal,
               "also SMF-EOT with the extent step as printed in the paper (one-object table)");
  CLI11_PARSE(app, argc, argv);

  xmc::PaperScenario scenario;
  scenario.mean_plots = mean_plots;
  const Eigen::Matrix2d bayes_noise =
      bayes == "bound" ? scenario.sensor_bound : Eigen::Matrix2d(scenario.sensor_bound / 4.0);
  if (table == "single" || table == "all") {
    fmt::print(
        "One object (paper 002, section 3.1), R of the Bayesian filters = {}, mean "
        "{} plots per scan\n\n",
        bayes == "bound" ? "U" : "U/4", mean_plots);
    print_single_table(scenario, bayes_noise, runs, seed, literal);
    fmt::print("\n");
  }
  if (table == "multi" || table == "all") {
    xmc::print_multi_table(bayes_noise, runs, seed);
  }
  return 0;
}
