#!/usr/bin/python3
"""Clearance-optimal planning: the mean clearance query of RRT* with the clearance objective, with
our checker ÷ with FCL's, per shipped problem, measured by `adsd benchmark` on the same seeds.

usage: clearance_query_ratios.py --adsd PROGRAM --problems DIR [--out DIR] [--seeds N] [--time SECONDS]
                                 [--only office,maze,...] [--planner rrtstar]

An optimizing planner asks the checker for clearance at every state it connects, near obstacles
and far from them alike; that query, not the validity check, is then the checker's cost. For every
PROBLEM.cfg in --problems, writes OUT/cfgs/PROBLEM.cfg (solve_time_ratios.py's variant: absolute
mesh paths, an objective threshold no path meets, so that the planner uses its whole time) with
`objective = max_min_clearance` and the one planner --planner, then for seeds 1..N and both
checkers (the order alternating seed by seed) runs
  adsd benchmark OUT/cfgs/PROBLEM.cfg --checker C --motion discrete --runs 1 --seed S --log-only
and reads every run's clearance queries and their time from one ompl_benchmark_statistics
database. Prints one Markdown row per problem: runs, clearance queries per run (median, each
checker), microseconds per clearance query over all runs (each checker: their total time ÷ their
count), ours ÷ FCL, and the lowest and highest per-run ratio. The two checkers' runs share a seed
but not their samples after the first answer that differs, so the queries differ too; the ratio is
of mean costs, over the states each run asked about.

Exit status: 0; 1 when adsd benchmark or ompl_benchmark_statistics fails; 2 on bad usage.
"""
import argparse
import os
import re
import statistics
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from solve_time_ratios import COMBINATION, variant_cfg, write_database  # noqa: E402


def clearance_cfg(source, planner, seconds):
    text = variant_cfg(source, [planner], 1, seconds)
    text = text.replace("# Written by bench/planning/solve_time_ratios.py",
                        "# Written by bench/planning/clearance_query_ratios.py")
    if re.search(r"^objective\s*=", text, re.M):
        return re.sub(r"^objective\s*=.*$", "objective = max_min_clearance", text, count=1, flags=re.M)
    return text.replace("[problem]\n", "[problem]\nobjective = max_min_clearance\n", 1)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--adsd", required=True)
    parser.add_argument("--problems", required=True)
    parser.add_argument("--out", default="clearance_queries")
    parser.add_argument("--seeds", type=int, default=5)
    parser.add_argument("--time", type=float, default=8.0)
    parser.add_argument("--only", default="")
    parser.add_argument("--planner", default="rrtstar")
    a = parser.parse_args()
    if a.seeds < 1 or not a.time > 0:
        parser.error("--seeds must be at least 1 and --time positive")
    only = [p for p in a.only.split(",") if p]
    problems = sorted(f[:-4] for f in os.listdir(a.problems) if f.endswith(".cfg"))
    if only:
        unknown = sorted(set(only) - set(problems))
        if unknown:
            parser.error("no such problem in %s: %s" % (a.problems, ", ".join(unknown)))
        problems = [p for p in problems if p in only]
    os.makedirs(os.path.join(a.out, "cfgs"), exist_ok=True)
    rows = []
    for problem in problems:
        cfg = os.path.join(a.out, "cfgs", problem + ".cfg")
        with open(cfg, "w") as f:
            f.write(clearance_cfg(os.path.join(a.problems, problem + ".cfg"), a.planner, a.time))
        logs, checkers = [], []
        # adsd benchmark --out makes its own directory but not a missing parent.
        os.makedirs(os.path.join(a.out, problem), exist_ok=True)
        for seed in range(1, a.seeds + 1):
            order = ["adsd", "fcl"] if seed % 2 else ["fcl", "adsd"]
            for checker in order:
                out = os.path.join(a.out, problem, "%s-%d" % (checker, seed))
                command = [a.adsd, "benchmark", cfg, "--checker", checker, "--motion", "discrete", "--runs", "1",
                           "--seed", str(seed), "--out", out, "--log-only"]
                result = subprocess.run(command, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
                if result.returncode != 0:
                    sys.stderr.write(result.stderr)
                    sys.exit("clearance_query_ratios.py: %s failed (exit %d)" % (" ".join(command), result.returncode))
                found = [os.path.join(out, f) for f in os.listdir(out) if f.endswith(".log")]
                if len(found) != 1:
                    sys.exit("clearance_query_ratios.py: expected one log in %s, found %d" % (out, len(found)))
                logs.append(found[0])
                checkers.append((checker, seed))
        connection = write_database(logs, os.path.join(a.out, problem, "runs.db"), "clearance_query_ratios.py")
        try:
            experiments = [e for (e,) in connection.execute("SELECT id FROM experiments ORDER BY id")]
            runs = connection.execute(
                "SELECT runs.experimentid, plannerConfigs.name, runs.clearance_queries, runs.clearance_query_time "
                "FROM runs JOIN plannerConfigs ON runs.plannerid = plannerConfigs.id").fetchall()
        finally:
            connection.close()
        per = {"adsd": {}, "fcl": {}}
        for experiment, name, queries, seconds in runs:
            m = COMBINATION.match(name)
            checker, seed = checkers[experiments.index(experiment)]
            if not m or m.group("checker") != checker:
                sys.exit("clearance_query_ratios.py: run of %s does not match its log (%s)" % (name, checker))
            per[checker][seed] = (queries or 0, seconds or 0.0)
        seeds = sorted(set(per["adsd"]) & set(per["fcl"]))
        if not seeds or any(per[c][s][0] == 0 for c in per for s in seeds):
            sys.exit("clearance_query_ratios.py: %s: a run made no clearance query" % problem)

        def micros(checker):
            return 1e6 * sum(per[checker][s][1] for s in seeds) / sum(per[checker][s][0] for s in seeds)

        per_run = [(per["adsd"][s][1] / per["adsd"][s][0]) / (per["fcl"][s][1] / per["fcl"][s][0]) for s in seeds]
        rows.append((problem, len(seeds), statistics.median(per["adsd"][s][0] for s in seeds),
                     statistics.median(per["fcl"][s][0] for s in seeds), micros("adsd"), micros("fcl"),
                     micros("adsd") / micros("fcl"), min(per_run), max(per_run)))
    lines = ["Command: `bench/planning/clearance_query_ratios.py --seeds %d --time %g --planner %s%s`. RRT* (or "
             "--planner) with objective = max_min_clearance, discrete motion validation, one run per seed and "
             "checker." % (a.seeds, a.time, a.planner, (" --only " + a.only) if only else ""),
             "",
             "| problem | runs | clearance queries per run, ours | FCL's | µs per clearance query, ours | FCL's | ours ÷ FCL | per-run range |",
             "|---|---:|---:|---:|---:|---:|---:|---|"]
    for r in rows:
        lines.append("| %s | %d | %.0f | %.0f | %.3g | %.3g | %.3g | %.3g–%.3g |" % r)
    text = "\n".join(lines) + "\n"
    with open(os.path.join(a.out, "clearance_queries.md"), "w") as f:
        f.write(text)
    print(text, end="")


if __name__ == "__main__":
    main()
