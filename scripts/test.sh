#!/usr/bin/env bash
# Builds the dev preset (Debug, strict GL error checks) and runs every test suite with ctest
# (OSMesa, so no GPU and no display are needed; the bad-input corpus included); then builds the
# release preset's plugin checks only (penumbra_plugin_checks: libpenumbra, the executables, the
# test plugins) and runs the `plugin` tests there, where plugins and host must share one
# libpenumbra without the dev build's exported symbols (the out-of-tree example is installed and
# built in Release too); then a short round of each fuzz target (scripts/fuzz.sh, clang +
# ASan/UBSan).
#   PENUMBRA_FUZZ_SECONDS=0 skips the fuzz round; PENUMBRA_TEST_RELEASE=0 skips the release
#   plugin checks; PENUMBRA_TEST_PRESET picks another preset than dev for the full run.
set -euo pipefail
cd "$(dirname "$0")/.."
preset=${PENUMBRA_TEST_PRESET:-dev}
cmake --preset "$preset" >/dev/null
cmake --build --preset "$preset" -j "$(nproc)"
ctest --preset "$preset" -j "$(nproc)" --timeout 900
if [ "${PENUMBRA_TEST_RELEASE:-1}" != 0 ] && [ "$preset" != release ]; then
  cmake --preset release >/dev/null
  cmake --build --preset release -j "$(nproc)" --target penumbra_plugin_checks
  ctest --preset release -L plugin -j "$(nproc)" --timeout 900
fi
fuzz_seconds=${PENUMBRA_FUZZ_SECONDS:-60}
if [ "$fuzz_seconds" != 0 ]; then
  bash scripts/fuzz.sh "$fuzz_seconds"
fi
