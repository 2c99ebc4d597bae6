#!/usr/bin/python3
"""The ratios of issue 6 from bench_scenes' CSV, one row per scene (medians of the same run).

    bench/ratio_summary.py DIR/scenes.csv > DIR/ratios.md
"""
import csv
import sys


def main(path):
    rows = {}
    order = []
    for r in csv.DictReader(open(path)):
        if r["scene"] not in rows:
            rows[r["scene"]] = {"triangles": r["triangles"]}
            order.append(r["scene"])
        rows[r["scene"]][r["method"]] = float(r["median_us"])

    def ratio(s, num, den):
        a, b = rows[s].get(num), rows[s].get(den)
        return f"{a / b:.3g}" if a is not None and b else ""

    print("| scene | triangles | exact ÷ FCL rebuild (or refit) | exact, tree ÷ FCL prebuilt | exact ÷ FCL prebuilt"
          " | threshold, tree ÷ FCL collide | threshold ÷ FCL collide | tol 1e-2 ÷ exact | tol 1e-2 ÷ exact, tree |")
    print("|---|---:|---:|---:|---:|---:|---:|---:|---:|")
    for s in order:
        deforming = "fcl_refit" in rows[s]
        rebuild = ratio(s, "ours_exact", "fcl_refit" if deforming else "fcl_rebuild")
        print(f"| {s} | {rows[s]['triangles']} | {rebuild} | {ratio(s, 'ours_tree_exact', 'fcl_prebuilt')} "
              f"| {ratio(s, 'ours_exact', 'fcl_prebuilt')} | {ratio(s, 'ours_tree_threshold', 'fcl_collide')} "
              f"| {ratio(s, 'ours_threshold', 'fcl_collide')} | {ratio(s, 'ours_tol_1e-02', 'ours_exact')} "
              f"| {ratio(s, 'ours_tree_tol_1e-02', 'ours_tree_exact')} |")
    print()
    print("Targets (issue 6): deforming ≤ 0.1 against FCL rebuild or refit; rigid exact clearance ≤ 1.0 against FCL"
          " prebuilt; validity ≤ 1.0 against FCL collide; 1 % tolerance ≤ 0.3 of exact.")


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    main(sys.argv[1])
