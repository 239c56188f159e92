#!/usr/bin/env bash
# esm's silhouette pass before and after a change, and esm at 512^2 against plain maps, as issue
# "ESM that keeps its promise on real meshes" asks: 11 scenes, 1080p, one device session.
#   scripts/gpu/esm-silhouettes-bench.sh BEFORE_PENUMBRA AFTER_PENUMBRA OUT_DIR [MODEL.gltf ...]
#   env: BEFORE_LIB / AFTER_LIB (the folder of each binary's libpenumbra.so), BEFORE_SHADERS (a tree of
#        the before commit, its PENUMBRA_SHADER_DIR: a binary reads the shaders and graphs of the source
#        tree it was built from where that path exists), CONTEXT=egl, SIZE=1920x1080,
#        FRAMES=100, ROUNDS=2, SCENES="fence ball poles colonnade palms showcase", PARTS="cost edge"
#        (one part per run where a device limits a command's time; the tables need both in OUT_DIR)
# Cost: `penumbra bench` of esm (debug views off) and hard at 512^2 and 2048^2, before and after
# alternating ROUNDS times; after also with silhouette_finding=gpu, =compute and =all. Edge error: `penumbra
# eval` against the exact hard shadow (light size 0, 4x4 samples a pixel) of esm (as auto picks, and
# with silhouette_finding=compute and =all, which must agree) and hard at 512^2,
# hard at 2048^2, and esm at 512^2 before. Then esm_silhouette_tables.py OUT_DIR writes the tables.
# On llvmpipe (checks that it runs; the numbers mean nothing): CONTEXT=osmesa SIZE=192x108 FRAMES=2 ROUNDS=1.
set -euo pipefail
before="${1:?usage: esm-silhouettes-bench.sh BEFORE AFTER OUT_DIR [MODEL ...]}"
after="${2:?usage: esm-silhouettes-bench.sh BEFORE AFTER OUT_DIR [MODEL ...]}"
out="${3:?usage: esm-silhouettes-bench.sh BEFORE AFTER OUT_DIR [MODEL ...]}"
shift 3
context="${CONTEXT:-egl}" frames="${FRAMES:-100}" rounds="${ROUNDS:-2}" size="${SIZE:-1920x1080}"
read -r -a scenes <<< "${SCENES-fence ball poles colonnade palms showcase}"
scenes+=("$@")
list="$(IFS=,; echo "${scenes[*]}")"
parts="${PARTS:-cost edge}"
mkdir -p "$out/cost" "$out/edge"
with_lib() {
  local lib=$1 shaders=""
  shift
  [ "$1" = "$before" ] && shaders="${BEFORE_SHADERS:-}"
  LD_LIBRARY_PATH="${lib:+$lib:}${LD_LIBRARY_PATH:-}" PENUMBRA_SHADER_DIR="${shaders:-${PENUMBRA_SHADER_DIR:-}}" "$@"
}
[[ " $parts " == *" cost "* ]] && for round in $(seq 1 "$rounds"); do
  for which in before after; do
    techniques=esm:debug_outputs=false,hard bin=$before lib="${BEFORE_LIB:-}"
    if [ "$which" = after ]; then
      techniques+=,esm:debug_outputs=false:silhouette_finding=gpu,esm:debug_outputs=false:silhouette_finding=compute
      techniques+=,esm:debug_outputs=false:silhouette_finding=all
      bin=$after lib="${AFTER_LIB:-}"
    fi
    echo "[esm-silhouettes] bench $which, round $round" >&2
    with_lib "$lib" "$bin" bench --context "$context" --techniques "$techniques" --scenes "$list" --size "$size" \
      --shadow-size 512,2048 --frames "$frames" --json "$out/cost/$which-$round.json" > "$out/cost/$which-$round.txt" 2>&1 ||
      { tail -20 "$out/cost/$which-$round.txt" >&2; exit 1; }
  done
done
edge() {  # edge NAME LIBDIR BINARY SCENE SIZE TECHNIQUES
  with_lib "$2" "$3" eval --context "$context" --scene "$4" --techniques "$6" --size "$size" --shadow-size "$5" \
    --frames 1 --light-size 0 --set pixel_samples=4 --no-cache --json "$out/edge/$1.json" > "$out/edge/$1.txt" 2>&1 ||
    { tail -20 "$out/edge/$1.txt" >&2; exit 1; }
}
[[ " $parts " == *" edge "* ]] && for scene in "${scenes[@]}"; do
  name="$(basename "$scene")"
  name="${name%.*}"
  echo "[esm-silhouettes] edge error on $name" >&2
  edge "${name}_512" "${AFTER_LIB:-}" "$after" "$scene" 512 esm,hard,esm:silhouette_finding=compute,esm:silhouette_finding=all
  edge "${name}_2048" "${AFTER_LIB:-}" "$after" "$scene" 2048 hard
  edge "${name}_512_before" "${BEFORE_LIB:-}" "$before" "$scene" 512 esm
done
"$after" info --context "$context" > "$out/info.txt" 2>&1 || true
[[ " $parts " == *" cost "* && " $parts " == *" edge "* ]] || exit 0
python3 "$(dirname "$0")/esm_silhouette_tables.py" "$out" | tee "$out/tables.md"
