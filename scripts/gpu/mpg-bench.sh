#!/usr/bin/env bash
# The mpg benchmark (Cherry & Kooima; issue 11): `penumbra bench` of the three alterations, the
# multi-pass kernel at max_kernel 9 / 19 / 29 (progressive and fixed), the single-pass Gaussian at
# the same maxima, with and without the umbra early-out, on colonnade and fence, at 1080p and 4K,
# first with the default (physical) D, then with D saturated (light_size_scale 10: every shadowed
# pixel takes the largest kernel / all passes, the per-pixel worst case the paper's cost claims
# are about). Then the Markdown tables and the target ratios (mpg_tables.py) in OUT_DIR/mpg.md.
#
#   scripts/gpu/mpg-bench.sh PENUMBRA_BINARY OUT_DIR
#   env: CONTEXT=egl  SIZES="1920x1080:2048 3840x2160:2048" (screen:shadow-map pairs)
#        SCENES=colonnade,fence  FRAMES=200  WARMUP=10
#
# On the GPU machine (docs/gpu-machine.md): source the bundle's env.sh and run with the bundled
# binary; CONTEXT=egl is the default. A size takes about 2-3 minutes on an H100; run the sizes as
# separate commands (SIZES=...) with the same OUT_DIR if one command must stay short, then
#   python3 scripts/gpu/mpg_tables.py OUT_DIR > OUT_DIR/mpg.md
# On llvmpipe (proves the script works; the numbers say nothing about a GPU):
#   CONTEXT=osmesa SIZES=160x90:512 FRAMES=3 WARMUP=1 scripts/gpu/mpg-bench.sh build/dev/cli/penumbra /tmp/mpg-bench
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
bin="${1:?usage: mpg-bench.sh PENUMBRA_BINARY OUT_DIR}"
out="${2:?usage: mpg-bench.sh PENUMBRA_BINARY OUT_DIR}"
context="${CONTEXT:-egl}"
sizes="${SIZES:-1920x1080:2048 3840x2160:2048}"
scenes="${SCENES:-colonnade,fence}"
frames="${FRAMES:-200}"
warmup="${WARMUP:-10}"
mkdir -p "$out"

# name|settings (on top of the defaults; debug views off). mpg_tables.py knows these names.
configs=(
  "pcf|alteration=pcf"
  "gaussian|alteration=gaussian"
  "multipass|alteration=multipass"
  "multipass_k9|alteration=multipass max_kernel=9"
  "multipass_k29|alteration=multipass max_kernel=29"
  "fixed_k9|alteration=multipass kernel_mode=fixed max_kernel=9"
  "fixed_k19|alteration=multipass kernel_mode=fixed max_kernel=19"
  "fixed_k29|alteration=multipass kernel_mode=fixed max_kernel=29"
  "gaussian_k9|alteration=gaussian max_kernel=9"
  "gaussian_k29|alteration=gaussian max_kernel=29"
  "multipass_early_out|alteration=multipass umbra_early_out=true"
  "sat_pcf|alteration=pcf light_size_scale=10"
  "sat_gaussian_k9|alteration=gaussian max_kernel=9 light_size_scale=10"
  "sat_gaussian|alteration=gaussian light_size_scale=10"
  "sat_gaussian_k29|alteration=gaussian max_kernel=29 light_size_scale=10"
  "sat_multipass_k9|alteration=multipass max_kernel=9 light_size_scale=10"
  "sat_multipass|alteration=multipass light_size_scale=10"
  "sat_multipass_k29|alteration=multipass max_kernel=29 light_size_scale=10"
  "sat_fixed_k19|alteration=multipass kernel_mode=fixed light_size_scale=10"
  "sat_multipass_early_out|alteration=multipass umbra_early_out=true light_size_scale=10"
)

"$bin" info --context "$context" > "$out/info.txt" 2>&1 || true
# One bench process per size for every configuration (--techniques items with their own
# settings), then one JSON per configuration for mpg_tables.py.
specs=()
names=()
for entry in "${configs[@]}"; do
  name="${entry%%|*}"
  label="mpg:$(echo "${entry#*|} debug_outputs=false" | tr ' ' ':')"
  specs+=("$label")
  names+=("$name=$label")
done
for pair in $sizes; do
  size="${pair%%:*}"
  shadow="${pair#*:}"
  dir="$out/${size}_s${shadow}"
  mkdir -p "$dir"
  echo "== $size shadow $shadow: ${#configs[@]} configurations" >&2
  "$bin" bench --context "$context" --techniques "$(IFS=,; echo "${specs[*]}")" --scenes "$scenes" --size "$size" \
    --shadow-size "$shadow" --frames "$frames" --warmup "$warmup" --json "$dir/bench.json" > "$dir/bench.txt" 2>&1 ||
    { echo "bench failed, see $dir/bench.txt" >&2; tail -5 "$dir/bench.txt" >&2; exit 1; }
  python3 "$here/split_bench.py" "$dir/bench.json" "$dir" "${names[@]}"
done
python3 "$here/mpg_tables.py" "$out" | tee "$out/mpg.md"
