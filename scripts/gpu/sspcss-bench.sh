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
# Every bench run uses the techniques' defaults otherwise. One run per configuration, both
# scenes in it.
#
#   scripts/gpu/sspcss-bench.sh PENUMBRA_BINARY OUTDIR
#   env: CONTEXT=egl FRAMES=200 WARMUP=10 SCENES=colonnade,fence
#        SHADOW_SIZES="1024 2048 4096 8192" SCREEN_SIZES="1280x720 1920x1080 2560x1440 3840x2160"
#        RADII="8 16 32" SIZE=1920x1080 (the screen of parts 1 and 3) SHADOW=2048 (parts 2 and 3)
#
# On the GPU machine (docs/gpu-machine.md): bundle here with
#   scripts/gpu/bundle.sh .gpu build/release/sandbox/penumbra
# then, in a device run carrying .gpu (21 bench runs; a few minutes of device time at FRAMES=200):
#   source .gpu/env.sh && scripts/gpu/sspcss-bench.sh .gpu/bin/penumbra $OUT/sspcss
# Writes OUTDIR/*.json (one per bench run), OUTDIR/info.txt and OUTDIR/sspcss-bench.md.
# A quick proof that it works on llvmpipe (numbers meaningless):
#   CONTEXT=osmesa FRAMES=2 WARMUP=1 SIZE=160x90 SHADOW=256 SHADOW_SIZES="256 512" \
#   SCREEN_SIZES="160x90 320x180" RADII="2 4" scripts/gpu/sspcss-bench.sh build/dev/sandbox/penumbra /tmp/sb
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

# bench NAME SIZE SHADOW TECHNIQUES [k=v]...
bench() {
  local name=$1 sz=$2 sh=$3 techniques=$4
  shift 4
  local sets=()
  for kv in "$@"; do sets+=(--set "$kv"); done
  echo "== $name: $techniques, $sz, shadow $sh ${*:-}" >&2
  "$bin" bench --context "$context" --techniques "$techniques" --scenes "$scenes" --size "$sz" \
    --shadow-size "$sh" --frames "$frames" --warmup "$warmup" ${sets[@]+"${sets[@]}"} \
    --json "$out/$name.json" > "$out/$name.txt"
}

for n in $shadow_sizes; do
  bench "shadow_$n" "$size" "$n" sspcss,pcss
  bench "shadow_${n}_centre" "$size" "$n" sspcss subpixel_hard_shadow=false
done
for s in $screen_sizes; do bench "screen_$s" "$s" "$shadow" sspcss,pcss; done
for r in $radii; do
  bench "radius_${r}_separable" "$size" "$shadow" sspcss filter=separable "fixed_radius_px=$r" receiver_footprint=false
  bench "radius_${r}_poisson" "$size" "$shadow" sspcss filter=poisson "fixed_radius_px=$r" receiver_footprint=false
  bench "radius_${r}_poisson64" "$size" "$shadow" sspcss filter=poisson poisson_taps=64 "fixed_radius_px=$r" \
    receiver_footprint=false
done

python3 "$here/sspcss_tables.py" "$out" --shadow-sizes "$shadow_sizes" --screen-sizes "$screen_sizes" \
  --radii "$radii" | tee "$out/sspcss-bench.md"
