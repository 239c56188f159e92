#!/usr/bin/env bash
# Builds the libFuzzer targets (the `fuzz` preset: clang, ASan + UBSan) and runs each for
# SECONDS (default 60), seeded from tests/fuzz/seeds and the shipped graph files, with its
# dictionary. A crash, leak or UB report fails the script (exit 1) and leaves the input that
# triggered it in build/fuzz/crashes/. The test command runs a short round; a longer one:
#   scripts/fuzz.sh 600
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-60}
cmake --preset fuzz >/dev/null
cmake --build --preset fuzz -j "$(nproc)"
work=build/fuzz/run
rm -rf "$work"
mkdir -p "$work" build/fuzz/crashes
status=0
for target in graph gltf script preset reference_cache; do
  corpus="$work/$target"
  mkdir -p "$corpus"
  cp tests/fuzz/seeds/"$target"/* "$corpus"/
  if [ "$target" = graph ]; then
    for f in techniques/*/*.json docs/graph-examples/*.json; do cp "$f" "$corpus/$(echo "$f" | tr / _)"; done
  fi
  echo "fuzz_$target: ${seconds}s" >&2
  if ! build/fuzz/tests/fuzz/fuzz_"$target" "$corpus" -dict=tests/fuzz/"$target".dict \
       -max_total_time="$seconds" -max_len=65536 -timeout=10 -rss_limit_mb=2048 \
       -artifact_prefix=build/fuzz/crashes/"$target"- -print_final_stats=1 >"$work/$target.log" 2>&1; then
    echo "fuzz_$target FAILED; the input is in build/fuzz/crashes/, the log in $work/$target.log:" >&2
    tail -40 "$work/$target.log" >&2
    status=1
  else
    grep -E "stat::number_of_executed_units|cov:" "$work/$target.log" | tail -2 >&2 || true
  fi
done
exit $status
