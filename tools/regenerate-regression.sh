#!/usr/bin/env bash
# Rewrites the replay regression's expected digests (tests/regression/expected) that differ
# from the current build beyond the test's tolerance (1e-9), on purpose: after a change meant
# to alter the tracks, run this, read the diff, and say why in the commit. Builds the
# regression test first.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build_dir=${SKYTRACK_BUILD_DIR:-$root/build}
cmake --build "$build_dir" --target regression_tests
SKYTRACK_REGENERATE_REGRESSION=1 "$build_dir/tests/regression_tests" --gtest_brief=1
git -C "$root" diff --stat -- tests/regression/expected
