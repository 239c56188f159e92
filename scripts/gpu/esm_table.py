#!/usr/bin/env python3
"""Turns the `penumbra bench --json` and `penumbra eval --json` files written by esm-bench.sh into
one Markdown page: per scene, esm at each shadow-map size and plain hard shadows at each size, with
the median GPU time of every pass of the technique (the G-buffer and the lighting, the same for
both, left out), their sum, and the edge error against the exact hard reference; then the
targets of issue 13 as ratios from the same run:
  esm 512^2 cost <= 1.3 x hard 512^2;  esm 512^2 cost < hard 2048^2;
  esm 512^2 edge error <= hard 2048^2 edge error.
usage: esm_table.py DIR --esm-sizes "512 1024 2048" --hard-sizes "512 2048 4096" [--size WxH] [--pixel-samples K]
"""
import argparse
import json
import sys
from pathlib import Path

FRAME_PASSES = {"gbuffer", "lighting"}  # the frame's prologue and epilogue, shared by every technique


def load_bench(d, scene, technique, size):
    path = Path(d) / f"bench_{scene}_{technique}_{size}.json"
    data = json.loads(path.read_text())
    rows = [r for r in data["rows"] if r["technique"].split(":")[0] == technique]
    if len(rows) != 1:
        sys.exit(f"{path}: expected one {technique} row, found {len(rows)}")
    passes = [(p["name"], p["ms"]) for p in rows[0]["passes"] if p["name"] not in FRAME_PASSES]
    return data, passes


def load_eval(d, scene, technique, size):
    path = Path(d) / f"eval_{scene}_{size}.json"
    data = json.loads(path.read_text())
    for r in data["rows"]:
        if r["technique"].split(":")[0] == technique:
            return r
    sys.exit(f"{path}: no {technique} row")


def scenes_in(d):
    names = set()
    for p in Path(d).glob("bench_*_*_*.json"):
        stem = p.stem[len("bench_"):]
        names.add(stem.rsplit("_", 2)[0])
    return sorted(names)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("dir")
    ap.add_argument("--esm-sizes", default="512 1024 2048")
    ap.add_argument("--hard-sizes", default="512 2048 4096")
    ap.add_argument("--size", default="1920x1080")
    ap.add_argument("--pixel-samples", default="4")
    a = ap.parse_args()
    esm_sizes = [int(s) for s in a.esm_sizes.split()]
    hard_sizes = [int(s) for s in a.hard_sizes.split()]
    out = []
    meta = None
    for scene in scenes_in(a.dir):
        rows = []
        for technique, sizes in (("esm", esm_sizes), ("hard", hard_sizes)):
            for n in sizes:
                meta, passes = load_bench(a.dir, scene, technique, n)
                e = load_eval(a.dir, scene, technique, n)
                rows.append({"technique": technique, "size": n, "passes": passes,
                             "total": sum(ms for _, ms in passes), "edge": e["edge_error"], "rmse": e["rmse"]})
        out.append(f"### {scene}\n")
        out.append("| technique | shadow map | passes (median ms) | total ms | edge error | RMSE |")
        out.append("|---|---|---|---|---|---|")
        for r in rows:
            passes = ", ".join(f"{name} {ms:.3f}" for name, ms in r["passes"])
            out.append(f"| {r['technique']} | {r['size']}² | {passes} | {r['total']:.3f} | {r['edge']:.4f} | {r['rmse']:.4f} |")
        by = {(r["technique"], r["size"]): r for r in rows}
        lo_esm, lo_hard = min(esm_sizes), min(hard_sizes)
        hi_hard = sorted(hard_sizes)[len(hard_sizes) // 2] if len(hard_sizes) > 1 else lo_hard  # 2048 of 512/2048/4096
        e, h_lo, h_hi = by[("esm", lo_esm)], by[("hard", lo_hard)], by[("hard", hi_hard)]
        out.append("")
        out.append("| target | value | met |")
        out.append("|---|---|---|")
        c1 = e["total"] / h_lo["total"] if h_lo["total"] > 0 else float("inf")
        c2 = e["total"] / h_hi["total"] if h_hi["total"] > 0 else float("inf")
        out.append(f"| cost esm {lo_esm}² / hard {lo_hard}² ≤ 1.3 | {c1:.2f} | {'yes' if c1 <= 1.3 else 'no'} |")
        out.append(f"| cost esm {lo_esm}² / hard {hi_hard}² < 1 | {c2:.2f} | {'yes' if c2 < 1.0 else 'no'} |")
        out.append(f"| edge error esm {lo_esm}² ({e['edge']:.4f}) ≤ hard {hi_hard}² ({h_hi['edge']:.4f}) | "
                   f"{e['edge'] / h_hi['edge'] if h_hi['edge'] > 0 else float('inf'):.2f}× | "
                   f"{'yes' if e['edge'] <= h_hi['edge'] else 'no'} |")
        out.append("")
    head = [f"{meta['device']} — {meta['renderer']}, {a.size}; times: median per pass over the measured frames "
            f"(`penumbra bench`); edge error: `penumbra eval --light-size 0 --set pixel_samples={a.pixel_samples}` "
            "(mean |mask - reference| within 3 px of a reference edge, docs/evaluation.md).", ""] if meta else []
    print("\n".join(head + out))


if __name__ == "__main__":
    main()
