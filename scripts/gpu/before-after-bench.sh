#!/usr/bin/env bash
# A speed change measured as the performance issues ask: two builds of `penumbra bench` in one
# device session, alternating (before, after, before, after) so drift shows as a spread, every
# technique at its defaults (debug views off: no method includes them), colonnade, 1080p and 4K,
# a 2048^2 shadow map. Each run's JSON (with the measured copy and fetch peaks) goes to OUT_DIR;
# scripts/report/bandwidth_report.py turns them into the before/after table and the roofline.
#
#   scripts/gpu/before-after-bench.sh BEFORE_PENUMBRA AFTER_PENUMBRA OUT_DIR
#   env: CONTEXT=egl  SIZES=1920x1080,3840x2160  SCENES=colonnade  FRAMES=200  WARMUP=10  ROUNDS=2
#        TECHNIQUES=hard,pcf,pcss,pmchss,mpg,sspcss,esm
# The two binaries may need different libpenumbra.so: BEFORE_LIB / AFTER_LIB name the folder
# each one's library is in (prepended to LD_LIBRARY_PATH for that binary).
# On llvmpipe (proves the script works; the numbers say nothing about a GPU):
#   CONTEXT=osmesa SIZES=160x90 FRAMES=3 WARMUP=1 ROUNDS=1 scripts/gpu/before-after-bench.sh A B /tmp/ab
set -euo pipefail
before="${1:?usage: before-after-bench.sh BEFORE_PENUMBRA AFTER_PENUMBRA OUT_DIR}"
after="${2:?usage: before-after-bench.sh BEFORE_PENUMBRA AFTER_PENUMBRA OUT_DIR}"
out="${3:?usage: before-after-bench.sh BEFORE_PENUMBRA AFTER_PENUMBRA OUT_DIR}"
context="${CONTEXT:-egl}" sizes="${SIZES:-1920x1080,3840x2160}" scenes="${SCENES:-colonnade}"
frames="${FRAMES:-200}" warmup="${WARMUP:-10}" rounds="${ROUNDS:-2}"
techniques="${TECHNIQUES:-hard,pcf,pcss,pmchss,mpg,sspcss,esm}"
mkdir -p "$out"
run() {  # run NAME BINARY LIBDIR
  local name=$1 bin=$2 lib=$3
  echo "[before-after] $name" >&2
  LD_LIBRARY_PATH="${lib:+$lib:}${LD_LIBRARY_PATH:-}" "$bin" bench --context "$context" --techniques "$techniques" \
    --scenes "$scenes" --size "$sizes" --shadow-size 2048 --frames "$frames" --warmup "$warmup" \
    --set debug_outputs=false --json "$out/$name.json" > "$out/$name.log" 2>&1 || { tail -20 "$out/$name.log" >&2; exit 1; }
}
for round in $(seq 1 "$rounds"); do
  run "before-$round" "$before" "${BEFORE_LIB:-}"
  run "after-$round" "$after" "${AFTER_LIB:-}"
done
echo "[before-after] done: $out" >&2
