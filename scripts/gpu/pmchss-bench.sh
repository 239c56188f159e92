#!/usr/bin/env bash
# Sterna 2018, Table 1 for pmchss: five `penumbra bench` runs (one technique configuration each)
# at 1920x1080, shadow 2048, scene colonnade, then the Table 1 markdown with the ratios.
#
#   scripts/gpu/pmchss-bench.sh [PENUMBRA_BINARY] [OUT_DIR]
#   env: SIZE=1920x1080 SHADOW=2048 SCENE=colonnade FRAMES=200 CONTEXT=egl
#        MASK_DIVISOR=4 (screen/4, the default) or 2 (screen/2: a quarter of the pixels, which
#        is what the paper's "quarter res" buffer holds)
#
# On the GPU machine: run with the bundled binary and CONTEXT=egl (the default). On llvmpipe
# (a proof that it works; the numbers say nothing about ratios): SIZE=320x180 CONTEXT=osmesa.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
bin="${1:-$here/../../build/release/cli/penumbra}"
out="${2:-pmchss-bench}"
size="${SIZE:-1920x1080}"
shadow="${SHADOW:-2048}"
scene="${SCENE:-colonnade}"
frames="${FRAMES:-200}"
context="${CONTEXT:-egl}"
mask_divisor="${MASK_DIVISOR:-4}"
mkdir -p "$out"

# name|settings: every row 16 filter taps, 32 blocker taps (Table 1's caption), no debug passes.
configs=(
  "regular_no_ch|variant=regular penumbra_mapping=fixed"
  "regular_chss|variant=regular"
  "penumbra_mask|variant=penumbra_mask"
  "regular_chss_checker|variant=regular checkerboard=true"
  "penumbra_mask_checker|variant=penumbra_mask checkerboard=true"
)
for entry in "${configs[@]}"; do
  name="${entry%%|*}"
  sets=()
  for kv in ${entry#*|} debug_outputs=false filter_samples=16 blocker_samples=32 \
            "mask_divisor=$mask_divisor"; do sets+=(--set "$kv"); done
  echo "== $name: ${entry#*|}" >&2
  "$bin" bench --techniques pmchss --scenes "$scene" --size "$size" --shadow-size "$shadow" \
    --frames "$frames" --context "$context" "${sets[@]}" --json "$out/$name.json"
done
python3 "$here/pmchss_table1.py" "$out" | tee "$out/table1.md"
