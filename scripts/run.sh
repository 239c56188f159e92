#!/usr/bin/env bash
# The main job: builds the release preset, then starts the sandbox when a display exists, or
# renders the built-in showcase scene headless into out/ when none does.
set -euo pipefail
cd "$(dirname "$0")/.."
cmake --preset release >/dev/null
cmake --build --preset release -j "$(nproc)"
bin=build/release/sandbox
if [ -n "${DISPLAY:-}${WAYLAND_DISPLAY:-}" ] && [ -x "$bin/penumbra-sandbox" ]; then
  exec "$bin/penumbra-sandbox" "$@"
fi
mkdir -p out
"$bin/penumbra" info
if "$bin/penumbra" --help | grep -q '^  render'; then
  "$bin/penumbra" render --scene showcase --all-techniques --out-dir out "$@"
fi
