#!/usr/bin/env bash
# Installs skytrack's build and test dependencies from Debian 12 packages. Idempotent and
# quiet when everything is already there. Needs root (or sudo) for apt-get.
set -euo pipefail

packages=(
  build-essential cmake ninja-build pkg-config
  libeigen3-dev cyclonedds-dev cyclonedds-tools
  libyaml-cpp-dev libspdlog-dev libfmt-dev
  libsimdjson-dev libcli11-dev libexpected-dev libnanoflann-dev
  libgtest-dev libgmock-dev libbenchmark-dev
  libcpp-httplib-dev
)
# --test: also what the test suite needs beyond the build: headless Chromium for the display's
# browser test (tests/daemon/display_browser_test.cpp), and tshark for the field-by-field check
# of the ASTERIX decoder against Wireshark's dissector (tests/asterix/realdata_test.cpp).
[ "${1:-}" = "--test" ] && packages+=(chromium tshark)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
[ ${#missing[@]} -eq 0 ] && exit 0

sudo_cmd=()
[ "$(id -u)" -ne 0 ] && sudo_cmd=(sudo)
echo "installing: ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
"${sudo_cmd[@]}" apt-get update -qq
"${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
