#!/usr/bin/env bash
# The results suite behind docs/results/README.md: every technique and main variant on every
# built-in scene and the given glTF models, against the ray-traced reference, timed on the device.
# Writes raw JSON and PNGs into OUT_DIR; scripts/report/make-report.py turns them into the report.
#
#   scripts/report/run-suite.sh PENUMBRA_BINARY OUT_DIR [MODEL.gltf|glb ...]
#   env: CONTEXT=egl (osmesa on a CPU), QUICK=1 (tiny sizes and frame counts: checks that the
#        suite runs, on llvmpipe, in a minute; its numbers mean nothing),
#        SCENES="fence ball" (the built-in scenes to run; default all seven; models come as arguments),
#        SIX_FACE_SCENES="room" (those lit by a point light inside them: no pmchss min-filter row),
#        COST=1|0|only (the cost sweep below: with the scenes, skipped, or alone). The device
#        allows 10 minutes a command: run the suite in parts into one OUT_DIR.
#        STEPS="eval edge flicker gallery bench" (the per-scene steps to run; default all: e.g.
#        STEPS=bench times the scenes again into an OUT_DIR that holds the rest).
#
# Per scene (progress on stderr, one line per step):
#   eval/   1920x1080, 2048^2 map: penumbra RMSE, SSIM, ... of every variant (ray-traced, RAYS)
#   edge/   the hard-shadow techniques against the exact hard reference (light size 0, 4x4
#           samples per pixel): edge error; edge512/ esm with a 512^2 map
#   flicker_pan/, flicker_light/   960x540: temporal change over 6 frames of a 0.25 deg/frame
#           camera pan / light motion, minus the reference's
#   gallery/  480x270: each variant's mask and error heat map, and the reference's mask
#   bench/  1920x1080, 2048^2: median GPU ms of each pass over FRAMES frames after 10 warm-up, of
#           every variant and of pcf and pcss over the classifier's penumbra tiles (tiles=true)
# Once: cost/ every cost variant on colonnade at 720p/1080p/4K x 1024^2/2048^2/4096^2 maps.
# Timings run with debug_outputs=false (debug views are not part of any method).
set -euo pipefail
bin="${1:?usage: run-suite.sh PENUMBRA_BINARY OUT_DIR [MODEL.gltf ...]}"
out="${2:?usage: run-suite.sh PENUMBRA_BINARY OUT_DIR [MODEL.gltf ...]}"
shift 2
context="${CONTEXT:-egl}"
read -r -a scenes <<< "${SCENES-fence ball poles colonnade palms room showcase}"
SIX_FACE_SCENES="${SIX_FACE_SCENES-room}"
scenes+=("$@")
cost_part="${COST:-1}"
[ "$cost_part" = only ] && scenes=()
steps=" ${STEPS:-eval edge flicker gallery bench} "
step() { [[ $steps == *" $1 "* ]]; }

# What the report compares. Quality: every technique at its defaults, its paper preset and its
# main variants. Cost: the same, plus Sterna's Table 1 rows (regular shadow mask = fixed kernel).
soft="hard,pcf,pcss,pmchss,pmchss:variant=regular,pmchss:variant=min_filter,pmchss@paper"
soft+=",mpg,mpg:alteration=gaussian,mpg:alteration=pcf,mpg@paper,sspcss,sspcss:filter=poisson,sspcss@paper,esm"
hard="hard,esm,esm@paper"
# Timed only: their masks are pcf's and pcss's (tests/baseline/tiled_filters_test.cpp).
tiled="pcf:tiles=true,pcss:tiles=true"
cost="hard,pcf,pcss,pmchss,pmchss:variant=regular,pmchss:variant=regular:penumbra_mapping=fixed"
cost+=",mpg,mpg:alteration=gaussian,sspcss,sspcss:filter=poisson,esm,pcss:tiles=true"
# MPG's claim: cost flat in the kernel size (every pixel at the largest kernel: kernel_mode=fixed).
cost+=",mpg:kernel_mode=fixed:max_kernel=9,mpg:kernel_mode=fixed:max_kernel=19,mpg:kernel_mode=fixed:max_kernel=29"

if [ "${QUICK:-0}" = 1 ]; then
  size=160x90 flicker_size=160x90 gallery_size=160x90 rays=8 frames=3 flicker_frames=2
  cost_sizes=160x90,192x108 cost_maps=256,512
else
  size=1920x1080 flicker_size=960x540 gallery_size=480x270 rays=128 frames=200 flicker_frames=6
  cost_sizes=1280x720,1920x1080,3840x2160 cost_maps=1024,2048,4096
fi

mkdir -p "$out"/{eval,edge,edge512,flicker_pan,flicker_light,gallery,bench,cost}
started=$(date +%s)
log() { echo "[suite $(($(date +%s) - started))s] $*" >&2; }
run() {  # a step's output goes to its log; a failure stops the suite and shows the log's end
  local logfile="$1"
  shift
  if ! "$@" > "$logfile" 2>&1; then
    echo "run-suite: failed: $*" >&2
    tail -20 "$logfile" >&2
    exit 1
  fi
}

{
  echo "date: $(date -u +%Y-%m-%dT%H:%MZ)"
  "$bin" info --context "$context" 2>&1
} > "$out/device.txt"
log "device: $(grep -m1 -i renderer "$out/device.txt" || echo unknown)"

i=0
for scene in "${scenes[@]}"; do
  i=$((i + 1))
  name="$(basename "$scene")"
  name="${name%.*}"
  common=(--context "$context" --scene "$scene" --frames 1)
  # Scenes lit by a point light inside them (six faces): pmchss's min-filter variant refuses them.
  soft_all="$soft"
  case " $SIX_FACE_SCENES " in *" $name "*) soft="${soft/,pmchss:variant=min_filter/}" ;; esac
  if step eval; then
    log "$i/${#scenes[@]} $name: quality at $size"
    run "$out/eval/$name.log" "$bin" eval "${common[@]}" --techniques "$soft" --size "$size" --rays "$rays" \
      --json "$out/eval/$name.json"
  fi
  if step edge; then
    log "$i/${#scenes[@]} $name: edge error against the exact hard shadow"
    run "$out/edge/$name.log" "$bin" eval "${common[@]}" --techniques "$hard" --size "$size" --light-size 0 \
      --set pixel_samples=4 --json "$out/edge/$name.json"
    log "$i/${#scenes[@]} $name: edge error of esm with a 512^2 map"
    run "$out/edge512/$name.log" "$bin" eval "${common[@]}" --techniques esm --size "$size" --light-size 0 \
      --set pixel_samples=4 --shadow-size 512 --json "$out/edge512/$name.json"
  fi
  if step flicker; then
    for motion in pan light; do
      log "$i/${#scenes[@]} $name: flicker ($motion) at $flicker_size"
      run "$out/flicker_$motion/$name.log" "$bin" eval "${common[@]}" --techniques "$soft" --size "$flicker_size" \
        --rays $((rays / 2)) --flicker "$motion" --flicker-frames "$flicker_frames" --json "$out/flicker_$motion/$name.json"
    done
  fi
  if step gallery; then
    log "$i/${#scenes[@]} $name: gallery at $gallery_size"
    run "$out/gallery/$name.log" "$bin" eval "${common[@]}" --techniques "$soft" --size "$gallery_size" --rays "$rays" \
      --masks "$out/gallery" --heatmaps "$out/gallery" --json "$out/gallery/$name.json"
  fi
  if step bench; then
    log "$i/${#scenes[@]} $name: GPU time, $frames frames"
    run "$out/bench/$name.log" "$bin" bench --context "$context" --scenes "$scene" --techniques "$soft,$tiled" \
      --size "$size" --shadow-size 2048 --frames "$frames" --set debug_outputs=false --json "$out/bench/$name.json"
  fi
  soft="$soft_all"
done
if [ "$cost_part" = 0 ]; then log "done: $out"; exit 0; fi
log "cost: colonnade at $cost_sizes x $cost_maps"
run "$out/cost/colonnade.log" "$bin" bench --context "$context" --scenes colonnade --techniques "$cost" \
  --size "$cost_sizes" --shadow-size "$cost_maps" --frames "$frames" --set debug_outputs=false \
  --json "$out/cost/colonnade.json"
log "done: $out"
