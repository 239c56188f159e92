#!/usr/bin/env bash
# Builds the dev preset (Debug, strict GL error checks) and runs every test suite with ctest.
# Tests use OSMesa (llvmpipe), so no GPU and no display are needed.
set -euo pipefail
cd "$(dirname "$0")/.."
preset=${PENUMBRA_TEST_PRESET:-dev}
cmake --preset "$preset" >/dev/null
cmake --build --preset "$preset" -j "$(nproc)"
ctest --preset "$preset" -j "$(nproc)" --timeout 900
