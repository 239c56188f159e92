"""Before/after table and roofline of a speed change (scripts/gpu/before-after-bench.sh output).

    python3 scripts/report/bandwidth_report.py RUN_DIR OUT.md [ROOFLINE.png]

RUN_DIR holds before-N.json and after-N.json (`penumbra bench --json`, with measured peaks and
per-pass traffic). A technique's own time is the sum of its passes' medians without the frame's
passes (gbuffer, lighting) and the shadow map (a raster pass shared by every technique and
unchanged by these changes); with several rounds, each pass's median over rounds is used and the
spread (max/min of the rounds' sums) is reported. The roofline plots every pass of the "after"
build: bytes moved against achieved bandwidth, with the measured copy peak as the ceiling.
"""
import glob
import json
import os
import statistics
import sys

OWN_EXCLUDED = ("gbuffer", "lighting", "shadow_map")


def load_runs(run_dir, build):
    runs = []
    for path in sorted(glob.glob(os.path.join(run_dir, f"{build}-*.json"))):
        with open(path) as f:
            runs.append(json.load(f))
    if not runs:
        sys.exit(f"bandwidth_report: no {build}-*.json in {run_dir}")
    return runs


def key(row):
    return (row["technique"], row["scene"], row["size"])


def merged(runs):
    """(technique, scene, size) -> {"passes": {name: pass with median ms over runs}, "sums": [own ms per run]}"""
    out = {}
    for run in runs:
        for row in run["rows"]:
            entry = out.setdefault(key(row), {"order": [], "passes": {}, "sums": []})
            own = 0.0
            for p in row["passes"]:
                if p["name"] not in entry["passes"]:
                    entry["order"].append(p["name"])
                    entry["passes"][p["name"]] = dict(p, runs=[])
                entry["passes"][p["name"]]["runs"].append(p["ms"])
                if p["name"] not in OWN_EXCLUDED:
                    own += p["ms"]
            entry["sums"].append(own)
    for entry in out.values():
        for p in entry["passes"].values():
            p["ms"] = statistics.median(p["runs"])
        entry["own_ms"] = sum(p["ms"] for n, p in entry["passes"].items() if n not in OWN_EXCLUDED)
        entry["own_bytes"] = sum(p["read_bytes"] + p["written_bytes"]
                                 for n, p in entry["passes"].items() if n not in OWN_EXCLUDED)
    return out


def spread(values):
    return max(values) / min(values) if values and min(values) > 0 else float("nan")


def pixels(size):
    w, h = size.split("x")
    return int(w) * int(h)


def peak_of(runs):
    peaks = [r["peaks"]["copy_gb_per_s"] for r in runs if r.get("peaks", {}).get("measured")]
    return statistics.median(peaks) if peaks else 0.0


def roofline(points, peak, path, title):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(9, 6))
    sizes = sorted({p["size"] for p in points}, key=pixels)
    markers = ["o", "s", "^", "D"]
    for i, size in enumerate(sizes):
        xs = [p["mb"] for p in points if p["size"] == size]
        ys = [p["gbs"] for p in points if p["size"] == size]
        ax.scatter(xs, ys, marker=markers[i % len(markers)], alpha=0.7, label=f"passes at {size}")
    if peak > 0:
        ax.axhline(peak, color="red", linestyle="--", label=f"measured copy peak {peak:.0f} GB/s")
        ax.axhline(0.7 * peak, color="orange", linestyle=":", label="70% of the peak")
    far = sorted((p for p in points if p["size"] == sizes[-1]), key=lambda p: p["gbs"])[:6]
    for i, p in enumerate(far):
        ax.annotate(f'{p["technique"]}/{p["pass"]}', (p["mb"], p["gbs"]), fontsize=7,
                    xytext=(6, -10 - 9 * (i % 2)), textcoords="offset points")
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("bytes moved per execution (MB, plan traffic model)")
    ax.set_ylabel("achieved bandwidth (GB/s)")
    ax.set_title(title + "\n(screen passes; the raster shadow map, about 3% of the peak, is left out)", fontsize=10)
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8, loc="lower right")
    fig.tight_layout()
    fig.savefig(path, dpi=110)


def main(run_dir, out_md, png=None):
    before_runs, after_runs = load_runs(run_dir, "before"), load_runs(run_dir, "after")
    before, after = merged(before_runs), merged(after_runs)
    peak_before, peak_after = peak_of(before_runs), peak_of(after_runs)
    lines = [f"Device: `{after_runs[0]['renderer']}` ({after_runs[0]['device']}), {after_runs[0].get('timing', '')}.",
             f"Measured copy peak: {peak_before:.0f} GB/s (before runs), {peak_after:.0f} GB/s (after runs); "
             f"{len(before_runs)} round(s) of each build, alternating.", ""]
    lines += ["| technique | scene | size | before µs | after µs | after / before | spread before | spread after "
              "| before B/px | after B/px |", "|---|---|---|---:|---:|---:|---:|---:|---:|---:|"]
    for k in sorted(before, key=lambda k: (k[0], k[1], pixels(k[2]))):
        if k not in after:
            continue
        b, a = before[k], after[k]
        px = pixels(k[2])
        lines.append(f"| {k[0]} | {k[1]} | {k[2]} | {1e3 * b['own_ms']:.1f} | {1e3 * a['own_ms']:.1f} | "
                     f"{a['own_ms'] / b['own_ms']:.2f} | {spread(b['sums']):.3f} | {spread(a['sums']):.3f} | "
                     f"{b['own_bytes'] / px:.1f} | {a['own_bytes'] / px:.1f} |")
    lines += ["", "Every pass (after), its time, bytes and achieved bandwidth; `bound` says what the "
              "traffic model predicts: `memory` where moving its bytes at the copy peak takes >= 60% of its time.", "",
              "| technique | size | pass | before µs | after µs | before MB | after MB | after GB/s | % of peak | bound |",
              "|---|---|---|---:|---:|---:|---:|---:|---:|---|"]
    points = []
    for k in sorted(after, key=lambda k: (k[0], k[1], pixels(k[2]))):
        a = after[k]
        b = before.get(k, {"passes": {}})
        for name in a["order"]:
            if name in ("gbuffer", "lighting"):
                continue
            p = a["passes"][name]
            q = b["passes"].get(name)
            mb = (p["read_bytes"] + p["written_bytes"]) / 1e6
            gbs = mb / 1e3 / (p["ms"] * 1e-3) if p["ms"] > 0 else 0.0
            pct = 100.0 * gbs / peak_after if peak_after > 0 else 0.0
            bound = "memory" if pct >= 60 else "other"
            if name != "shadow_map":  # a raster pass (about 3% of the peak): the roofline is about the screen passes
                points.append({"technique": k[0], "size": k[2], "pass": name, "mb": mb, "gbs": gbs, "pct": pct})
            qb = f"{1e3 * q['ms']:.1f}" if q else "-"
            qmb = f"{(q['read_bytes'] + q['written_bytes']) / 1e6:.1f}" if q else "-"
            lines.append(f"| {k[0]} | {k[2]} | {name} | {qb} | {1e3 * p['ms']:.1f} | {qmb} | {mb:.1f} | {gbs:.0f} | "
                         f"{pct:.0f}% | {bound} |")
    largest = max((pixels(p["size"]) for p in points), default=0)
    far = sorted((p for p in points if pixels(p["size"]) == largest), key=lambda p: p["pct"])[:8]
    lines += ["", "Furthest from the copy peak at the largest size: " +
              ", ".join(f'{p["technique"]}/{p["pass"]} ({p["pct"]:.0f}%)' for p in far) + "."]
    with open(out_md, "w") as f:
        f.write("\n".join(lines) + "\n")
    if png:
        roofline(points, peak_after, png, f"Every pass after the change: {after_runs[0]['renderer']}")
    return 0


if __name__ == "__main__":
    if len(sys.argv) not in (3, 4):
        sys.exit("usage: bandwidth_report.py RUN_DIR OUT.md [ROOFLINE.png]")
    sys.exit(main(*sys.argv[1:]))
