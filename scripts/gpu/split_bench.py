#!/usr/bin/env python3
"""Splits one `penumbra bench --json` run (several --techniques items, sizes and shadow sizes)
into one JSON per configuration, so table scripts can read a file per configuration while the
GPU runs a single process (one context, scene load and shader build for all of them).

usage: split_bench.py BENCH.json OUT_DIR NAME=LABEL[+LABEL...][@size=WxH][@shadow=N]...
  writes OUT_DIR/NAME.json with the device, the renderer and the rows whose technique is one of
  the LABELs (the --techniques items as written), at that screen size and shadow size if given
"""
import json
import os
import sys


def main():
    if len(sys.argv) < 4:
        sys.exit(__doc__)
    bench = json.load(open(sys.argv[1]))
    out_dir = sys.argv[2]
    os.makedirs(out_dir, exist_ok=True)
    for pair in sys.argv[3:]:
        name, spec = pair.split("=", 1)
        labels, *filters = spec.split("@")
        wanted = dict(f.split("=", 1) for f in filters)
        rows = [r for r in bench["rows"]
                if r["technique"] in labels.split("+")
                and wanted.get("size", r["size"]) == r["size"]
                and int(wanted.get("shadow", r["shadow_size"])) == r["shadow_size"]]
        if not rows:
            sys.exit(f"split_bench.py: no rows for {spec!r} in {sys.argv[1]}")
        with open(os.path.join(out_dir, name + ".json"), "w") as f:
            json.dump({"device": bench["device"], "renderer": bench["renderer"], "rows": rows}, f, indent=2)


if __name__ == "__main__":
    main()
