#pragma once
// `skytrack eval --identity`: scores a track output against the transponder identities the
// plot stream carries (metrics/identity_score.hpp), for recordings without ground truth.
#include <string>

namespace skytrack::tool {

struct IdentityOptions {
  std::string plots_path, tracks_path;
  double gap = 20.0;  // [s]
  bool json = false;
};

/// Prints the score; returns the exit code (0, or 2 when a file cannot be read).
int run_eval_identity(const IdentityOptions& options);

}  // namespace skytrack::tool
