#!/usr/bin/env bash
# Builds the dev preset (Debug, strict GL error checks) and runs every test suite with ctest
# (OSMesa, so no GPU and no display are needed; the bad-input corpus included), then a short
# round of each fuzz target (scripts/fuzz.sh, clang + ASan/UBSan).
#   PENUMBRA_FUZZ_SECONDS=0 skips the fuzz round; PENUMBRA_TEST_PRESET picks another preset.
set -euo pipefail
cd "$(dirname "$0")/.."
preset=${PENUMBRA_TEST_PRESET:-dev}
cmake --preset "$preset" >/dev/null
cmake --build --preset "$preset" -j "$(nproc)"
ctest --preset "$preset" -j "$(nproc)" --timeout 900
fuzz_seconds=${PENUMBRA_FUZZ_SECONDS:-60}
if [ "$fuzz_seconds" != 0 ]; then
  bash scripts/fuzz.sh "$fuzz_seconds"
fi
