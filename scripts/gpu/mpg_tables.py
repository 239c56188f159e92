#!/usr/bin/env python3
"""Turns the `penumbra bench --json` files written by mpg-bench.sh into the Markdown of the mpg
benchmark (Cherry & Kooima, issue 11): one table per scene and size, then the target ratios.

Pass groups (pass names in techniques/mpg/mpg.json), median ms per pass summed:
  shadow map = shadow_map (reported apart: a raster pass the GPU machines are slow at)
  distance   = distance_map (pass 2)
  early-out  = umbra_early_out_x + umbra_early_out_y (section 5)
  dilation   = dilate_x + dilate_y (pass 3)
  pass 4     = pcf_filter | gaussian_filter_x + gaussian_filter_y | multipass_blur[*]
  resolve    = resolve_mask (pass 5)
  mpg        = distance + early-out + dilation + pass 4 + resolve (the technique's own passes)
gbuffer and lighting are the frame's, the same for every technique, and left out.

usage: mpg_tables.py OUT_DIR      (OUT_DIR/<W>x<H>_s<shadow>/<config>.json)
"""
import json
import sys
from pathlib import Path

ROWS = [  # (config, label)
    ("pcf", "PCF, D-sized box (defaults: max_kernel 19)"),
    ("gaussian", "single-pass Gaussian, max_kernel 19"),
    ("multipass", "multi-pass, progressive 3..19, 10 passes, 20 taps (defaults)"),
    ("gaussian_k9", "single-pass Gaussian, max_kernel 9"),
    ("gaussian_k29", "single-pass Gaussian, max_kernel 29"),
    ("multipass_k9", "multi-pass, progressive 3..9"),
    ("multipass_k29", "multi-pass, progressive 3..29"),
    ("fixed_k9", "multi-pass, fixed 9x9"),
    ("fixed_k19", "multi-pass, fixed 19x19"),
    ("fixed_k29", "multi-pass, fixed 29x29"),
    ("multipass_early_out", "multi-pass + umbra early-out (N 31)"),
    ("sat_pcf", "saturated D: PCF, max_kernel 19"),
    ("sat_gaussian_k9", "saturated D: single-pass Gaussian, max_kernel 9"),
    ("sat_gaussian", "saturated D: single-pass Gaussian, max_kernel 19"),
    ("sat_gaussian_k29", "saturated D: single-pass Gaussian, max_kernel 29"),
    ("sat_multipass_k9", "saturated D: multi-pass, progressive 3..9"),
    ("sat_multipass", "saturated D: multi-pass, progressive 3..19"),
    ("sat_multipass_k29", "saturated D: multi-pass, progressive 3..29"),
    ("sat_fixed_k19", "saturated D: multi-pass, fixed 19x19"),
    ("sat_multipass_early_out", "saturated D: multi-pass + umbra early-out (N 31)"),
]
GROUPS = ["shadow map", "distance", "early-out", "dilation", "pass 4", "resolve", "mpg"]


def group_of(name):
    if name == "shadow_map":
        return "shadow map"
    if name == "distance_map":
        return "distance"
    if name.startswith("umbra_early_out"):
        return "early-out"
    if name.startswith("dilate"):
        return "dilation"
    if name in ("pcf_filter", "gaussian_filter_x", "gaussian_filter_y") or name.startswith("multipass_blur"):
        return "pass 4"
    if name == "resolve_mask":
        return "resolve"
    return None  # gbuffer, lighting, debug views


def load(directory):
    """{config: (meta, {scene: {group: ms}})} for every <config>.json in directory."""
    runs = {}
    for path in sorted(Path(directory).glob("*.json")):
        data = json.loads(path.read_text())
        per_scene = {}
        for row in data["rows"]:
            if row["technique"].split(":")[0] != "mpg":
                continue
            groups = {g: 0.0 for g in GROUPS}
            for p in row["passes"]:
                g = group_of(p["name"])
                if g:
                    groups[g] += p["ms"]
            groups["mpg"] = sum(groups[g] for g in GROUPS[1:-1])
            per_scene[row["scene"]] = groups
        runs[path.stem] = (data, per_scene)
    return runs


def ratio(a, b):
    return a / b if b > 0 else float("nan")


def table(runs, scene):
    lines = ["| configuration | " + " | ".join(GROUPS) + " |", "|---|" + "---:|" * len(GROUPS)]
    for config, label in ROWS:
        if config in runs and scene in runs[config][1]:
            g = runs[config][1][scene]
            lines.append(f"| {label} | " + " | ".join(f"{g[k]:.3f}" for k in GROUPS) + " |")
    return lines


def pass4(runs, config, scene):
    if config not in runs or scene not in runs[config][1]:
        return float("nan")
    return runs[config][1][scene]["pass 4"]


def spread(values):
    """(max - min) / min over the values: the +-10% flatness target asks for <= 0.10."""
    values = [v for v in values if v == v]
    return (max(values) - min(values)) / min(values) if values and min(values) > 0 else float("nan")


def verdict(value, ok):
    return "—" if value != value else ("yes" if ok else "**no**")


def ratios(runs, scenes):
    lines = ["| ratio (pass 4 only) | " + " | ".join(scenes) + " | target | met |", "|---|" + "---:|" * len(scenes) + "---|---|"]

    def row(label, values, target, test):
        cells = " | ".join(f"{v:.2f}" if v == v else "—" for v in values)
        met = ", ".join(verdict(v, test(v)) for v in values) if test else "(information)"
        lines.append(f"| {label} | {cells} | {target} | {met} |")

    for prefix, what in (("", "default D"), ("sat_", "saturated D")):
        for k in (9, 19, 29):
            mp = f"{prefix}multipass" + ("" if k == 19 else f"_k{k}")
            ga = f"{prefix}gaussian" + ("" if k == 19 else f"_k{k}")
            row(f"multi-pass / single-pass Gaussian, max_kernel {k}, {what}",
                [ratio(pass4(runs, mp, s), pass4(runs, ga, s)) for s in scenes], "<= 1.0x", lambda v: v <= 1.0)
    row("multi-pass spread over max_kernel 9/19/29, progressive, default D",
        [spread([pass4(runs, c, s) for c in ("multipass_k9", "multipass", "multipass_k29")]) for s in scenes],
        "<= 0.10", lambda v: v <= 0.10)
    row("multi-pass spread over max_kernel 9/19/29, progressive, saturated D",
        [spread([pass4(runs, c, s) for c in ("sat_multipass_k9", "sat_multipass", "sat_multipass_k29")]) for s in scenes],
        "<= 0.10", lambda v: v <= 0.10)
    row("multi-pass spread over max_kernel 9/19/29, fixed kernel, default D",
        [spread([pass4(runs, c, s) for c in ("fixed_k9", "fixed_k19", "fixed_k29")]) for s in scenes],
        "<= 0.10", lambda v: v <= 0.10)
    row("fixed 19x19 / progressive 3..19, default D",
        [ratio(pass4(runs, "fixed_k19", s), pass4(runs, "multipass", s)) for s in scenes], "paper: > 1", None)
    row("fixed 19x19 / progressive 3..19, saturated D",
        [ratio(pass4(runs, "sat_fixed_k19", s), pass4(runs, "sat_multipass", s)) for s in scenes], "paper: > 1", None)
    return lines


def early_out(runs, scenes):
    """The early-out adds two passes and saves pass-4 work: compare the whole technique."""
    lines = ["| umbra early-out: mpg total with / without | " + " | ".join(scenes) + " |", "|---|" + "---:|" * len(scenes)]
    for prefix, what in (("", "default D"), ("sat_", "saturated D")):
        cells = []
        for s in scenes:
            on, off = runs.get(f"{prefix}multipass_early_out"), runs.get(f"{prefix}multipass")
            cells.append(f"{ratio(on[1][s]['mpg'], off[1][s]['mpg']):.2f}x" if on and off and s in on[1] and s in off[1] else "—")
        lines.append(f"| {what} | " + " | ".join(cells) + " |")
    return lines


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    root = Path(sys.argv[1])
    dirs = sorted(d for d in root.iterdir() if d.is_dir() and any(d.glob("*.json")))
    if not dirs:
        sys.exit(f"{root}: no <size>_s<shadow>/*.json from mpg-bench.sh")
    print("# mpg benchmark (Cherry & Kooima, multi-pass Gaussian contact-hardening soft shadows)\n")
    print("Written by `scripts/gpu/mpg-bench.sh` (`penumbra bench`, debug views off). Median ms per pass,")
    print("summed per group: distance = pass 2, early-out = section 5 (x + y), dilation = pass 3 (x + y),")
    print("pass 4 = the alteration, resolve = pass 5, mpg = their sum; the shadow map is apart. \"Saturated D\"")
    print("is light_size_scale = 10: every shadowed pixel takes the largest kernel (PCF, Gaussian) or all ten")
    print("passes (multi-pass), the per-pixel worst case.\n")
    for d in dirs:
        runs = load(d)
        meta = next(iter(runs.values()))[0]
        scenes = sorted({s for _, per_scene in runs.values() for s in per_scene})
        size, shadow = d.name.rsplit("_s", 1)
        print(f"## {size}, shadow map {shadow}²\n")
        print(f"Device: {meta.get('device', '?')}, renderer: {meta.get('renderer', '?')}.\n")
        for s in scenes:
            print(f"### {s}\n")
            print("\n".join(table(runs, s)))
            print()
        print(f"### Targets, {size}\n")
        print("\n".join(ratios(runs, scenes)))
        print()
        print("\n".join(early_out(runs, scenes)))
        print()


if __name__ == "__main__":
    main()
