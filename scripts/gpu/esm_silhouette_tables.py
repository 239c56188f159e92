#!/usr/bin/env python3
"""The tables of docs/results/esm.md from what esm-silhouettes-bench.sh wrote.

usage: esm_silhouette_tables.py OUT_DIR
Medians over the rounds of each pass's median GPU time; "default" is what silhouette_finding=auto
picks (silhouette_buffers.h): compute above 4,096 quads over all instances (kComputeAboveQuads),
quads read from the bench log, or at 2048^2 and wider maps (kComputeFromMapSize); else all.
"""
import glob
import json
import os
import re
import statistics
import sys

COMPUTE_ABOVE_QUADS = 4096
COMPUTE_FROM_MAP_SIZE = 2048


def default_finding(quads, map_size):
    return "compute" if quads > COMPUTE_ABOVE_QUADS or map_size >= COMPUTE_FROM_MAP_SIZE else "all"


def name_of(scene):
    return os.path.basename(scene).split(".")[0]


def load(out, which):
    runs = {}
    for path in sorted(glob.glob(os.path.join(out, "cost", f"{which}-*.json"))):
        for row in json.load(open(path))["rows"]:
            technique = row["technique"].replace("esm:debug_outputs=false", "esm").replace("esm:silhouette_finding=", "esm/")
            passes = {p["name"]: p["ms"] for p in row["passes"] if not p["frame"]}
            runs.setdefault((name_of(row["scene"]), technique, row["shadow_size"]), []).append(passes)
    return {k: {n: statistics.median(r[n] for r in v) for n in v[0]} for k, v in runs.items()}


def quads_per_scene(out):
    """Quads per scene from the bench log's 'esm: N silhouette quads' lines, in scene order."""
    text = open(os.path.join(out, "cost", "after-1.txt")).read()
    scenes, quads = [], {}
    for m in re.finditer(r"bench \S+ on (.+?) \(.*?\n\[info\] esm: (\d+) silhouette quads", text):
        scene = name_of(m.group(1))
        if scene not in quads:
            scenes.append(scene)
            quads[scene] = int(m.group(2))
    return scenes, quads


def edge_rows(path):
    data = json.load(open(path))
    return {r["technique"]: r["edge_error"] for r in data.get("techniques", data.get("rows", []))}


def main():
    out = sys.argv[1]
    before, after = load(out, "before"), load(out, "after")
    scenes, quads = quads_per_scene(out)
    total = lambda passes: sum(passes.values())  # noqa: E731
    print("| scene | quads | silhouette pass before | all | gpu | compute | default | esm 512² before | esm 512² now | × "
          "| plain 512² | plain 2048² | now / plain 512² | now / plain 2048² |")
    print("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|")
    for s in scenes:
        pick = default_finding(quads[s], 512)
        now = after[(s, "esm/" + pick, 512)]
        was = before[(s, "esm", 512)]
        plain512, plain2048 = total(after[(s, "hard", 512)]), total(after[(s, "hard", 2048)])
        pass_ms = lambda variant: after[(s, "esm/" + variant, 512)]["silhouette_quads"]  # noqa: E731
        print(f"| {s} | {quads[s]:,} | {was['silhouette_quads']:.3f} | {pass_ms('all'):.3f} | {pass_ms('gpu'):.3f} "
              f"| {pass_ms('compute'):.3f} | {now['silhouette_quads']:.3f} ({pick}) "
              f"| {total(was):.3f} | {total(now):.3f} | {total(now) / total(was):.2f} | {plain512:.3f} | {plain2048:.3f} "
              f"| {total(now) / plain512:.2f} | {total(now) / plain2048:.3f} |")
    print()
    print("At 2048² (silhouette pass, ms; the default there is compute):")
    print()
    print("| scene | before | all | gpu | compute |")
    print("|---|---:|---:|---:|---:|")
    for s in scenes:
        cell = lambda which, t: f"{which[(s, t, 2048)]['silhouette_quads']:.3f}"  # noqa: E731
        print(f"| {s} | {cell(before, 'esm')} | {cell(after, 'esm/all')} | {cell(after, 'esm/gpu')} "
              f"| {cell(after, 'esm/compute')} |")
    print()
    print("| scene | esm 512² before | esm 512² now | compute | all | plain 512² | plain 2048² | now ≤ plain 512² "
          "| now / plain 2048² |")
    print("|---|---:|---:|---:|---:|---:|---:|---|---:|")
    for s in scenes:
        e512 = edge_rows(os.path.join(out, "edge", f"{s}_512.json"))
        e2048 = edge_rows(os.path.join(out, "edge", f"{s}_2048.json"))
        was = edge_rows(os.path.join(out, "edge", f"{s}_512_before.json"))["esm"]
        print(f"| {s} | {was:.4f} | {e512['esm']:.4f} | {e512.get('esm:silhouette_finding=compute', float('nan')):.4f} "
              f"| {e512.get('esm:silhouette_finding=all', float('nan')):.4f} | {e512['hard']:.4f} | {e2048['hard']:.4f} "
              f"| {'yes' if e512['esm'] <= e512['hard'] else 'no'} | {e512['esm'] / e2048['hard']:.2f} |")


if __name__ == "__main__":
    main()
