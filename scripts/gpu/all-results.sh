#!/usr/bin/env bash
# Everything we measure on the GPU machine, in one run (device time is scarce):
#   pm-CHSS Table 1 (scripts/gpu/pmchss-bench.sh: 1080p with the screen/4 and screen/2 mask,
#   1440p, 4K with a 4096^2 map), the bench of every technique on the four
#   test scenes, and the eval tables against the ray-traced reference at 1080p.
# usage (on the GPU machine, from the checkout with .gpu carried):
#   source .gpu/env.sh && scripts/gpu/all-results.sh .gpu/bin/penumbra OUTDIR
set -uo pipefail
bin=${1:?penumbra binary}
out=${2:?output directory}
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
mkdir -p "$out/pmchss" "$out/eval"
"$bin" info --context egl > "$out/info.txt"
CONTEXT=egl "$here/pmchss-bench.sh" "$bin" "$out/pmchss" || echo "pmchss-bench failed: $?"
MASK_DIVISOR=2 CONTEXT=egl "$here/pmchss-bench.sh" "$bin" "$out/pmchss-half" || echo "pmchss-bench half failed: $?"
SIZE=2560x1440 CONTEXT=egl "$here/pmchss-bench.sh" "$bin" "$out/pmchss-1440" || echo "pmchss-bench 1440 failed: $?"
SIZE=3840x2160 SHADOW=4096 CONTEXT=egl "$here/pmchss-bench.sh" "$bin" "$out/pmchss-2160" || echo "pmchss-bench 2160 failed: $?"
"$bin" bench --context egl --techniques hard,pcf,pcss,pmchss --scenes colonnade,ball,fence,poles \
  --size 1920x1080 --shadow-size 2048 --frames 200 --json "$out/bench.json" > "$out/bench.txt" 2>&1
for s in ball fence poles colonnade; do
  "$bin" eval --context egl --scene "$s" --techniques hard,pcf,pcss,pmchss --reference raytraced \
    --size 1920x1080 --shadow-size 2048 --frames 60 --json "$out/eval/$s.json" > "$out/eval/$s.txt" 2>&1
done
