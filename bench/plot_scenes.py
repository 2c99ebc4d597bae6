#!/usr/bin/python3
"""Plots of bench_scenes' CSV: time against error per scene (one point per method and tolerance),
and time against triangle count. Usage: plot_scenes.py SCENES.csv OUT_DIR"""
import csv
import math
import sys

import matplotlib

matplotlib.use("Agg")  # files only, no display
import matplotlib.pyplot as plt  # noqa: E402

# Errors of exactly zero (threshold decisions that were all right, answers equal to the oracle's
# to the last bit) cannot sit on a log axis: they are drawn at this floor, labelled as such.
ERROR_FLOOR = 1e-18

FAMILY_STYLE = {"ours": ("tab:blue", "o"), "fcl": ("tab:red", "s"), "oracle": ("tab:gray", "^")}


def number(text):
    return float(text) if text not in ("", None) else math.nan


def main(csv_path, out_dir):
    with open(csv_path, newline="") as f:
        rows = list(csv.DictReader(f))
    scenes = list(dict.fromkeys(r["scene"] for r in rows))

    columns = min(3, len(scenes))
    lines = math.ceil(len(scenes) / columns)
    fig, axes = plt.subplots(lines, columns, figsize=(5.2 * columns, 4.2 * lines), squeeze=False)
    for ax, scene in zip(axes.flat, scenes):
        for r in (r for r in rows if r["scene"] == scene):
            if r["method"] in ("fcl_collide", "ours_threshold", "ours_tree_threshold", "ours_tree_contact"):
                continue  # yes/no answers: their error is a count of wrong decisions, in the table
            error = number(r["max_error"])
            if math.isnan(error) or int(r["oracle_queries"]) == 0:
                continue
            color, marker = FAMILY_STYLE.get(r["family"], ("black", "x"))
            ax.scatter(max(error, ERROR_FLOOR), number(r["median_us"]) / 1000, color=color, marker=marker)
            ax.annotate(r["method"].replace("ours_", "").replace("fcl_", "fcl "), (max(error, ERROR_FLOOR),
                        number(r["median_us"]) / 1000), fontsize=7, xytext=(3, 3), textcoords="offset points")
        first = next(r for r in rows if r["scene"] == scene)
        ax.set_title(f"{scene} ({first['triangles']} triangles)", fontsize=10)
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_xlabel(f"max |answer - oracle| (0 drawn at {ERROR_FLOOR:g})")
        ax.set_ylabel("median time per query [ms]")
        ax.grid(True, which="both", alpha=0.3)
    for ax in list(axes.flat)[len(scenes):]:
        ax.axis("off")
    fig.suptitle("Time against error (blue: ours, red: FCL, grey: brute-force oracle)")
    fig.tight_layout()
    fig.savefig(f"{out_dir}/time_vs_error.png", dpi=110)

    fig, ax = plt.subplots(figsize=(7, 5))
    for method, color in (("ours_exact", "tab:blue"), ("ours_tol_1e-02", "tab:cyan"), ("ours_tree_exact", "tab:purple"),
                          ("fcl_prebuilt", "tab:red"),
                          ("fcl_rebuild", "tab:orange"), ("fcl_refit", "tab:brown"), ("brute_force", "tab:gray")):
        points = sorted((int(r["triangles"]), number(r["median_us"]) / 1000) for r in rows if r["method"] == method)
        if points:
            ax.plot([p[0] for p in points], [p[1] for p in points], "o-", color=color, label=method)
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("triangles in the scene (both meshes)")
    ax.set_ylabel("median time per query [ms]")
    ax.set_title("Time against triangle count")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(f"{out_dir}/time_vs_triangles.png", dpi=110)
    print(f"plot_scenes.py: wrote {out_dir}/time_vs_error.png and {out_dir}/time_vs_triangles.png")


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit("usage: plot_scenes.py SCENES.csv OUT_DIR")
    main(sys.argv[1], sys.argv[2])
