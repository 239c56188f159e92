"""Before/after table of penumbra RMSE (scripts/report/compare-quality.sh). Exit 1 when a
technique's RMSE moved by more than LIMIT percent (relative) on any scene."""
import json
import os
import sys


def load(folder):
    rows = {}
    for name in sorted(os.listdir(folder)):
        if name.endswith(".json"):
            with open(os.path.join(folder, name)) as f:
                report = json.load(f)
            for row in report["rows"]:
                rows[(report["scene"], row["technique"])] = row["rmse_penumbra"]
    return rows


def main(before_dir, after_dir, limit):
    before, after = load(before_dir), load(after_dir)
    worst = 0.0
    print("| scene | technique | penumbra RMSE before | after | change |")
    print("|---|---|---:|---:|---:|")
    for key in sorted(before):
        if key not in after:
            print(f"| {key[0]} | {key[1]} | {before[key]:.5f} | missing | |")
            worst = float("inf")
            continue
        b, a = before[key], after[key]
        change = 100.0 * (a - b) / b if b > 0 else (0.0 if a == b else float("inf"))
        worst = max(worst, abs(change))
        print(f"| {key[0]} | {key[1]} | {b:.5f} | {a:.5f} | {change:+.2f}% |")
    print(f"\nlargest change {worst:.2f}% (limit {limit}%)")
    return 0 if worst <= limit else 1


if __name__ == "__main__":
    if len(sys.argv) != 4:
        sys.exit("usage: quality_table.py BEFORE_DIR AFTER_DIR LIMIT_PERCENT")
    sys.exit(main(sys.argv[1], sys.argv[2], float(sys.argv[3])))
