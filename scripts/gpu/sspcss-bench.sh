#!/usr/bin/env bash
# The sspcss benchmark of issue 12 (screen-space PCSS, MohammadBagher et al.): `penumbra bench`
# runs through EGL on colonnade and fence, then the Markdown tables with the target ratios
# (sspcss_tables.py):
#   1. shadow maps 1024^2 .. 8192^2 at 1920x1080, sspcss and pcss (the paper: sspcss nearly
#      independent of the map size; target: its passes change <= 10% from 1024^2 to 8192^2);
#      sspcss also with subpixel_hard_shadow=false (one shadow-map sample per pixel, the paper's
#      hard shadow, instead of the default 2x2);
#   2. screens 1280x720 .. 3840x2160 with a 2048^2 map, sspcss and pcss (the paper: linear in
#      pixels);
#   3. separable vs Poisson filters at fixed 8, 16 and 32-pixel radii (fixed_radius_px, round
#      kernels: receiver_footprint=false), 1080p, 2048^2 (targets: separable <= 0.3x Poisson at
#      32 px; separable at 32 px <= 1.2x at 8 px). Poisson at its default 32 taps and at 64.
# Every bench run uses the techniques' defaults otherwise. One bench process per part, both
# scenes in it.
#
#   scripts/gpu/sspcss-bench.sh PENUMBRA_BINARY OUTDIR
#   env: CONTEXT=egl FRAMES=200 WARMUP=10 SCENES=colonnade,fence
#        SHADOW_SIZES="1024 2048 4096 8192" SCREEN_SIZES="1280x720 1920x1080 2560x1440 3840x2160"
#        RADII="8 16 32" SIZE=1920x1080 (the screen of parts 1 and 3) SHADOW=2048 (parts 2 and 3)
#
# On the GPU machine (docs/gpu-machine.md): bundle here with
#   scripts/gpu/bundle.sh .gpu build/release/cli/penumbra
# then, in a device run carrying .gpu (3 bench processes; a few minutes of device time at FRAMES=200):
#   source .gpu/env.sh && scripts/gpu/sspcss-bench.sh .gpu/bin/penumbra $OUT/sspcss
# Writes OUTDIR/*.json (one per bench run), OUTDIR/info.txt and OUTDIR/sspcss-bench.md.
# A quick proof that it works on llvmpipe (numbers meaningless):
#   CONTEXT=osmesa FRAMES=2 WARMUP=1 SIZE=160x90 SHADOW=256 SHADOW_SIZES="256 512" \
#   SCREEN_SIZES="160x90 320x180" RADII="2 4" scripts/gpu/sspcss-bench.sh build/dev/cli/penumbra /tmp/sb
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
bin="${1:?usage: sspcss-bench.sh PENUMBRA_BINARY OUTDIR}"
out="${2:?usage: sspcss-bench.sh PENUMBRA_BINARY OUTDIR}"
context="${CONTEXT:-egl}"
frames="${FRAMES:-200}"
warmup="${WARMUP:-10}"
scenes="${SCENES:-colonnade,fence}"
size="${SIZE:-1920x1080}"
shadow="${SHADOW:-2048}"
shadow_sizes="${SHADOW_SIZES:-1024 2048 4096 8192}"
screen_sizes="${SCREEN_SIZES:-1280x720 1920x1080 2560x1440 3840x2160}"
radii="${RADII:-8 16 32}"
mkdir -p "$out"

"$bin" info --context "$context" > "$out/info.txt"

# bench NAME --techniques ... --size ... --shadow-size ...: one process for a whole part (its
# configurations are --techniques items with their own settings, its sizes lists), then one JSON
# per configuration for sspcss_tables.py (split_bench.py).
bench() {
  local name=$1
  shift
  echo "== $name: $*" >&2
  "$bin" bench --context "$context" --scenes "$scenes" --frames "$frames" --warmup "$warmup" "$@" \
    --json "$out/$name.json" > "$out/$name.txt" 2>&1 || { tail -5 "$out/$name.txt" >&2; exit 1; }
}
list() { echo "$*" | tr ' ' ','; }

centre="sspcss:subpixel_hard_shadow=false"
bench part_shadow --techniques "sspcss,pcss,$centre" --size "$size" --shadow-size "$(list $shadow_sizes)"
names=()
for n in $shadow_sizes; do names+=("shadow_$n=sspcss+pcss@shadow=$n" "shadow_${n}_centre=$centre@shadow=$n"); done
python3 "$here/split_bench.py" "$out/part_shadow.json" "$out" "${names[@]}"

bench part_screen --techniques sspcss,pcss --size "$(list $screen_sizes)" --shadow-size "$shadow"
names=()
for s in $screen_sizes; do names+=("screen_$s=sspcss+pcss@size=$s"); done
python3 "$here/split_bench.py" "$out/part_screen.json" "$out" "${names[@]}"

specs=()
names=()
for r in $radii; do
  fixed="fixed_radius_px=$r:receiver_footprint=false"
  for variant in "separable|filter=separable" "poisson|filter=poisson" "poisson64|filter=poisson:poisson_taps=64"; do
    label="sspcss:${variant#*|}:$fixed"
    specs+=("$label")
    names+=("radius_${r}_${variant%%|*}=$label")
  done
done
bench part_radius --techniques "$(IFS=,; echo "${specs[*]}")" --size "$size" --shadow-size "$shadow"
python3 "$here/split_bench.py" "$out/part_radius.json" "$out" "${names[@]}"

python3 "$here/sspcss_tables.py" "$out" --shadow-sizes "$shadow_sizes" --screen-sizes "$screen_sizes" \
  --radii "$radii" | tee "$out/sspcss-bench.md"
