#!/usr/bin/python3
"""Time against error, one panel per band, from bench_bands' CSV.

    bench/plot_bands.py BANDS.csv OUT.png

Each point is one scene and one method: x the median microseconds per query, y the largest error
against FCL's exact distance on that scene's queries in that band, as a fraction of the scene's
reference length L (FCL's own points sit on the floor of the axis: they are the reference; the
floor is 1e-17). Our capped query is compared with min(FCL's distance, the cap). The collision band
has no distance methods and no panel.
"""
import collections
import csv
import statistics
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

FLOOR = 1e-17
CAP_FRACTION = 0.05  # bench_bands' kCapFraction
METHODS = {  # method: (label, colour, marker)
    "exact": ("ours exact", "tab:blue", "o"),
    "tolerance": ("ours 1 % tolerance", "tab:cyan", "^"),
    "capped": ("ours capped at 5 % L", "tab:purple", "s"),
    "fcl_distance": ("FCL distance (reference)", "tab:red", "x"),
}
BANDS = ["near", "mid", "far", "uniform"]


def main(argv):
    if len(argv) != 3:
        sys.exit(__doc__)
    times = collections.defaultdict(list)   # (band, scene, method) -> microseconds
    answers = {}                            # (band, scene, method, query) -> answer
    lengths = {}
    with open(argv[1], newline="") as f:
        for row in csv.DictReader(f):
            key = (row["band"], row["scene"], row["method"])
            times[key].append(float(row["microseconds"]))
            answers[key + (int(row["query"]),)] = float(row["answer"])
            lengths[row["scene"]] = float(row["reference_length"])
    bands = [b for b in BANDS if any(k[0] == b for k in times)]
    if not bands:
        sys.exit(f"{argv[1]}: no distance bands")
    fig, axes = plt.subplots(1, len(bands), figsize=(4.2 * len(bands), 4.2), sharey=True, squeeze=False)
    for ax, band in zip(axes[0], bands):
        for method, (label, colour, marker) in METHODS.items():
            xs, ys = [], []
            for (b, scene, m), samples in times.items():
                if b != band or m != method:
                    continue
                length = lengths[scene]
                worst = 0.0
                queries = {k[3] for k in answers if k[:3] == (b, scene, m)}
                for q in queries:
                    reference = answers[(b, scene, "fcl_distance", q)]
                    if method == "capped":
                        reference = min(reference, CAP_FRACTION * length)
                    worst = max(worst, abs(answers[(b, scene, m, q)] - reference) / length)
                xs.append(statistics.median(samples))
                ys.append(max(worst, FLOOR))
            ax.scatter(xs, ys, c=colour, marker=marker, label=label, s=28)
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_title(band)
        ax.set_xlabel("median µs per query")
        ax.grid(True, which="both", alpha=0.3)
    axes[0][0].set_ylabel("largest error against FCL / L")
    axes[0][-1].legend(fontsize=8, loc="upper right")
    fig.tight_layout()
    fig.savefig(argv[2], dpi=110)


if __name__ == "__main__":
    main(sys.argv)
