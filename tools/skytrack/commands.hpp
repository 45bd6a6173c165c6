#pragma once
// Subcommands of the `skytrack` tool. Each registers itself on the CLI11 app; the callback
// stores its exit code in `exit_code`.
#include <CLI/CLI.hpp>

namespace skytrack::tool {

void add_simulate_command(CLI::App& app, int& exit_code);
void add_eval_command(CLI::App& app, int& exit_code);
void add_check_profile_command(CLI::App& app, int& exit_code);
void add_track_command(CLI::App& app, int& exit_code);
void add_replay_command(CLI::App& app, int& exit_code);
void add_record_command(CLI::App& app, int& exit_code);
void add_status_command(CLI::App& app, int& exit_code);
void add_bench_latency_command(CLI::App& app, int& exit_code);
void add_rebatch_command(CLI::App& app, int& exit_code);
void add_import_asterix_command(CLI::App& app, int& exit_code);
void add_display_command(CLI::App& app, int& exit_code);
void add_fuse_command(CLI::App& app, int& exit_code);

}  // namespace skytrack::tool
