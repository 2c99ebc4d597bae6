#!/usr/bin/python3
"""Summary table and plots of an OMPL benchmark database (the SQLite file `ompl_benchmark_statistics`
writes from `adsd benchmark`'s logs, one log or many merged).

usage: plot_benchmark.py DB [--out DIR] [--prefix STEM] [--no-plots]

Prints a Markdown summary per problem and planner configuration (runs, solved, median solve time,
median solution clearance: OMPL's, the mean of the clearance at the path's states, not their
minimum, our query counters) and the FCL / adsd ratios, and writes it to
DIR/STEM.summary.md. Unless --no-plots, draws from the same rows:
  DIR/STEM.time.png       solve time per planner, checker and motion validator (all runs)
  DIR/STEM.clearance.png  solution clearance of the solved runs (after simplification when the
                          benchmark simplified)
  DIR/STEM.queries.png    mean time per validity check and per clearance query
STEM defaults to the database's file name without its extension, DIR to its directory.

Planner configurations are grouped by name, as Planner Arena groups them; `adsd benchmark` names
them "LABEL [CHECKER, MOTION]" and records the checker and motion validator in every run.
"""
import argparse
import math
import os
import re
import sqlite3
import statistics
import sys

COMBINATION = re.compile(r"^(?P<label>.*) \[(?P<checker>[^,\]]+), (?P<motion>[^\]]+)\]$")
CHECKER_COLOUR = {"adsd": "tab:blue", "fcl": "tab:red"}
MICROSECONDS = 1e6


def read_runs(path):
    """Every run as a dict of its columns, plus 'problem' and 'planner' (without 'geometric_')."""
    if not os.path.isfile(path):
        sys.exit("plot_benchmark.py: error: no database '%s'" % path)
    connection = sqlite3.connect("file:%s?mode=ro" % path, uri=True)
    connection.row_factory = sqlite3.Row
    try:
        rows = connection.execute(
            "SELECT experiments.name AS problem, plannerConfigs.name AS planner, runs.* FROM runs "
            "JOIN plannerConfigs ON runs.plannerid = plannerConfigs.id "
            "JOIN experiments ON runs.experimentid = experiments.id "
            "ORDER BY experiments.name, runs.id").fetchall()
    except sqlite3.DatabaseError as e:
        sys.exit("plot_benchmark.py: error: %s is not an OMPL benchmark database (%s)" % (path, e))
    finally:
        connection.close()
    runs = []
    for row in rows:
        run = dict(row)
        run["planner"] = re.sub(r"^(geometric|control)_", "", run["planner"])
        runs.append(run)
    return runs


class Group:
    """The runs of one planner configuration on one problem."""

    def __init__(self, problem, planner):
        self.problem = problem
        self.planner = planner
        m = COMBINATION.match(planner)
        self.label = m.group("label") if m else planner
        self.checker = m.group("checker") if m else ""
        self.motion = m.group("motion") if m else ""
        self.runs = []

    def values(self, column, solved_only=False):
        out = []
        for r in self.runs:
            if solved_only and not r.get("solved"):
                continue
            v = r.get(column)
            if v is not None and not (isinstance(v, float) and math.isnan(v)):
                out.append(float(v))
        return out

    def solved(self):
        return sum(1 for r in self.runs if r.get("solved"))

    def solved_in_contact(self):
        """Solved runs whose path comes within the margin (adsd benchmark's "path in contact": a
        discrete validator's path that stepped over an obstacle); "–" for a log without the column."""
        if not any(r.get("path_in_contact") is not None for r in self.runs):
            return "–"
        return "%d" % sum(1 for r in self.runs if r.get("solved") and r.get("path_in_contact"))

    def pooled_mean(self, seconds_column, count_column):
        """Total time over total count: each query weighs the same, whatever run it was in."""
        seconds, count = sum(self.values(seconds_column)), sum(self.values(count_column))
        return seconds / count if count > 0 else None

    def clearance_column(self):
        has_simplified = any(r.get("simplified_solution_clearance") is not None for r in self.runs)
        return "simplified_solution_clearance" if has_simplified else "solution_clearance"


def group_runs(runs):
    groups = {}
    for r in runs:
        key = (r["problem"], r["planner"])
        if key not in groups:
            groups[key] = Group(*key)
        groups[key].runs.append(r)
        # Our columns, when present, say the combination even if the name was changed.
        g = groups[key]
        if r.get("checker"):
            g.checker = str(r["checker"])
        if r.get("motion_validator"):
            g.motion = str(r["motion_validator"])
    # Side by side: each planner's combinations together, ours beside FCL's (order of appearance).
    ordered = list(groups.values())
    order = {}
    for g in ordered:
        for field in ("problem", "label", "motion", "checker"):
            order.setdefault((field, getattr(g, field)), len(order))
    return sorted(ordered, key=lambda g: tuple(order[(f, getattr(g, f))] for f in ("problem", "label", "motion", "checker")))


def cell(text):
    """Text for a Markdown table cell: a planner named 'a | b' split its row into two cells."""
    return text.replace("|", "\\|")


def median(values):
    return statistics.median(values) if values else None


def fmt(value, digits=3):
    if value is None:
        return "–"
    if isinstance(value, int):
        return str(value)
    if value == 0:
        return "0"
    return "%.*g" % (digits, value)


def count(value):
    """A median of counts: whole numbers, a half where the median falls between two runs."""
    return "–" if value is None else ("%d" % value if value == int(value) else "%.1f" % value)


def summary(groups):
    lines = []
    for problem in dict.fromkeys(g.problem for g in groups):
        members = [g for g in groups if g.problem == problem]
        lines += ["## %s" % problem, "",
                  "| planner | checker | motion | runs | solved | solved, path in contact | median time (s) | "
                  "median clearance (mean over the path's states) | "
                  "median validity checks | mean validity check (µs) | median clearance queries | "
                  "mean clearance query (µs) | median query time fraction |",
                  "|---|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|"]
        for g in members:
            validity = g.pooled_mean("validity_check_time", "validity_checks")
            clearance = g.pooled_mean("clearance_query_time", "clearance_queries")
            lines.append("| %s | %s | %s | %d | %d (%.0f %%) | %s | %s | %s | %s | %s | %s | %s | %s |" % (
                cell(g.label), g.checker or "–", g.motion or "–", len(g.runs), g.solved(),
                100.0 * g.solved() / len(g.runs), g.solved_in_contact(), fmt(median(g.values("time"))),
                fmt(median(g.values(g.clearance_column(), solved_only=True))),
                count(median(g.values("validity_checks"))),
                fmt(validity * MICROSECONDS if validity is not None else None),
                count(median(g.values("clearance_queries"))),
                fmt(clearance * MICROSECONDS if clearance is not None else None),
                fmt(median(g.values("query_time_fraction")))))
        lines.append("")
        ratios = []
        for ours in (g for g in members if g.checker == "adsd"):
            for theirs in (g for g in members if g.checker == "fcl" and g.label == ours.label and g.motion == ours.motion):
                def ratio(a, b):
                    return a / b if a is not None and b not in (None, 0) else None
                ratios.append("| %s | %s | %s | %s | %s |" % (
                    cell(ours.label), ours.motion,
                    fmt(ratio(median(theirs.values("time")), median(ours.values("time")))),
                    fmt(ratio(theirs.pooled_mean("validity_check_time", "validity_checks"),
                              ours.pooled_mean("validity_check_time", "validity_checks"))),
                    fmt(ratio(theirs.pooled_mean("clearance_query_time", "clearance_queries"),
                              ours.pooled_mean("clearance_query_time", "clearance_queries")))))
        if ratios:
            lines += ["FCL ÷ adsd in this benchmark (above 1: adsd faster). The runs are not paired: each "
                      "checker's runs draw their own samples, so the median times differ by the draws as well "
                      "as by the checkers; the per-query means compare like with like. Paired runs: one "
                      "process per run and seed (`--runs 1 --seed S`, as bench/planning/solve_time_ratios.py "
                      "runs them).", "",
                      "| planner | motion | median time | mean validity check | mean clearance query |",
                      "|---|---|---:|---:|---:|"] + ratios + [""]
    return "\n".join(lines)


def write_atomically(path, write):
    """Writes through a temporary name renamed over `path`; a failure leaves neither."""
    temporary = path + ".tmp"
    try:
        write(temporary)
        os.replace(temporary, path)
    except BaseException:
        if os.path.lexists(temporary) and not os.path.isdir(temporary):
            os.remove(temporary)
        raise


def tick(g):
    return "%s\n%s\n%s" % (g.label, g.checker, g.motion) if g.checker else g.label


def plot(groups, out_dir, prefix):
    import matplotlib
    matplotlib.use("Agg")  # files only, no display
    import matplotlib.pyplot as plt

    problems = list(dict.fromkeys(g.problem for g in groups))
    written = []

    def figure(draw, name, ylabel):
        fig, axes = plt.subplots(len(problems), 1, squeeze=False,
                                 figsize=(max(6.0, 1.3 * max(len([g for g in groups if g.problem == p])
                                                              for p in problems) + 2), 4.2 * len(problems)))
        for ax, problem in zip(axes[:, 0], problems):
            members = [g for g in groups if g.problem == problem]
            draw(ax, members)
            ax.set_title(problem, pad=14)
            ax.set_ylabel(ylabel)
            ax.grid(True, axis="y", alpha=0.3)
            ax.set_xticks(range(1, len(members) + 1))
            ax.set_xticklabels([tick(g) for g in members], fontsize=8)
            ax.set_xlim(0.4, len(members) + 0.6)
        fig.tight_layout()
        path = os.path.join(out_dir, "%s.%s.png" % (prefix, name))
        write_atomically(path, lambda p: fig.savefig(p, dpi=110, format="png"))
        plt.close(fig)
        written.append(path)

    def boxes(ax, members, series, annotate):
        data = [series(g) for g in members]
        positions = [i + 1 for i, d in enumerate(data) if d]
        shown = [d for d in data if d]
        if shown:
            parts = ax.boxplot(shown, positions=positions, widths=0.6, patch_artist=True, showfliers=True)
            shown_groups = [g for g, d in zip(members, data) if d]
            for box, g in zip(parts["boxes"], shown_groups):
                box.set_facecolor(CHECKER_COLOUR.get(g.checker, "tab:gray"))
                box.set_alpha(0.55)
                if g.motion == "certified":
                    box.set_hatch("//")
            everything = [v for d in shown for v in d if v > 0]
            if everything and max(everything) / min(everything) > 50:
                ax.set_yscale("log")
        for i, g in enumerate(members):
            ax.annotate(annotate(g), (i + 1, 1.0), xycoords=("data", "axes fraction"), ha="center", va="bottom",
                        fontsize=7)

    figure(lambda ax, m: boxes(ax, m, lambda g: g.values("time"),
                               lambda g: "solved %d/%d" % (g.solved(), len(g.runs))),
           "time", "solve time (s), all runs")
    figure(lambda ax, m: boxes(ax, m, lambda g: g.values(g.clearance_column(), solved_only=True),
                               lambda g: "%d solved" % g.solved()),
           "clearance", "solution clearance, mean over the path's states (solved runs)")

    def query_bars(ax, members):
        from matplotlib.patches import Patch
        width = 0.38
        kinds = (("validity_check_time", "validity_checks", "validity check", ""),
                 ("clearance_query_time", "clearance_queries", "clearance query", ".."))
        drawn = False
        for offset, (seconds, count, _, hatch) in zip((-width / 2, width / 2), kinds):
            for i, g in enumerate(members):
                mean = g.pooled_mean(seconds, count)
                if mean is None:
                    continue
                ax.bar(i + 1 + offset, mean * MICROSECONDS, width, color=CHECKER_COLOUR.get(g.checker, "tab:gray"),
                       alpha=0.7, hatch=hatch, edgecolor="black", linewidth=0.5)
                drawn = True
        if drawn:
            ax.set_yscale("log")
            checkers = list(dict.fromkeys(g.checker for g in members if g.checker))
            ax.legend([Patch(facecolor=CHECKER_COLOUR.get(c, "tab:gray"), alpha=0.7) for c in checkers] +
                      [Patch(facecolor="white", edgecolor="black", hatch=h) for _, _, _, h in kinds],
                      checkers + [k[2] for k in kinds], fontsize=8)

    figure(query_bars, "queries", "mean time per query (µs), planning only")
    return written


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("database")
    parser.add_argument("--out", help="directory for the summary and the plots (default: the database's)")
    parser.add_argument("--prefix", help="file-name stem (default: the database's name without extension)")
    parser.add_argument("--no-plots", action="store_true", help="the summary only")
    args = parser.parse_args()

    runs = read_runs(args.database)
    if not runs:
        sys.exit("plot_benchmark.py: error: %s has no runs" % args.database)
    groups = group_runs(runs)
    out_dir = args.out or os.path.dirname(os.path.abspath(args.database))
    prefix = args.prefix or os.path.splitext(os.path.basename(args.database))[0]
    os.makedirs(out_dir, exist_ok=True)

    text = summary(groups)
    print(text)
    summary_path = os.path.join(out_dir, prefix + ".summary.md")

    def write_summary(path):
        with open(path, "w") as f:
            f.write(text + "\n")
    write_atomically(summary_path, write_summary)
    print("summary     %s" % summary_path)
    if not args.no_plots:
        for path in plot(groups, out_dir, prefix):
            print("plot        %s" % path)


if __name__ == "__main__":
    main()
