#!/usr/bin/env python3
"""Turns the five pmchss `penumbra bench --json` files written by pmchss-bench.sh into the
rows of Sterna 2018's Table 1 (markdown) with the two ratios the paper discusses.

Pass groups (pass names in techniques/pmchss/pmchss.json):
  penumbra mask  = penumbra_mask_* (search, max filter, blur; at either resolution)
  shadow mask    = shadow_mask_* + checker_upsample
Excluded: shadow_map, gbuffer, lighting, min_*, debug_* (the same in every row or not in it).
usage: pmchss_table1.py DIR
"""
import json
import sys
from pathlib import Path

PAPER = {  # GTX 660, 1080p, 2048^2 (Table 1)
    "Regular Shadow Mask": 0.84, "Regular CHSS Shadow Mask": 1.72, "Penumbra Mask": 0.115,
    "Shadow Mask using Penumbra Mask": 0.62, "Penumbra Mask + Shadow Mask using Penumbra Mask": 0.74,
    "Regular CHSS Shadow Mask + Checkerboarding": 1.17,
    "Penumbra Mask + Shadow Mask using Penumbra Mask + Checkerboarding": 0.76,
}


def load(directory, name):
    data = json.loads((Path(directory) / f"{name}.json").read_text())
    rows = [r for r in data["rows"] if r["technique"] == "pmchss"]
    if len(rows) != 1:
        sys.exit(f"{name}.json: expected one pmchss row, found {len(rows)}")
    return data, rows[0]


def group(row, kind):
    total = 0.0
    for p in row["passes"]:
        n = p["name"]
        if kind == "mask" and n.startswith("penumbra_mask_"):
            total += p["ms"]
        if kind == "shadow" and (n.startswith("shadow_mask_") or n == "checker_upsample"):
            total += p["ms"]
    return total


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    d = sys.argv[1]
    meta, no_ch = load(d, "regular_no_ch")
    _, chss = load(d, "regular_chss")
    _, mask = load(d, "penumbra_mask")
    _, chss_cb = load(d, "regular_chss_checker")
    _, mask_cb = load(d, "penumbra_mask_checker")
    rows = [
        ("Regular Shadow Mask", group(no_ch, "shadow")),
        ("Regular CHSS Shadow Mask", group(chss, "shadow")),
        ("Penumbra Mask", group(mask, "mask")),
        ("Shadow Mask using Penumbra Mask", group(mask, "shadow")),
        ("Penumbra Mask + Shadow Mask using Penumbra Mask", group(mask, "mask") + group(mask, "shadow")),
        ("Regular CHSS Shadow Mask + Checkerboarding", group(chss_cb, "shadow")),
        ("Penumbra Mask + Shadow Mask using Penumbra Mask + Checkerboarding",
         group(mask_cb, "mask") + group(mask_cb, "shadow")),
    ]
    print(f"device: {meta.get('device', '?')}, renderer: {meta.get('renderer', '?')}, "
          f"scene {no_ch['scene']}, {no_ch['size']}, shadow {no_ch['shadow_size']}^2 (median ms per pass)\n")
    print("| Pass | ours (ms) | paper, GTX 660 (ms) |")
    print("|---|---:|---:|")
    for name, ms in rows:
        print(f"| {name} | {ms:.3f} | {PAPER[name]} |")
    both = rows[4][1]
    print()
    print("| Ratio | ours | paper | target |")
    print("|---|---:|---:|---:|")
    r1 = both / rows[0][1] if rows[0][1] > 0 else float("nan")
    r2 = both / rows[1][1] if rows[1][1] > 0 else float("nan")
    print(f"| (Penumbra Mask + Shadow Mask) / Regular Shadow Mask | {r1:.2f}x | 0.88x | <= 0.9x |")
    print(f"| (Penumbra Mask + Shadow Mask) / Regular CHSS | {r2:.2f}x | 0.43x | <= 0.45x |")


if __name__ == "__main__":
    main()
