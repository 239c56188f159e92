#!/usr/bin/env bash
# Quality must not move with a speed change: every technique at its defaults on every built-in
# scene, penumbra RMSE against the ray-traced reference, by two builds of the CLI on the same
# frames. Prints a Markdown table (before, after, relative change) and fails when a change
# exceeds LIMIT percent (default 2).
#   scripts/report/compare-quality.sh BEFORE_PENUMBRA AFTER_PENUMBRA OUT_DIR
# SIZE (default 480x270), RAYS (default 64), SCENES, TECHNIQUES and CONTEXT (default osmesa)
# override the defaults. Both builds share one reference cache (PENUMBRA_CACHE_DIR in OUT_DIR),
# so they are compared with the same ground truth. A binary reads technique graphs and shaders
# from its own source tree when that tree exists: build "before" in a separate worktree
# (git worktree add ../before COMMIT), not from a checkout that has moved on.
set -euo pipefail
before="${1:?usage: compare-quality.sh BEFORE_PENUMBRA AFTER_PENUMBRA OUT_DIR}"
after="${2:?usage: compare-quality.sh BEFORE_PENUMBRA AFTER_PENUMBRA OUT_DIR}"
out="${3:?usage: compare-quality.sh BEFORE_PENUMBRA AFTER_PENUMBRA OUT_DIR}"
size="${SIZE:-480x270}" rays="${RAYS:-64}" context="${CONTEXT:-osmesa}" limit="${LIMIT:-2}"
read -r -a scenes <<< "${SCENES:-fence ball poles colonnade palms room showcase}"
techniques="${TECHNIQUES:-hard,pcf,pcss,pmchss,mpg,sspcss,esm}"
mkdir -p "$out/before" "$out/after"
export PENUMBRA_CACHE_DIR="$out/reference-cache"
for scene in "${scenes[@]}"; do
  for build in before after; do
    bin=$before
    [ "$build" = after ] && bin=$after
    echo "[compare-quality] $build: $scene ($size, $rays rays)" >&2
    "$bin" eval --context "$context" --scene "$scene" --techniques "$techniques" --size "$size" --rays "$rays" \
      --frames 1 --json "$out/$build/$scene.json" > "$out/$build/$scene.log" 2>&1 ||
      { tail -20 "$out/$build/$scene.log" >&2; exit 1; }
  done
done
python3 "$(dirname "$0")/quality_table.py" "$out/before" "$out/after" "$limit"
