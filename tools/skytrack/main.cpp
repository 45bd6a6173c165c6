// skytrack: the command-line tool (simulate, track, eval, check-profile, import-asterix, fuse;
// replay, record and status over DDS).
#include <CLI/CLI.hpp>

#include "commands.hpp"
#include "skytrack/daemon/memory_policy.hpp"
#include "skytrack/daemon/tsan_suppressions.hpp"

int main(int argc, char** argv) {
  skytrack::daemon::apply_memory_policy();
  CLI::App app{"skytrack - radar track processing: simulate, track and evaluate"};
  app.require_subcommand(1);
  int exit_code = 0;
  skytrack::tool::add_simulate_command(app, exit_code);
  skytrack::tool::add_eval_command(app, exit_code);
  skytrack::tool::add_check_profile_command(app, exit_code);
  skytrack::tool::add_track_command(app, exit_code);
  skytrack::tool::add_replay_command(app, exit_code);
  skytrack::tool::add_record_command(app, exit_code);
  skytrack::tool::add_status_command(app, exit_code);
  skytrack::tool::add_bench_latency_command(app, exit_code);
  skytrack::tool::add_rebatch_command(app, exit_code);
  skytrack::tool::add_import_asterix_command(app, exit_code);
  skytrack::tool::add_display_command(app, exit_code);
  skytrack::tool::add_fuse_command(app, exit_code);
  CLI11_PARSE(app, argc, argv);
  return exit_code;
}
