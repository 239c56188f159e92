#!/usr/bin/env python3
"""Turns the `penumbra bench --json` files written by sspcss-bench.sh into the Markdown tables of
issue 12 with its target ratios.

Pass groups (pass names in techniques/sspcss/sspcss.json and techniques/baseline/pcss.json):
  technique passes  every pass but gbuffer, lighting and shadow_map (the shadow map is a raster
                    pass whose cost grows with the map on any technique: reported on its own)
  sspcss search     blocker_search_*; sspcss filter: shadow_filter_*; preparation: prepare
usage: sspcss_tables.py DIR --shadow-sizes "1024 ..." --screen-sizes "1280x720 ..." --radii "8 16 32"
"""
import argparse
import json
import sys
from pathlib import Path

FRAME = {"gbuffer", "lighting"}


def load(directory, name):
    path = Path(directory) / f"{name}.json"
    if not path.exists():
        sys.exit(f"{path}: missing (did its bench run fail? see {name}.txt)")
    return json.loads(path.read_text())


def row(data, technique, scene):
    for r in data["rows"]:
        if r["technique"].split(":")[0] == technique and r["scene"] == scene:
            return r
    sys.exit(f"no row for {technique} on {scene}")


def group(r, kind):
    """Sum of the pass medians (ms) of one group of a bench row."""
    total = 0.0
    for p in r["passes"]:
        n = p["name"]
        if n in FRAME:
            continue
        if (kind == "technique" and n != "shadow_map") or (kind == "shadow_map" and n == "shadow_map") \
                or (kind == "search" and n.startswith("blocker_search")) \
                or (kind == "filter" and n.startswith("shadow_filter")) or (kind == "prepare" and n == "prepare"):
            total += p["ms"]
    return total


def verdict(value, limit):
    return f"{value:.2f} ({'meets' if value <= limit else 'misses'} <= {limit})"


def megapixels(size):
    w, h = (int(v) for v in size.split("x"))
    return w * h / 1e6


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("dir")
    ap.add_argument("--shadow-sizes", required=True)
    ap.add_argument("--screen-sizes", required=True)
    ap.add_argument("--radii", required=True)
    a = ap.parse_args()
    shadows, screens, radii = a.shadow_sizes.split(), a.screen_sizes.split(), a.radii.split()
    first = load(a.dir, f"shadow_{shadows[0]}")
    scenes = sorted({r["scene"] for r in first["rows"]})
    info = (Path(a.dir) / "info.txt").read_text().strip().splitlines() if (Path(a.dir) / "info.txt").exists() else []
    print("# sspcss benchmark\n")
    print(f"Device: `{first['device']}`, renderer `{first['renderer']}`. Times: median ms of the measured "
          "frames per pass (`penumbra bench`), summed per group. *Technique* = all of a technique's passes "
          "but the shadow map (a raster pass, reported on its own), the G-buffer and the lighting.\n")
    if info:
        print("```\n" + "\n".join(info) + "\n```\n")

    print("## 1. Shadow-map size (screen " + first["rows"][0]["size"] + ")\n")
    print("| scene | map | sspcss prepare | search | filter | sspcss technique | "
          "sspcss, centre sample: prepare | technique | pcss technique | shadow map |")
    print("|---|---|---|---|---|---|---|---|---|---|")
    for s in scenes:
        for n in shadows:
            d = load(a.dir, f"shadow_{n}")
            ss, pc = row(d, "sspcss", s), row(d, "pcss", s)
            cs = row(load(a.dir, f"shadow_{n}_centre"), "sspcss", s)
            print(f"| {s} | {n}² | {group(ss, 'prepare'):.3f} | {group(ss, 'search'):.3f} | "
                  f"{group(ss, 'filter'):.3f} | {group(ss, 'technique'):.3f} | {group(cs, 'prepare'):.3f} | "
                  f"{group(cs, 'technique'):.3f} | {group(pc, 'technique'):.3f} | {group(ss, 'shadow_map'):.3f} |")
    print()

    def change(name, technique, s):
        lo, hi = (group(row(load(a.dir, name.format(n)), technique, s), "technique") for n in (shadows[0], shadows[-1]))
        return hi / lo - 1.0

    for s in scenes:
        c, cc = change("shadow_{}", "sspcss", s), change("shadow_{}_centre", "sspcss", s)
        print(f"- {s}: sspcss technique {shadows[0]}² -> {shadows[-1]}²: {100 * c:+.1f}% "
              f"(target within 10%: {'meets' if abs(c) <= 0.10 else 'misses'}); with the centre sample "
              f"{100 * cc:+.1f}% ({'meets' if abs(cc) <= 0.10 else 'misses'}); "
              f"pcss {100 * change('shadow_{}', 'pcss', s):+.1f}%")
    print()

    print("## 2. Screen size (shadow map " + str(load(a.dir, f"screen_{screens[0]}")["rows"][0]["shadow_size"]) + "²)\n")
    print("| scene | screen | Mpixel | sspcss technique | ms / Mpixel | pcss technique | ms / Mpixel |")
    print("|---|---|---|---|---|---|---|")
    for s in scenes:
        for size in screens:
            d = load(a.dir, f"screen_{size}")
            ss, pc = row(d, "sspcss", s), row(d, "pcss", s)
            mp = megapixels(size)
            print(f"| {s} | {size} | {mp:.2f} | {group(ss, 'technique'):.3f} | {group(ss, 'technique') / mp:.3f} | "
                  f"{group(pc, 'technique'):.3f} | {group(pc, 'technique') / mp:.3f} |")
    print("\n(Linear in pixels: constant ms / Mpixel, up to the fixed cost of each dispatch.)\n")

    print("## 3. Separable vs Poisson at fixed radii (receiver_footprint=false: round kernels)\n")
    print("| scene | radius | separable filter | Poisson filter (32 taps) | Poisson filter (64 taps) | "
          "separable / Poisson 32 | separable technique | Poisson 32 technique |")
    print("|---|---|---|---|---|---|---|---|")
    for s in scenes:
        for r in radii:
            sep = row(load(a.dir, f"radius_{r}_separable"), "sspcss", s)
            poi = row(load(a.dir, f"radius_{r}_poisson"), "sspcss", s)
            p64 = row(load(a.dir, f"radius_{r}_poisson64"), "sspcss", s)
            print(f"| {s} | {r} px | {group(sep, 'filter'):.3f} | {group(poi, 'filter'):.3f} | "
                  f"{group(p64, 'filter'):.3f} | {group(sep, 'filter') / group(poi, 'filter'):.2f} | "
                  f"{group(sep, 'technique'):.3f} | {group(poi, 'technique'):.3f} |")
    print()
    lo, hi = radii[0], radii[-1]
    for s in scenes:
        sep_hi = group(row(load(a.dir, f"radius_{hi}_separable"), "sspcss", s), "filter")
        sep_lo = group(row(load(a.dir, f"radius_{lo}_separable"), "sspcss", s), "filter")
        poi_hi = group(row(load(a.dir, f"radius_{hi}_poisson"), "sspcss", s), "filter")
        p64_hi = group(row(load(a.dir, f"radius_{hi}_poisson64"), "sspcss", s), "filter")
        print(f"- {s}: separable / Poisson filter at {hi} px: {verdict(sep_hi / poi_hi, 0.3)} with 32 taps, "
              f"{sep_hi / p64_hi:.2f} with 64; separable at {hi} px / at {lo} px: {verdict(sep_hi / sep_lo, 1.2)}")
    print("\nThe ratios compare the filter passes (shadow_filter_*), the only ones the radius changes; "
          "the blocker search runs with its own W_search in both rows.")


if __name__ == "__main__":
    main()
