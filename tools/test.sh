#!/usr/bin/env bash
# The README's test command: install dependencies (with headless Chromium for the display's
# browser test), build (the same build as run-default.sh), run the whole suite with ctest.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/tools/install-deps.sh" --test
"$root/tools/build.sh"
build_dir=${SKYTRACK_BUILD_DIR:-$root/build}
# Every DDS participant uses the loopback-only configuration, never Cyclone's default.
export CYCLONEDDS_URI="file://$root/config/dds/loopback.xml"
# Chromium was installed above: the browser test must run, not skip.
export SKYTRACK_REQUIRE_BROWSER=1
ctest --test-dir "$build_dir" --output-on-failure -j"$(nproc)"
