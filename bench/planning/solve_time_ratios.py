#!/usr/bin/python3
"""Issue 6's end-to-end row: median solve time of RRTConnect and PRM with our checker ÷ with FCL's,
per shipped problem, measured by `adsd benchmark`, the two checkers' runs paired by seed.

usage: solve_time_ratios.py --adsd PROGRAM --problems DIR [--out DIR] [--runs N] [--time SECONDS]
                            [--planners rrtconnect,prm] [--only office,maze,...] [--seed S]
                            [--control adsd|fcl]

For every PROBLEM.cfg in --problems (the build's problem_files directory: the shipped .cfg files
next to the meshes the build generated), writes OUT/cfgs/PROBLEM.cfg: the file's [problem]
section with absolute mesh paths and `objective.threshold` so high that any path meets it, then a
[benchmark] section (--time, one run, no simplification) and a [planner] section listing
--planners. Then, for each run r and each checker C (the order alternating run by run), runs
  adsd benchmark OUT/cfgs/PROBLEM.cfg --checker C --motion discrete --runs 1 --seed SEED+r
                 --out OUT/PROBLEM/placeP-C-r --log-only
then puts all of a problem's logs into OUT/PROBLEM/runs.db with one call of ompl_benchmark_statistics
and reads them from there. Both checkers' run r start from one
seed (common random numbers), so a single-threaded planner such as RRTConnect draws the same
samples with either, and the pair's times differ by the checking alone: far less noise than
independent runs, whose solve times spread over a factor of ten.

Why the threshold: the shipped files ask for short paths, and PRM then keeps improving its roadmap
until the time limit (its solve time is the limit whatever the checker); with a threshold any path
meets, PRM stops at its first solution, as RRTConnect always does. Solve time is then the time to
a first exact solution, the question a validity checker's speed answers.

Solve time is the planner's own: `planner time`, which adsd benchmark measures from the planner's
solve call to its return. OMPL's `time` adds the thread of the termination condition that
Planner::solve(condition, period) starts before the planner and joins after it; that thread sleeps
in steps of 1 ms, so the join waits up to 1 ms whatever the checker, which on the problems solved
in 1-2 ms is most of the difference between runs. The ratio of OMPL's `time` is printed too.

Prints (and writes to OUT/solve_times.md) one Markdown row per problem and planner: runs, exact
solutions found before the time limit, median solve time with each checker (a run without one counts
as the time limit, as OMPL records it), ours ÷ FCL, the same ratio of OMPL's `time`, the two
checkers' time per validity check over all runs (from the runs' validity check counters), ours ÷
FCL, and the share of FCL's solve time its checks took. When half or more of a checker's runs found
no exact solution, its median is the time limit, not a solve time, and the ratio is marked
"censored". Each ratio of medians comes with a 95 % interval: a percentile bootstrap that resamples
the run pairs (both checkers' run r together, as they share a seed), 2000 resamples from a fixed
seed.

--control C runs checker C in both places of every pair (an A/A test): the same command and timing
with nothing to tell apart, so its ratios and intervals show how far this benchmark's rows move on
their own, which a real difference must exceed.
Exit status: 0; 1 when adsd benchmark fails; 2 on bad usage.
"""
import argparse
import collections
import os
import random
import re
import shutil
import sqlite3
import statistics
import subprocess
import sys
import time

# Path-length threshold every path of the shipped problems meets (their workspaces are at most
# tens of metres across and the paths a few hundred segments): PRM stops at its first solution.
ANY_PATH_LENGTH = 1e9
COMBINATION = re.compile(r"^(?:geometric_)?(?P<label>.*) \[(?P<checker>[^,\]]+), (?P<motion>[^\]]+)\]$")


def sections(path):
    """The file's lines grouped by section: a list of (name, lines), name '' before the first."""
    result = [("", [])]
    for line in open(path):
        header = re.match(r"^\s*\[([^\]]+)\]\s*$", line)
        if header:
            result.append((header.group(1).strip().lower(), []))
        else:
            result[-1][1].append(line.rstrip("\n"))
    return result


def variant_cfg(source, planners, runs, seconds):
    """The text of SOURCE's variant: its [problem] (absolute meshes, any path meets the objective),
    then our [benchmark] and [planner]."""
    directory = os.path.dirname(os.path.abspath(source))
    out = ["# Written by bench/planning/solve_time_ratios.py from %s" % os.path.abspath(source)]
    for name, lines in sections(source):
        if name in ("benchmark", "planner"):
            continue
        if name:
            out.append("[%s]" % name)
        for line in lines:
            key = line.split("=", 1)[0].strip().lower() if "=" in line else ""
            if name == "problem" and key in ("robot", "world"):
                value = line.split("=", 1)[1].strip()
                line = "%s = %s" % (key, os.path.normpath(os.path.join(directory, value)))
            if name == "problem" and key == "objective.threshold":
                continue
            out.append(line)
        if name == "problem":
            out.append("objective.threshold = %g" % ANY_PATH_LENGTH)
    # simplify = 0: OMPL's path simplification after each run is not part of the solve time and
    # only lengthens the benchmark.
    out += ["", "[benchmark]", "time_limit = %g" % seconds, "mem_limit = 4000", "run_count = %d" % runs,
            "simplify = 0", "",
            "[planner]"] + ["%s =" % p for p in planners]
    return "\n".join(out) + "\n"


def write_database(logs, database, program="solve_time_ratios.py"):
    """DATABASE made anew from LOGS by one call of ompl_benchmark_statistics, which makes each log
    an experiment, numbered in the order given (one call for all logs, as the program's start-up
    costs more than a short problem's run); opened read-only. PROGRAM names the caller in errors."""
    if os.path.exists(database):
        os.remove(database)
    # Debian's name for OMPL's script, or the name OMPL's own install gives it.
    converter = shutil.which("ompl_benchmark_statistics") or shutil.which("ompl_benchmark_statistics.py")
    if converter is None:
        sys.exit("%s: ompl_benchmark_statistics is not on PATH (Debian package ompl-demos)" % program)
    result = subprocess.run([converter] + logs + ["-d", database],
                            stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
    if result.returncode != 0:
        sys.stderr.write(result.stderr)
        sys.exit("%s: ompl_benchmark_statistics failed on %d logs (exit %d)" % (program, len(logs), result.returncode))
    return sqlite3.connect("file:%s?mode=ro" % database, uri=True)


def read_runs(logs, database):
    """Every run of LOGS as (index of its log in LOGS, database row), from DATABASE
    (write_database)."""
    connection = write_database(logs, database)
    try:
        experiments = connection.execute("SELECT id, seed FROM experiments ORDER BY id").fetchall()
        # Each log is named STEM.seed-S.log after the seed it ran with, which its experiment records.
        if len(experiments) != len(logs) or any(
                not log.endswith(".seed-%s.log" % seed) for log, (_, seed) in zip(logs, experiments)):
            sys.exit("solve_time_ratios.py: the experiments of %s do not match its %d logs in order" % (
                database, len(logs)))
        index = {experiment: i for i, (experiment, _) in enumerate(experiments)}
        rows = connection.execute(
            "SELECT runs.experimentid, plannerConfigs.name, runs.time, runs.planner_time, runs.solved, "
            "runs.approximate_solution, runs.validity_checks, runs.validity_check_time FROM runs "
            "JOIN plannerConfigs ON runs.plannerid = plannerConfigs.id ORDER BY runs.id").fetchall()
        return [(index[row[0]], row[1:]) for row in rows]
    finally:
        connection.close()


def bootstrap_interval(first, second, resamples=2000):
    """95 % percentile-bootstrap interval of median(first) / median(second), resampling the pairs
    (first[i], second[i]) together. The generator's seed is fixed, so one set of runs always gives
    the same interval."""
    generator = random.Random(20261122)
    n = len(first)
    ratios = []
    for _ in range(resamples):
        picked = [generator.randrange(n) for _ in range(n)]
        ratios.append(statistics.median(first[i] for i in picked) / statistics.median(second[i] for i in picked))
    ratios.sort()
    return ratios[int(0.025 * resamples)], ratios[int(0.975 * resamples) - 1]


# One run as the rows use it: solve time (the planner's own; the time limit when it found no exact
# solution in time), OMPL's time (the same way), whether it solved, its validity checks and their time.
Run = collections.namedtuple("Run", "solve ompl exact checks check_time")


def rows_for(problem, runs, seconds):
    """One row per planner: (problem, planner, runs, exact solutions per place, medians, ratio, its
    interval, censored, OMPL time's ratio and interval, per-check ratio, checks' share). RUNS: (place,
    r, database row), place 0 for the checker under test (ours) and 1 for the reference (FCL's)."""
    groups = {}
    for place, r, (name, elapsed, planner_elapsed, solved, approximate, checks, check_time) in runs:
        m = COMBINATION.match(name)
        if not m:
            continue
        # Solved: an exact solution before the time limit (PRM can report one found as the limit
        # stopped it, after as long as an unsolved run took).
        exact = bool(solved) and not bool(approximate) and elapsed < seconds
        groups.setdefault(m.group("label"), ({}, {}))[place][r] = Run(
            solve=planner_elapsed if exact else max(planner_elapsed, seconds),
            ompl=elapsed if exact else max(elapsed, seconds),
            exact=exact, checks=checks or 0, check_time=check_time or 0.0)
    rows = []
    for label, (tested, reference) in groups.items():
        paired = sorted(set(tested) & set(reference))
        if not paired:
            continue
        ours, fcl = [tested[r] for r in paired], [reference[r] for r in paired]

        def times(rs, field):
            return [getattr(r, field) for r in rs]

        def censored(rs):
            return 2 * sum(1 for r in rs if r.exact) <= len(rs)

        def time_per_check(rs):
            checks = sum(r.checks for r in rs)
            return sum(r.check_time for r in rs) / checks if checks else float("nan")

        ratio = statistics.median(times(ours, "solve")) / statistics.median(times(fcl, "solve"))
        interval = bootstrap_interval(times(ours, "solve"), times(fcl, "solve"))
        ompl_ratio = statistics.median(times(ours, "ompl")) / statistics.median(times(fcl, "ompl"))
        ompl_interval = bootstrap_interval(times(ours, "ompl"), times(fcl, "ompl"))
        # What share of the reference's solve time its checks took (both summed over the runs):
        # the same checks at k times the cost each change the solve time by that share times k - 1.
        checking_share = sum(r.check_time for r in fcl) / sum(r.solve for r in fcl)
        rows.append((problem, label, len(ours), sum(r.exact for r in ours), sum(r.exact for r in fcl),
                     statistics.median(times(ours, "solve")), statistics.median(times(fcl, "solve")), ratio,
                     interval, censored(ours) or censored(fcl), ompl_ratio, ompl_interval,
                     time_per_check(ours) / time_per_check(fcl), checking_share))
    return rows


def table(rows, command, control):
    if control:
        names = ("%s (A)" % control, "%s (B)" % control)
        about = ("Control (A/A): checker `%s` in both places of every pair, so the two columns differ by timing "
                 "alone; a ratio away from 1 here is how far this benchmark moves on its own. " % control)
    else:
        names = ("ours", "FCL")
        about = ""
    lines = [about + "Command: `%s`. Median solve time over the runs: the planner's own (`planner time`: its solve "
             "call to its return; OMPL's `time` adds up to 1 ms of waiting for its termination-condition thread, "
             "whose ratio is the column `OMPL time`); a run without an exact solution before the time limit counts "
             "as the limit. Planners stop at their first solution; discrete motion validator. Run r is one `adsd "
             "benchmark --runs 1 --seed SEED+r` per checker, the two back to back (common random numbers: "
             "RRTConnect then draws the same samples with either checker; PRM's two threads make its runs differ "
             "anyway). 95 %% interval: percentile bootstrap of the ratio over the run pairs. Per check: the "
             "checkers' own time per validity check over all runs (the runs' `validity check time` ÷ `validity "
             "checks`), %s ÷ %s: what the checker controls, without the planner's own work and the spread of solve "
             "times. Checks' share: %s's validity check time ÷ its solve time, summed over the runs; making the same "
             "checks at k times the cost per check changes the solve time by that share × (k − 1)." % (
                 command, names[0], names[1], names[1]), "",
             "| problem | planner | runs | solved in time, {0} | solved in time, {1} | median ms, {0} | "
             "median ms, {1} | {0} ÷ {1} | 95 % interval | OMPL time, {0} ÷ {1} (95 % interval) | "
             "per check, {0} ÷ {1} | checks' share, {1} |".format(*names),
             "|---|---|---:|---:|---:|---:|---:|---:|---|---|---:|---:|"]
    for (problem, label, n, ours_ok, fcl_ok, ours_t, fcl_t, ratio, (low, high), censored, ompl_ratio,
         (ompl_low, ompl_high), per_check, share) in rows:
        lines.append("| %s | %s | %d | %d | %d | %.3g | %.3g | %s | %.3g–%.3g | %.3g (%.3g–%.3g) | %.3g | %.2f |" % (
            problem, label, n, ours_ok, fcl_ok, 1e3 * ours_t, 1e3 * fcl_t,
            ("%.3g (censored)" % ratio) if censored else "%.3g" % ratio, low, high, ompl_ratio, ompl_low, ompl_high,
            per_check, share))
    if not control:
        lines += ["", "Target: ours ÷ FCL ≤ 1.0 for RRTConnect and PRM."]
    return "\n".join(lines) + "\n"


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--adsd", required=True, help="the adsd program")
    parser.add_argument("--problems", required=True, help="directory of the shipped problems' .cfg files")
    parser.add_argument("--out", default="solve-times", help="output directory (default: solve-times)")
    parser.add_argument("--runs", type=int, default=10, help="runs per planner and checker (default 10)")
    parser.add_argument("--time", type=float, default=10.0, help="time limit per run in seconds (default 10)")
    parser.add_argument("--planners", default="rrtconnect,prm", help="planners (default rrtconnect,prm)")
    parser.add_argument("--only", help="comma-separated problem names (default: every .cfg in --problems)")
    parser.add_argument("--seed", type=int, default=1, help="seed of run 0; run r uses seed + r (default 1)")
    parser.add_argument("--control", choices=("adsd", "fcl"),
                        help="run this checker in both places of every pair (an A/A test of the benchmark's noise)")
    args = parser.parse_args()
    if args.runs < 1 or not args.time > 0:
        parser.error("--runs and --time must be positive")
    if args.seed < 1 or args.seed + args.runs - 1 > 4294967295:
        parser.error("--seed: run seeds must lie in 1 .. 4294967295 (OMPL takes no seed 0)")
    if not os.access(args.adsd, os.X_OK):
        parser.error("no adsd program at '%s'" % args.adsd)
    problems = sorted(f[:-4] for f in os.listdir(args.problems) if f.endswith(".cfg"))
    if args.only:
        wanted = args.only.split(",")
        unknown = [p for p in wanted if p not in problems]
        if unknown:
            parser.error("no %s.cfg in %s" % (", ".join(unknown), args.problems))
        problems = wanted
    planners = args.planners.split(",")
    os.makedirs(os.path.join(args.out, "cfgs"), exist_ok=True)

    rows = []
    for problem in problems:
        cfg = os.path.join(args.out, "cfgs", problem + ".cfg")
        with open(cfg, "w") as f:
            f.write(variant_cfg(os.path.join(args.problems, problem + ".cfg"), planners, 1, args.time))
        started = time.monotonic()
        logs, places_and_runs = [], []
        # adsd benchmark --out makes its own directory but not a missing parent.
        os.makedirs(os.path.join(args.out, problem), exist_ok=True)
        for r in range(args.runs):
            # Common random numbers: run r of both checkers starts from the same seed, so that a
            # single-threaded planner draws the same samples and builds the same tree with either
            # checker (their answers agree, tests/planner), and the two times differ by the
            # checking alone. The order alternates so that neither checker always runs first.
            seed = args.seed + r
            places = (0, 1) if r % 2 == 0 else (1, 0)
            for place in places:
                checker = args.control or ("adsd", "fcl")[place]
                out_dir = os.path.join(args.out, problem, "place%d-%s-%d" % (place, checker, r))
                command = [args.adsd, "benchmark", cfg, "--checker", checker, "--motion", "discrete",
                           "--runs", "1", "--seed", str(seed), "--out", out_dir, "--log-only"]
                result = subprocess.run(command, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
                if result.returncode != 0:
                    sys.stderr.write(result.stderr)
                    sys.exit("solve_time_ratios.py: %s failed (exit %d)" % (" ".join(command), result.returncode))
                logs.append(os.path.join(out_dir, "%s.seed-%d.log" % (problem, seed)))
                places_and_runs.append((place, r))
        runs = [places_and_runs[i] + (row,) for i, row in read_runs(logs, os.path.join(args.out, problem, "runs.db"))]
        rows += rows_for(problem, runs, args.time)
        print("solve_time_ratios.py: %s done in %.0f s" % (problem, time.monotonic() - started), file=sys.stderr)

    command = "bench/planning/solve_time_ratios.py --runs %d --time %g --planners %s --seed %d%s%s" % (
        args.runs, args.time, args.planners, args.seed, (" --only " + args.only) if args.only else "",
        (" --control " + args.control) if args.control else "")
    text = table(rows, command, args.control)
    with open(os.path.join(args.out, "solve_times.md.tmp"), "w") as f:
        f.write("<!-- generated by bench/planning/solve_time_ratios.py; do not edit -->\n" + text)
    os.replace(os.path.join(args.out, "solve_times.md.tmp"), os.path.join(args.out, "solve_times.md"))
    sys.stdout.write(text)


if __name__ == "__main__":
    main()
