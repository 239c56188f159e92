#!/usr/bin/env bash
# esm (Bujnak, extended shadow maps) against plain hard shadows on the GPU: cost of every pass
# (the silhouette-quad pass included) and edge error against the exact hard reference, side by
# side, with the issue's target ratios. Two scenes: the built-in colonnade and a glTF model.
#
#   scripts/gpu/esm-bench.sh PENUMBRA_BINARY OUT_DIR MODEL.gltf|glb
#   env: SIZE=1920x1080 FRAMES=200 CONTEXT=egl ESM_SIZES="512 1024 2048" HARD_SIZES="512 2048 4096"
#        PIXEL_SAMPLES=4 (the reference's K x K samples per pixel) SCENES="colonnade MODEL" (default)
#
# Per scene: one `penumbra bench` run over every shadow-map size (median of FRAMES frames, GPU
# timestamps) for the cost; per scene and size one `penumbra eval` run (--light-size 0: the exact hard shadow,
# ray-traced on the CPU with PIXEL_SAMPLES^2 rays per pixel, i.e. box-filtered edges) for the
# edge error. esm runs with debug_outputs=false (its debug views are not part of the method).
# Then esm_table.py writes OUT_DIR/esm.md. On llvmpipe, to check that it works (the numbers say
# nothing about a GPU): SIZE=192x108 FRAMES=3 CONTEXT=osmesa ESM_SIZES="64 128" HARD_SIZES="64 128 256".
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
bin="${1:?usage: esm-bench.sh PENUMBRA_BINARY OUT_DIR MODEL.gltf}"
out="${2:?usage: esm-bench.sh PENUMBRA_BINARY OUT_DIR MODEL.gltf}"
model="${3:-}"
size="${SIZE:-1920x1080}"
frames="${FRAMES:-200}"
context="${CONTEXT:-egl}"
esm_sizes="${ESM_SIZES:-512 1024 2048}"
hard_sizes="${HARD_SIZES:-512 2048 4096}"
pixel_samples="${PIXEL_SAMPLES:-4}"
if [ -n "${SCENES:-}" ]; then
  read -r -a scenes <<< "$SCENES"
else
  scenes=(colonnade)
  if [ -n "$model" ]; then scenes+=("$model"); else echo "esm-bench: no MODEL given, colonnade only" >&2; fi
fi
mkdir -p "$out"
"$bin" info --context "$context" > "$out/info.txt" 2>&1 || true

for scene in "${scenes[@]}"; do
  name="$(basename "$scene")"
  name="${name%.*}"
  # Every size either technique runs at: one eval each (the reference is traced once per run).
  all_sizes="$(printf '%s\n' $esm_sizes $hard_sizes | sort -n -u | tr '\n' ' ')"
  # The cost: one bench process for both techniques at every size (a few rows more than the
  # tables use), then a JSON per technique and size for esm_table.py.
  echo "== bench esm, hard on $name, $size, shadow $all_sizes" >&2
  "$bin" bench --context "$context" --techniques esm:debug_outputs=false,hard --scenes "$scene" --size "$size" \
    --shadow-size "$(echo $all_sizes | tr ' ' ',')" --frames "$frames" --json "$out/bench_${name}.json" > "$out/bench_${name}.txt"
  names=()
  for n in $esm_sizes; do names+=("bench_${name}_esm_${n}=esm:debug_outputs=false@shadow=$n"); done
  for n in $hard_sizes; do names+=("bench_${name}_hard_${n}=hard@shadow=$n"); done
  python3 "$here/split_bench.py" "$out/bench_${name}.json" "$out" "${names[@]}"
  for n in $all_sizes; do
    techniques=()
    [[ " $esm_sizes " == *" $n "* ]] && techniques+=(esm)
    [[ " $hard_sizes " == *" $n "* ]] && techniques+=(hard)
    list="$(IFS=,; echo "${techniques[*]}")"
    debug=()
    [[ " $esm_sizes " == *" $n "* ]] && debug=(--set debug_outputs=false)  # only esm has the key
    echo "== eval $list on $name, $size, shadow $n (exact hard reference, ${pixel_samples}x${pixel_samples} rays a pixel)" >&2
    "$bin" eval --context "$context" --scene "$scene" --techniques "$list" --size "$size" --shadow-size "$n" \
      --frames 3 --light-size 0 --set "pixel_samples=$pixel_samples" "${debug[@]}" \
      --json "$out/eval_${name}_${n}.json" > "$out/eval_${name}_${n}.txt"
  done
done
python3 "$here/esm_table.py" "$out" --esm-sizes "$esm_sizes" --hard-sizes "$hard_sizes" \
  --size "$size" --pixel-samples "$pixel_samples" | tee "$out/esm.md"
