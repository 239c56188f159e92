#!/usr/bin/env bash
# The main job: builds the release preset, then starts the sandbox when a display exists, or
# renders the built-in showcase scene with every technique into out/ when none does (the
# reference is ray-traced there, so its image is exact rather than a progressive average).
# PENUMBRA_BUILD_DIR=DIR runs an existing build instead (tests run the dev build this way).
set -euo pipefail
cd "$(dirname "$0")/.."
build=${PENUMBRA_BUILD_DIR:-}
if [ -z "$build" ]; then
  cmake --preset release >/dev/null
  cmake --build --preset release -j "$(nproc)"
  build=build/release
fi
# The showcase unless the command line names a scene itself.
scene=(--scene showcase)
for arg in "$@"; do
  case $arg in --scene|--scene=*) scene=() ;; esac
done
if [ -n "${DISPLAY:-}${WAYLAND_DISPLAY:-}" ]; then
  exec "$build/sandbox/penumbra-sandbox" "${scene[@]}" "$@"
fi
echo "no display: rendering ${scene[1]:-the given scene} headless into out/ (the sandbox needs a display)"
"$build/cli/penumbra" info
"$build/cli/penumbra" render "${scene[@]}" --all-techniques --out-dir out --set method=raytraced "$@"
ls out/
