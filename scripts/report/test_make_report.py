#!/usr/bin/env python3
"""Tests of make-report.py on a synthetic suite run: the Pareto front, the penumbra crop, and the
targets table computed from known numbers (ctest: ReportScript)."""
import importlib.util
import json
import os
import sys
import tempfile
import unittest

import numpy as np
from PIL import Image

HERE = os.path.dirname(os.path.abspath(__file__))
spec = importlib.util.spec_from_file_location("make_report", os.path.join(HERE, "make-report.py"))
report = importlib.util.module_from_spec(spec)
spec.loader.exec_module(report)

# label -> (penumbra RMSE, technique ms); the shadow map costs 0.5 ms for every one.
SCENE = {"hard": (0.30, 0.03), "pcf": (0.20, 0.06), "pcss": (0.10, 0.14), "pmchss": (0.12, 0.08),
         "mpg": (0.14, 0.50), "sspcss": (0.09, 0.30), "esm": (0.28, 0.60)}


def write_json(path, value):
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, "w") as f:
        json.dump(value, f)


def bench_row(label, ms, size="1920x1080", shadow=2048):
    return {"technique": label, "size": size, "shadow_size": shadow,
            "passes": [{"name": "shadow_map", "ms": 0.5}, {"name": "gbuffer", "ms": 0.2}, {"name": label, "ms": ms}]}


def synthetic_run(raw):
    write_json(os.path.join(raw, "eval", "ball.json"), {"scene": "ball", "rows": [
        {"technique": l, "rmse_penumbra": e, "ssim": 0.99} for l, (e, _) in SCENE.items()]})
    # Tiled PCSS timed only (its mask is PCSS's), here slower than untiled and than sspcss.
    write_json(os.path.join(raw, "bench", "ball.json"), {"rows": [bench_row(l, ms) for l, (_, ms) in SCENE.items()] +
                                                          [bench_row("pcss:tiles=true", 0.35)]})
    write_json(os.path.join(raw, "edge", "ball.json"), {"rows": [{"technique": "hard", "edge_error": 0.03}]})
    write_json(os.path.join(raw, "edge512", "ball.json"), {"rows": [{"technique": "esm", "edge_error": 0.02}]})
    # sspcss: 0.25 / 0.26 / 0.30 ms over the map sizes (20%: the target is missed).
    write_json(os.path.join(raw, "cost", "colonnade.json"), {"rows": [
        bench_row("sspcss", ms, shadow=n) for n, ms in ((1024, 0.25), (2048, 0.26), (4096, 0.30))]})
    mask = np.ones((40, 60), np.uint8) * 255
    mask[10:20, 20:30] = 128  # the only penumbra
    os.makedirs(os.path.join(raw, "gallery"))
    for label in ["reference"] + list(SCENE):
        Image.fromarray(mask).save(os.path.join(raw, "gallery", f"ball_{report.file_label(label)}_mask.png"))
        Image.fromarray(np.zeros((40, 60, 3), np.uint8)).save(
            os.path.join(raw, "gallery", f"ball_{report.file_label(label)}_error.png"))


class MakeReport(unittest.TestCase):
    def test_pareto_front_keeps_only_points_nothing_beats(self):
        points = [(1.0, 0.3, "a"), (2.0, 0.1, "b"), (3.0, 0.2, "c"), (0.5, 0.5, "d")]
        self.assertEqual([p[2] for p in report.pareto(points)], ["d", "a", "b"])

    def test_penumbra_crop_frames_the_penumbra_with_padding(self):
        grey = np.ones((100, 200))
        grey[40:50, 60:100] = 0.5
        rows, cols = report.penumbra_crop(grey)
        self.assertEqual((rows.start, rows.stop), (36, 54))  # 4-pixel minimum padding
        self.assertEqual((cols.start, cols.stop), (56, 104))
        self.assertEqual(report.penumbra_crop(np.ones((10, 10))), (slice(None), slice(None)))

    def test_targets_and_tables_from_a_synthetic_run(self):
        with tempfile.TemporaryDirectory() as tmp:
            raw, out = os.path.join(tmp, "raw"), os.path.join(tmp, "out")
            synthetic_run(raw)
            sys.argv = ["make-report.py", raw, out]
            report.main()
            with open(os.path.join(out, "README.md")) as f:
                md = f.read()
            for png in ("quality_vs_cost.png", "cost_scaling.png", "gallery_ball.png"):
                self.assertTrue(os.path.getsize(os.path.join(out, png)) > 0, png)
        # pmchss 1.20x PCSS (met), mpg 1.40x (missed), sspcss 0.90x (met); all below PCF's 0.20.
        self.assertIn("`pmchss` defaults: penumbra RMSE ≤ 1.25× PCSS on every scene | worst 1.20× (ball); met on 1/1 | yes", md)
        self.assertIn("`mpg` defaults: penumbra RMSE ≤ 1.25× PCSS on every scene | worst 1.40× (ball); met on 0/1 | no", md)
        self.assertIn("`sspcss` defaults: below PCF everywhere | below on 1/1 | yes", md)
        # pmchss is cheaper than PCSS (0.58 < 0.64 ms total) but worse: on the front, not dominating.
        self.assertIn("on the Pareto front (no variant both cheaper and better) on most scenes | on 1/1 | yes", md)
        self.assertIn("beats PCSS in error and cost on most scenes | on 0/1 (none) | no", md)
        # sspcss: less error than PCSS, cheaper than tiled PCSS (0.80 < 0.85 ms total).
        self.assertIn("beats tiled PCSS (`pcss:tiles=true`) in error and cost on most scenes | on 1/1 (ball) | yes", md)
        self.assertIn("0.250 / 0.260 / 0.300 ms: 20% | no", md)
        self.assertIn("met on 1/1: ball 0.0200/0.0300 | yes", md)
        # The per-scene table: PCSS ratio and the technique's own time (gbuffer and shadow map out),
        # tiled where timed.
        self.assertIn("| `mpg` | 0.1400 | 1.40 | 0.9900 | – | – | – | 0.500 | – | 0.500 |", md)
        self.assertIn("| `pcss` | 0.1000 | 1.00 | 0.9900 | – | – | – | 0.140 | 0.350 | 0.500 |", md)


if __name__ == "__main__":
    unittest.main()
