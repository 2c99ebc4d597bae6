#!/usr/bin/python3
"""Issue 4's planning comparison: does `adsd plan` solve every shipped problem that RRTConnect
solves with FCL, within the same time limit?

  problems/compare_checkers.py [--build DIR] [--problems NAME ...] [--seeds N] [--motion KIND ...]
                               [--time SECONDS] [--planner NAME] [--out DIR] [--verify]

For every problem, motion validator and seed 1..N it runs

  adsd plan PROBLEM.cfg --planner rrtconnect --checker {fcl,adsd} --motion M --seed S --no-simplify

FCL then adsd, one after the other (interleaved, so a busy machine slows both alike), with the same
planner, time limit (the cfg's [benchmark] time_limit unless --time), motion validator and seed.
With the same seed and the same answers, both checkers lead RRTConnect through the same states:
the runs differ in what a query costs, not in luck. It prints a Markdown table: runs solved, the
median planning time over all runs (an unsolved run counts as the time limit, so the median is a
time only when most runs solved), and the planner's validity checks and clearance queries with
their mean cost. Every run's output is kept in OUT/logs, every solution in OUT/paths.

--verify then walks every path that a certified run wrote with the brute-force oracle
(test_planner's SolutionPathsVersusOracle.PathFilesNamedInTheEnvironment): no state of an
accepted motion may collide.

Exit status: 0 when every problem FCL solved in some run was solved by adsd in as many runs (and
--verify passed), 1 otherwise, 2 bad arguments or a missing program.
"""
import argparse
import os
import re
import statistics
import subprocess
import sys
import time

PROBLEMS = ["office", "maze", "thin_wall", "bug_trap", "twisted_passage", "alpha_puzzle", "cow_doorway"]
CHECKERS = ["fcl", "adsd"]


def cfg_time_limit(cfg):
    """The [benchmark] time_limit of a cfg, or adsd plan's default of 10 s."""
    section = ""
    with open(cfg) as f:
        for line in f:
            line = line.split("#", 1)[0].strip()
            if line.startswith("["):
                section = line.strip("[]").strip()
            elif section == "benchmark" and "=" in line:
                key, value = (p.strip() for p in line.split("=", 1))
                if key == "time_limit":
                    return float(value)
    return 10.0


def parse_run(output):
    """The fields of `adsd plan`'s summary that the table needs."""
    run = {"solved": False, "seconds": None, "checks": 0, "check_us": 0.0, "clearances": 0, "clearance_us": 0.0,
           "steps": 0}
    m = re.search(r"^solved\s+(yes|no)", output, re.M)
    run["solved"] = bool(m and m.group(1) == "yes")
    m = re.search(r"^time\s+([0-9.]+) s planning", output, re.M)
    if m:
        run["seconds"] = float(m.group(1))
    m = re.search(r"^queries\s+planning: (\d+) validity checks \(mean ([0-9.]+) us\), (\d+) clearance queries "
                  r"\(mean ([0-9.]+) us\)", output, re.M)
    if m:
        run["checks"], run["check_us"] = int(m.group(1)), float(m.group(2))
        run["clearances"], run["clearance_us"] = int(m.group(3)), float(m.group(4))
    m = re.search(r"^motions\s+planning: (\d+) certified checks, (\d+) rejected, (\d+) clearance steps", output, re.M)
    if m:
        run["steps"] = int(m.group(3))
    return run


def summarize(runs, limit):
    solved = [r for r in runs if r["solved"]]
    times = [r["seconds"] if r["solved"] else limit for r in runs]
    median = statistics.median(times)
    median_text = f"{median:.2f} s" if len(solved) * 2 > len(runs) else f"> {limit:g} s"
    checks = statistics.median(r["checks"] for r in runs)
    total_checks = sum(r["checks"] for r in runs)
    check_us = sum(r["checks"] * r["check_us"] for r in runs) / total_checks if total_checks else 0.0
    clearances = statistics.median(r["clearances"] for r in runs)
    total_clearances = sum(r["clearances"] for r in runs)
    clearance_us = (sum(r["clearances"] * r["clearance_us"] for r in runs) / total_clearances
                    if total_clearances else 0.0)
    queries = f"{checks:,.0f} checks ({check_us:.1f} µs)"
    if total_clearances:
        queries += f" + {clearances:,.0f} clearances ({clearance_us:.1f} µs)"
    return f"{len(solved)}/{len(runs)}", median_text, queries, len(solved)


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--build", default=os.path.join(os.path.dirname(here), "build"),
                        help="build directory holding planner/app/adsd and problem_files/ (default: build)")
    parser.add_argument("--problems", nargs="+", default=PROBLEMS, metavar="NAME")
    parser.add_argument("--seeds", type=int, default=5, help="runs per problem and checker, seeds 1..N")
    parser.add_argument("--motion", nargs="+", default=["discrete"], choices=["discrete", "certified"])
    parser.add_argument("--time", type=float, help="time limit in seconds (default: each cfg's time_limit)")
    parser.add_argument("--planner", default="rrtconnect")
    parser.add_argument("--out", default="compare_checkers.out", help="directory for logs and paths")
    parser.add_argument("--verify", action="store_true",
                        help="walk the certified runs' paths with the oracle (needs BUILD/tests/test_planner)")
    args = parser.parse_args()
    if args.seeds < 1:
        parser.error("--seeds must be at least 1")

    adsd = os.path.join(args.build, "planner", "app", "adsd")
    problems_dir = os.path.join(args.build, "problem_files")
    if not os.access(adsd, os.X_OK):
        print(f"compare_checkers.py: error: no program {adsd} (build the adsd target)", file=sys.stderr)
        return 2
    for name in args.problems:
        if not os.path.exists(os.path.join(problems_dir, name + ".cfg")):
            print(f"compare_checkers.py: error: no {name}.cfg in {problems_dir} (build adsd_problems)",
                  file=sys.stderr)
            return 2
    os.makedirs(os.path.join(args.out, "logs"), exist_ok=True)
    os.makedirs(os.path.join(args.out, "paths"), exist_ok=True)

    rows = []
    verify = []
    behind = False
    started = time.time()
    for name in args.problems:
        cfg = os.path.join(problems_dir, name + ".cfg")
        limit = args.time if args.time else cfg_time_limit(cfg)
        for motion in args.motion:
            runs = {c: [] for c in CHECKERS}
            for seed in range(1, args.seeds + 1):
                for checker in CHECKERS:
                    stem = f"{name}.{motion}.{checker}.seed-{seed}"
                    path = os.path.join(args.out, "paths", stem + ".path")
                    if os.path.exists(path):
                        os.remove(path)
                    command = [adsd, "plan", cfg, "--planner", args.planner, "--checker", checker, "--motion", motion,
                               "--seed", str(seed), "--no-simplify", "--time", f"{limit:g}", "--path", path]
                    done = subprocess.run(command, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
                    with open(os.path.join(args.out, "logs", stem + ".log"), "w") as log:
                        log.write(" ".join(command) + "\n" + done.stdout)
                    if done.returncode not in (0, 1):
                        print(f"compare_checkers.py: error: {' '.join(command)} exited {done.returncode}:\n"
                              f"{done.stdout}", file=sys.stderr)
                        return 2
                    run = parse_run(done.stdout)
                    runs[checker].append(run)
                    if run["solved"] and motion == "certified" and os.path.exists(path):
                        verify += [cfg, path]
                    print(f"  {stem}: {'solved' if run['solved'] else 'unsolved'} in {run['seconds']} s "
                          f"({time.time() - started:.0f} s so far)", file=sys.stderr, flush=True)
            fcl = summarize(runs["fcl"], limit)
            ours = summarize(runs["adsd"], limit)
            if fcl[3] > 0 and ours[3] < fcl[3]:
                behind = True
            rows.append((name, motion, f"{limit:g} s", fcl, ours))

    print(f"RRTConnect ({args.planner}), seeds 1..{args.seeds}, no simplification; median planning time over all "
          "runs (unsolved = time limit); planner's queries: median count, mean cost\n")
    print("| problem | motion | limit | FCL solved | FCL median | FCL queries | adsd solved | adsd median | "
          "adsd queries |")
    print("|---|---|---|---|---|---|---|---|---|")
    for name, motion, limit, fcl, ours in rows:
        print(f"| {name} | {motion} | {limit} | {fcl[0]} | {fcl[1]} | {fcl[2]} | {ours[0]} | {ours[1]} | {ours[2]} |")

    status = 1 if behind else 0
    if args.verify and verify:
        test = os.path.join(args.build, "tests", "test_planner")
        env = dict(os.environ, ADSD_VERIFY_PATHS=" ".join(verify))
        done = subprocess.run([test, "--gtest_filter=SolutionPathsVersusOracle.PathFilesNamedInTheEnvironment"],
                              env=env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
        with open(os.path.join(args.out, "logs", "verify.log"), "w") as log:
            log.write(done.stdout)
        print(f"\noracle walk of {len(verify) // 2} certified paths: "
              f"{'no collision' if done.returncode == 0 else 'FAILED (see logs/verify.log)'}")
        for line in done.stdout.splitlines():
            if line.startswith("[") and "motions" in line:
                print("  " + line)
        if done.returncode != 0:
            status = 1
    return status


if __name__ == "__main__":
    sys.exit(main())
