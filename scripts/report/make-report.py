#!/usr/bin/env python3
"""Turns the raw results of scripts/report/run-suite.sh into the results report: Markdown tables
per scene, a quality-vs-cost chart per scene with the Pareto front, cost-vs-shadow-map-size and
cost-vs-pixels charts, a labelled gallery per scene, and the issue's targets checked.

usage: make-report.py RAW_DIR OUT_DIR
  RAW_DIR   what run-suite.sh wrote (device.txt, eval/, edge/, edge512/, flicker_*/, gallery/,
            bench/, cost/)
  OUT_DIR   gets README.md and its PNGs (docs/results); OUT_DIR/verdicts.md, when present, is the
            hand-written verdict per technique and is included as it is.
Needs python3-matplotlib (Debian). Prints progress.
"""
import glob
import json
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import matplotlib.image as mpimg  # noqa: E402
from PIL import Image  # noqa: E402  (python3-pil, a dependency of python3-matplotlib)

# Techniques whose defaults the contact-hardening targets judge, and their families (colours).
CONTACT_HARDENING = ["pmchss", "mpg", "sspcss"]
FAMILIES = ["hard", "pcf", "pcss", "pmchss", "mpg", "sspcss", "esm"]
COLOURS = dict(zip(FAMILIES, ["#777777", "#1f77b4", "#000000", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e"]))
SHADOW_MAP_PASS = "shadow_map"
PCSS_LIMIT = 1.25
# Filters that can run over the shared classifier's penumbra tiles only (`tiles`, off by default):
# their masks equal the untiled ones (tests/baseline/tiled_filters_test.cpp), so a tiled variant has
# its technique's quality and its own cost (bench rows only).
TILED = {"pcf": "pcf:tiles=true", "pcss": "pcss:tiles=true"}


def untiled(label):
    return next((t for t, tiled in TILED.items() if tiled == label), label)


def family(label):
    return label.split(":")[0].split("@")[0]


def file_label(label):
    return "".join(c if c.isalnum() or c in "_." else "-" for c in label)


def load(path):
    with open(path) as f:
        return json.load(f)


def save(fig, path, dpi):
    """Writes the figure as a 128-colour palette PNG: the report's images are committed, so small."""
    fig.savefig(path, dpi=dpi)
    plt.close(fig)
    Image.open(path).convert("RGB").quantize(colors=128).save(path, optimize=True)


def progress(message):
    print("make-report: " + message, file=sys.stderr, flush=True)


def scene_names(raw):
    return sorted(os.path.splitext(os.path.basename(p))[0] for p in glob.glob(os.path.join(raw, "eval", "*.json")))


def rows_by_label(path):
    if not os.path.exists(path):
        return {}
    return {r["technique"]: r for r in load(path)["rows"]}


def bench_split(path):
    """label -> (technique ms without the shadow map, shadow map ms), at the file's only config."""
    if not os.path.exists(path):
        return {}
    out = {}
    for r in load(path)["rows"]:
        sm = sum(p["ms"] for p in r["passes"] if p["name"] == SHADOW_MAP_PASS)
        own = sum(p["ms"] for p in r["passes"] if p["name"] not in (SHADOW_MAP_PASS, "gbuffer", "lighting"))
        out[r["technique"]] = (own, sm)
    return out


def pareto(points):
    """Points (cost, error, label) on the lower-left front: no other point is cheaper and better."""
    front, best = [], float("inf")
    for cost, error, label in sorted(points):
        if error < best:
            front.append((cost, error, label))
            best = error
    return front


class Scene:
    def __init__(self, raw, name):
        self.name = name
        evaluation = load(os.path.join(raw, "eval", name + ".json"))
        self.title = evaluation["scene"]
        self.quality = {r["technique"]: r for r in evaluation["rows"]}
        self.labels = [r["technique"] for r in evaluation["rows"]]
        self.edge = rows_by_label(os.path.join(raw, "edge", name + ".json"))
        self.edge512 = rows_by_label(os.path.join(raw, "edge512", name + ".json"))
        self.flicker = {m: rows_by_label(os.path.join(raw, "flicker_" + m, name + ".json")) for m in ("pan", "light")}
        self.cost = bench_split(os.path.join(raw, "bench", name + ".json"))
        self.tiled = [TILED[t] for t in TILED if t in self.quality and TILED[t] in self.cost]

    def rmse(self, label):
        return self.quality[untiled(label)]["rmse_penumbra"]

    def total_ms(self, label):
        own, sm = self.cost.get(label, (float("nan"), 0.0))
        return own + sm


def fmt(value, digits=4):
    return "–" if value is None or value != value else f"{value:.{digits}f}"


def scene_table(s):
    pcss = s.rmse("pcss")
    lines = ["| variant | penumbra RMSE | × PCSS | SSIM | edge error (exact hard) | flicker, pan | flicker, light "
             "| GPU ms, technique | GPU ms, tiled | GPU ms, shadow map |", "|---|---|---|---|---|---|---|---|---|---|"]
    for label in s.labels:
        q = s.quality[label]
        edge = s.edge.get(label, {}).get("edge_error")
        pan = s.flicker["pan"].get(label, {}).get("flicker")
        light = s.flicker["light"].get(label, {}).get("flicker")
        own, sm = s.cost.get(label, (float("nan"), float("nan")))
        tiled = s.cost[TILED[label]][0] if TILED.get(label) in s.tiled else None
        lines.append(f"| `{label}` | {fmt(q['rmse_penumbra'])} | {fmt(q['rmse_penumbra'] / pcss, 2)} | {fmt(q['ssim'])} "
                     f"| {fmt(edge)} | {fmt(pan)} | {fmt(light)} | {fmt(own, 3)} | {fmt(tiled, 3)} | {fmt(sm, 3)} |")
    return "\n".join(lines)


def quality_cost_chart(scenes, path):
    cols = 3
    rows = (len(scenes) + cols - 1) // cols
    fig, axes = plt.subplots(rows, cols, figsize=(4.2 * cols, 3.4 * rows), squeeze=False)
    for ax, s in zip(axes.flat, scenes):
        points = [(s.total_ms(l), s.rmse(l), l) for l in s.labels + s.tiled if s.total_ms(l) == s.total_ms(l)]
        for cost, error, label in points:
            f = family(label)
            colour = COLOURS.get(f, "#444444")
            if label in s.tiled:  # the technique's own error at the tiled cost
                ax.scatter(cost, error, facecolors="none", edgecolors=colour, marker="o", s=22, zorder=3)
                continue
            marker = "o" if label == f else ("s" if "@paper" in label else "^")
            ax.scatter(cost, error, c=colour, marker=marker, s=22, zorder=3)
        front = pareto(points)
        ax.plot([p[0] for p in front], [p[1] for p in front], "k--", lw=0.8, zorder=2)
        for cost, error, label in front:
            ax.annotate(label, (cost, error), fontsize=6, xytext=(3, 3), textcoords="offset points")
        ax.set_title(s.title, fontsize=9)
        ax.set_xlabel("GPU ms (technique + shadow map)", fontsize=7)
        ax.set_ylabel("penumbra RMSE", fontsize=7)
        ax.tick_params(labelsize=6)
        ax.grid(True, which="both", lw=0.3, alpha=0.5)
    for ax in list(axes.flat)[len(scenes):]:
        ax.axis("off")
    handles = [plt.Line2D([], [], marker="o", ls="", color=COLOURS[f], label=f) for f in FAMILIES]
    handles += [plt.Line2D([], [], marker="^", ls="", color="k", label="variant"),
                plt.Line2D([], [], marker="s", ls="", color="k", label="@paper"),
                plt.Line2D([], [], marker="o", ls="", color="k", markerfacecolor="none", label="tiles=true"),
                plt.Line2D([], [], ls="--", color="k", label="Pareto front")]
    fig.legend(handles=handles, loc="lower center", ncol=len(handles), fontsize=7, frameon=False)
    fig.tight_layout(rect=(0, 0.04, 1, 1))
    save(fig, path, 90)


def cost_rows(raw):
    path = os.path.join(raw, "cost", "colonnade.json")
    if not os.path.exists(path):
        return []
    out = []
    for r in load(path)["rows"]:
        own = sum(p["ms"] for p in r["passes"] if p["name"] not in (SHADOW_MAP_PASS, "gbuffer", "lighting"))
        sm = sum(p["ms"] for p in r["passes"] if p["name"] == SHADOW_MAP_PASS)
        w, h = (int(v) for v in r["size"].split("x"))
        out.append({"label": r["technique"], "pixels": w * h, "size": r["size"], "map": r["shadow_size"], "own": own, "sm": sm})
    return out


def cost_charts(rows, path):
    fig, (a, b) = plt.subplots(1, 2, figsize=(11, 4))
    labels = sorted({r["label"] for r in rows}, key=lambda l: (FAMILIES.index(family(l)) if family(l) in FAMILIES else 99, l))
    # The sweep's 1080p and 2048² (a quick run has other sizes: its middle ones then).
    sizes = sorted({r["size"] for r in rows}, key=lambda v: rows[[x["size"] for x in rows].index(v)]["pixels"])
    maps = sorted({r["map"] for r in rows})
    screen = "1920x1080" if "1920x1080" in sizes else sizes[len(sizes) // 2]
    shadow = 2048 if 2048 in maps else maps[len(maps) // 2]
    for label in labels:
        colour = COLOURS.get(family(label), "#444444")
        style = "-" if label == family(label) else ":"
        at1080 = sorted((r["map"], r["own"]) for r in rows if r["label"] == label and r["size"] == screen)
        at2048 = sorted((r["pixels"], r["own"]) for r in rows if r["label"] == label and r["map"] == shadow)
        if at1080:
            a.plot(*zip(*at1080), style, marker="o", ms=3, color=colour, label=label)
        if at2048:
            b.plot([p / 1e6 for p, _ in at2048], [m for _, m in at2048], style, marker="o", ms=3, color=colour, label=label)
    a.set_xscale("log", base=2)
    a.set_xlabel(f"shadow map size (texels per side), {screen}")
    b.set_xlabel(f"screen megapixels, {shadow}² map")
    for ax in (a, b):
        ax.set_ylabel("GPU ms, technique passes (no shadow map)")
        ax.set_yscale("log")
        ax.grid(True, which="both", lw=0.3, alpha=0.5)
    b.legend(fontsize=6, loc="center left", bbox_to_anchor=(1.0, 0.5))
    fig.tight_layout()
    save(fig, path, 90)


def penumbra_crop(reference):
    """The frame's rows and columns around the reference's penumbra (0.02 < v < 0.98), padded by a
    tenth, so that the shadows fill the gallery's small cells; the whole frame when it has none."""
    grey = reference if reference.ndim == 2 else reference[..., 0]
    rows, cols = ((grey > 0.02) & (grey < 0.98)).nonzero()
    if len(rows) == 0:
        return (slice(None), slice(None))
    h, w = grey.shape
    pad_y, pad_x = max(4, (rows.max() - rows.min()) // 10), max(4, (cols.max() - cols.min()) // 10)
    return (slice(max(0, rows.min() - pad_y), min(h, rows.max() + pad_y + 1)),
            slice(max(0, cols.min() - pad_x), min(w, cols.max() + pad_x + 1)))


def gallery(raw, s, path):
    labels = [l for l in s.labels if os.path.exists(os.path.join(raw, "gallery", f"{s.title}_{file_label(l)}_mask.png"))]
    ref = os.path.join(raw, "gallery", f"{s.title}_reference_mask.png")
    if not labels or not os.path.exists(ref):
        return False
    cols = 4  # two (mask, error) pairs per row
    rows = (len(labels) + 1 + 1) // 2
    fig, axes = plt.subplots(rows, cols, figsize=(2.4 * cols, 1.55 * rows), squeeze=False)
    reference = mpimg.imread(ref)
    crop = penumbra_crop(reference)
    cells = [("reference", reference[crop], None)]
    for l in labels:
        mask = mpimg.imread(os.path.join(raw, "gallery", f"{s.title}_{file_label(l)}_mask.png"))
        error = mpimg.imread(os.path.join(raw, "gallery", f"{s.title}_{file_label(l)}_error.png"))
        cells.append((l, mask[crop], error[crop]))
    flat = list(axes.flat)
    for i, (label, mask, error) in enumerate(cells):
        m, e = flat[2 * i], flat[2 * i + 1]
        m.imshow(mask, cmap="gray", vmin=0, vmax=1, interpolation="nearest")
        m.set_title(label, fontsize=6)
        if error is not None:
            e.imshow(error, interpolation="nearest")
            e.set_title(f"error, RMSE_p {s.rmse(label):.3f}", fontsize=6)
    for ax in flat:
        ax.axis("off")
    fig.suptitle(f"{s.title}, 480x270 cropped to the penumbrae: mask and |error| (black 0, blue, green, red, "
                 "white ≥ 0.25)", fontsize=7)
    fig.tight_layout(pad=0.2, rect=(0, 0, 1, 0.97))
    save(fig, path, 80)
    return True


def targets(scenes, cost):
    lines = ["| target | measured | met |", "|---|---|---|"]
    for t in CONTACT_HARDENING:
        ratios = [(s.rmse(t) / s.rmse("pcss"), s.title) for s in scenes if t in s.quality]
        worst = max(ratios)
        met = sum(r <= PCSS_LIMIT for r, _ in ratios)
        lines.append(f"| `{t}` defaults: penumbra RMSE ≤ {PCSS_LIMIT}× PCSS on every scene | worst {worst[0]:.2f}× "
                     f"({worst[1]}); met on {met}/{len(ratios)} | {'yes' if met == len(ratios) else 'no'} |")
        below = sum(s.rmse(t) < s.rmse("pcf") for s in scenes if t in s.quality)
        lines.append(f"| `{t}` defaults: below PCF everywhere | below on {below}/{len(ratios)} "
                     f"| {'yes' if below == len(ratios) else 'no'} |")
    def beating(pcss_label):
        """Scenes where a contact-hardening default has less error than PCSS and costs less than pcss_label."""
        return [s.title for s in scenes if pcss_label in s.cost and any(
            family(l) in CONTACT_HARDENING and l == family(l) and s.rmse(l) < s.rmse("pcss")
            and s.total_ms(l) < s.total_ms(pcss_label) for l in s.labels)]

    dominating = beating("pcss")
    on_front = []
    for s in scenes:
        points = [(s.total_ms(l), s.rmse(l), l) for l in s.labels + s.tiled if s.total_ms(l) == s.total_ms(l)]
        front = {label for _, _, label in pareto(points)}
        if any(t in front for t in CONTACT_HARDENING):
            on_front.append(s.title)
    lines.append(f"| a contact-hardening default on the Pareto front (no variant both cheaper and better) on most scenes "
                 f"| on {len(on_front)}/{len(scenes)} | {'yes' if 2 * len(on_front) > len(scenes) else 'no'} |")
    lines.append(f"| a contact-hardening default beats PCSS in error and cost on most scenes | on {len(dominating)}"
                 f"/{len(scenes)} ({', '.join(dominating) or 'none'}) | {'yes' if 2 * len(dominating) > len(scenes) else 'no'} |")
    with_tiled = [s for s in scenes if TILED["pcss"] in s.tiled]
    if with_tiled:
        tiled_pcss = beating(TILED["pcss"])
        lines.append(f"| … and beats tiled PCSS (`{TILED['pcss']}`) in error and cost on most scenes | on {len(tiled_pcss)}"
                     f"/{len(with_tiled)} ({', '.join(tiled_pcss) or 'none'}) "
                     f"| {'yes' if 2 * len(tiled_pcss) > len(with_tiled) else 'no'} |")

    def own(label, size, shadow):
        m = [r["own"] for r in cost if r["label"] == label and r["size"] == size and r["map"] == shadow]
        return m[0] if m else None

    mask, fixed = own("pmchss", "3840x2160", 4096), own("pmchss:variant=regular:penumbra_mapping=fixed", "3840x2160", 4096)
    if mask and fixed:
        lines.append(f"| pm-CHSS penumbra mask + shadow mask ≤ 0.9× the regular shadow mask (4K, 4096²) | {mask:.3f} / "
                     f"{fixed:.3f} ms = {mask / fixed:.2f}× | {'yes' if mask / fixed <= 0.9 else 'no'} |")
    ss = [own("sspcss", "1920x1080", n) for n in (1024, 2048, 4096)]
    if all(ss):
        change = max(ss) / min(ss) - 1
        lines.append(f"| SSPCSS ≤ 10% change across shadow-map sizes (1080p, 1024²–4096²) | "
                     f"{' / '.join(f'{v:.3f}' for v in ss)} ms: {100 * change:.0f}% | {'yes' if change <= 0.1 else 'no'} |")
    mk = [own(f"mpg:kernel_mode=fixed:max_kernel={k}", "1920x1080", 2048) for k in (9, 19, 29)]
    if all(mk):
        change = max(mk) / min(mk) - 1
        lines.append(f"| MPG flat across kernel sizes (every pixel at 9 / 19 / 29 px, 1080p) | "
                     f"{' / '.join(f'{v:.3f}' for v in mk)} ms: {100 * change:.0f}% | {'yes' if change <= 0.1 else 'no'} |")
    esm_ok = []
    for s in scenes:
        e512 = s.edge512.get("esm", {}).get("edge_error")
        hard = s.edge.get("hard", {}).get("edge_error")
        if e512 is not None and hard is not None:
            esm_ok.append((e512 <= hard, s.title, e512, hard))
    if esm_ok:
        met = sum(ok for ok, *_ in esm_ok)
        detail = ", ".join(f"{t} {a:.4f}/{b:.4f}" for _, t, a, b in esm_ok)
        lines.append(f"| ESM at 512² edge error ≤ plain 2048² | met on {met}/{len(esm_ok)}: {detail} "
                     f"| {'yes' if met == len(esm_ok) else 'no'} |")
    return "\n".join(lines)


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    raw, out = sys.argv[1], sys.argv[2]
    os.makedirs(out, exist_ok=True)
    names = scene_names(raw)
    if not names:
        sys.exit(f"make-report: no eval/*.json under {raw}")
    scenes = [Scene(raw, n) for n in names]
    progress(f"{len(scenes)} scenes")
    device = open(os.path.join(raw, "device.txt")).read().strip() if os.path.exists(os.path.join(raw, "device.txt")) else ""
    cost = cost_rows(raw)
    quality_cost_chart(scenes, os.path.join(out, "quality_vs_cost.png"))
    progress("quality_vs_cost.png")
    if cost:
        cost_charts(cost, os.path.join(out, "cost_scaling.png"))
        progress("cost_scaling.png")
    md = ["# Results: which technique is how good at what cost", "",
          "Generated by `scripts/report/make-report.py` from a run of `scripts/report/run-suite.sh` (see "
          "[Reproduce](#reproduce)). Quality is measured against the ray-traced reference (`penumbra eval`), cost "
          "on the GPU (`penumbra bench`, GPU timestamps, median of 200 frames after 10 warm-up). Memory traffic "
          "per pass, the measured copy peak and the roofline of every pass: [bandwidth.md](bandwidth.md).", "",
          "## Device", "", "```", device, "```", "", "## Targets", "", targets(scenes, cost), ""]
    verdicts = os.path.join(out, "verdicts.md")
    if os.path.exists(verdicts):
        md += [open(verdicts).read().strip(), ""]
    md += ["## Quality against cost", "",
           "Penumbra RMSE (reference pixels with 0.02 < visibility < 0.98) against the GPU time of the technique's "
           "passes and its shadow map, 1920x1080, 2048² map, one chart per scene; the dashed line is the Pareto "
           "front (no other variant is both cheaper and better). Circles: defaults; triangles: variants; squares: "
           "the paper's constants (`@paper`).", "", "![quality against cost](quality_vs_cost.png)", ""]
    if cost:
        md += ["## Cost against shadow-map size and pixels", "",
               "colonnade; GPU ms of the technique's own passes, without the shadow map (which every technique "
               "but esm shares).", "", "![cost scaling](cost_scaling.png)", ""]
    md += ["## Per scene", "",
           "Settings: every variant as labelled (the rest at its defaults), 1920x1080, 2048² shadow map, the scene's "
           "own light, reference ray-traced with 128 rays per pixel. Edge error: mean |error| within 3 px of an edge "
           "of the exact hard shadow (light size 0, 4x4 samples per pixel). Flicker: mean frame-to-frame change of the "
           "reprojected mask minus the reference's, 6 frames at 960x540, camera panning or light turning 0.25° per "
           "frame (docs/evaluation.md). GPU ms: medians of 200 frames; technique = its passes but the shadow map.", ""]
    for s in scenes:
        md += [f"### {s.title}", "", scene_table(s), ""]
        png = f"gallery_{file_label(s.name)}.png"
        if gallery(raw, s, os.path.join(out, png)):
            md += [f"![{s.title} gallery]({png})", ""]
        progress(f"scene {s.title}")
    md += ["## Reproduce", "", "```",
           "cmake --preset release && cmake --build --preset release",
           "scripts/gpu/bundle.sh .gpu build/release/cli/penumbra   # plus the models to carry",
           "# on the GPU machine (docs/gpu-machine.md):",
           "source .gpu/env.sh",
           "COST=0 scripts/report/run-suite.sh .gpu/bin/penumbra OUT MODEL.gltf ...   # 6 min on an H100",
           "COST=only scripts/report/run-suite.sh .gpu/bin/penumbra OUT                 # 2.5 min",
           "# here:",
           "scripts/report/make-report.py OUT docs/results",
           "```", ""]
    with open(os.path.join(out, "README.md"), "w") as f:
        f.write("\n".join(md))
    progress(f"wrote {os.path.join(out, 'README.md')}")


if __name__ == "__main__":
    main()
