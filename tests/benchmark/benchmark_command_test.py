#!/usr/bin/python3
"""`adsd benchmark` run as a user runs it, on the shipped thin-wall problem with tiny runs.

usage: benchmark_command_test.py --adsd PROGRAM --problems DIR --work DIR

Checks: bad input stops with exit status 2 and one line before anything is written; a missing
ompl_benchmark_statistics stops with exit status 1 before the runs; a run over both checkers and
both motion validators writes a log, a database that ompl_benchmark_statistics accepted, a summary
and plots, and the database holds the experiment, the four combinations and our columns with
values consistent with each other; shards (--run-range, --seed, --log-only) write their own logs
with their own seeds, and ompl_benchmark_statistics merges them into one database; the script
found by the name OMPL's own install gives it (ompl_benchmark_statistics.py) serves as well.
"""
import argparse
import os
import shutil
import sqlite3
import subprocess
import sys

failures = []

# Our run properties and their SQL types as ompl_benchmark_statistics declares them.
OUR_COLUMNS = {
    "checker": "STRING",
    "motion_validator": "STRING",
    "run_index": "INTEGER",
    "planner_time": "REAL",
    "validity_checks": "INTEGER",
    "clearance_queries": "INTEGER",
    "validity_check_time": "REAL",
    "clearance_query_time": "REAL",
    "mean_validity_check_time": "REAL",
    "mean_clearance_query_time": "REAL",
    "motion_checks": "INTEGER",
    "motions_rejected": "INTEGER",
    "certified_clearance_steps": "INTEGER",
    "query_time_fraction": "REAL",
    "path_least_clearance": "REAL",
    "path_in_contact": "BOOLEAN",
}
OMPL_COLUMNS = {"time": "REAL", "solved": "BOOLEAN", "solution_clearance": "REAL", "valid_segment_fraction": "REAL"}
COMBINATIONS = [("adsd", "discrete"), ("adsd", "certified"), ("fcl", "discrete"), ("fcl", "certified")]
TIME_LIMIT = 1.0
RUNS = 2
# Our counters' times are sums of nanosecond counts; the mean is that sum over the count, written
# with OMPL's full double precision: this much relative rounding is all that may separate them.
RELATIVE_ROUNDING = 1e-9


def check(condition, what):
    if not condition:
        failures.append(what)
        print("FAIL: " + what, flush=True)
    return condition


def run(adsd, args, env=None):
    shown = " ".join(["adsd", "benchmark"] + args)
    print("$ " + shown, flush=True)
    p = subprocess.run([adsd, "benchmark"] + args, capture_output=True, text=True, timeout=240, env=env)
    print("  -> exit %d" % p.returncode, flush=True)
    return p


def expect_bad_input(adsd, args, needle, out_dir, status=2, env=None):
    p = run(adsd, args + ["--out", out_dir], env=env)
    shown = " ".join(args)
    check(p.returncode == status, "%s: exit status %d, expected %d\nstderr: %s" % (shown, p.returncode, status, p.stderr))
    lines = p.stderr.splitlines()
    check(len(lines) == 1, "%s: expected one line on stderr, got:\n%s" % (shown, p.stderr))
    check(needle in p.stderr, "%s: stderr does not name '%s':\n%s" % (shown, needle, p.stderr))
    check(p.stdout == "", "%s: wrote to stdout on bad input:\n%s" % (shown, p.stdout))
    check(not os.path.exists(out_dir), "%s: created %s on bad input" % (shown, out_dir))


def thin_wall_cfg(work, problems, name, planners):
    """A thin-wall problem file named NAME.cfg in WORK, with the [planner] lines PLANNERS (its
    first on line 16)."""
    path = os.path.join(work, name + ".cfg")
    with open(path, "w") as f:
        f.write("[problem]\nname = %s\n" % name +
                "robot = %s\nworld = %s\n" % (os.path.join(problems, "thin_wall_robot.obj"),
                                              os.path.join(problems, "thin_wall_env.obj")) +
                "start.x = -2.03\nstart.y = -1\nstart.theta = 0\ngoal.x = 1.97\ngoal.y = -1\ngoal.theta = 0\n"
                "volume.min.x = -4\nvolume.min.y = -4\nvolume.max.x = 4\nvolume.max.y = 4\n"
                "[planner]\n" + planners)
    return path


def bad_input(adsd, cfg, problems, work):
    cases = [
        (["--checker", "nope"], "--checker"),
        (["--motion", "sometimes"], "--motion"),
        (["--run-range", "3:3"], "--run-range"),
        (["--run-range", "2"], "--run-range"),
        (["--run-range", "a:4"], "--run-range"),
        (["--runs", "0"], "--runs"),
        (["--runs", "2", "--run-range", "0:2"], "--run-range"),
        (["--seed", "0"], "--seed"),
        # Beyond OMPL's 64-bit seed type (its own seeds, printed, are taken back: 16 digits).
        (["--seed", "18446744073709551616"], "--seed"),
        (["--time", "-1"], "--time"),
        (["--log-only", "--no-plots"], "--log-only"),
        (["--frobnicate"], "--frobnicate"),
    ]
    for i, (args, needle) in enumerate(cases):
        expect_bad_input(adsd, [cfg] + args, needle, os.path.join(work, "bad%d" % i))
    expect_bad_input(adsd, [os.path.join(work, "missing.cfg")], "missing.cfg", os.path.join(work, "bad_missing"))

    # A planner parameter OMPL rejects: the message names the file, the line and the key.
    bad_cfg = thin_wall_cfg(work, problems, "bad_range", "rrtconnect =\nrrtconnect.range = far\n")
    expect_bad_input(adsd, [bad_cfg], "bad_range.cfg:17", os.path.join(work, "bad_param"))

    # No ompl_benchmark_statistics on PATH: exit 1 before any run, nothing written.
    env = dict(os.environ, PATH=os.path.join(work, "empty-path"))
    expect_bad_input(adsd, [cfg], "ompl_benchmark_statistics", os.path.join(work, "bad_tool"), status=1, env=env)


def clearance_not_simplified(adsd, problems, work):
    """A problem planned for clearance is benchmarked without OMPL's simplifier, as adsd plan keeps
    such a path: the runs recorded the simplifier's shortcut, back towards the wall (the maze: 5 of
    8 RRT* paths in contact; an outside review). simplify = 1 in the file still asks for it."""
    for name, line, simplified in (("clearance", "", False), ("clearance_simplified", "simplify = 1\n", True)):
        cfg = thin_wall_cfg(work, problems, name, "rrtstar =\n")
        with open(cfg) as f:
            text = f.read().replace("[planner]", "objective = max_min_clearance\n[benchmark]\n" + line + "[planner]")
        with open(cfg, "w") as f:
            f.write(text)
        out = os.path.join(work, name)
        p = run(adsd, [cfg, "--runs", "1", "--time", "0.3", "--checker", "adsd", "--motion", "discrete", "--out", out])
        if not check(p.returncode == 0, "%s: exit status %d\nstderr: %s" % (name, p.returncode, p.stderr)):
            continue
        db = sqlite3.connect(os.path.join(out, name + ".db"))
        times = [r[0] for r in db.execute("SELECT simplification_time FROM runs")] \
            if "simplification_time" in columns(db) else []
        check(any(t is not None for t in times) == simplified,
              "%s: simplification times %s, expected %s" % (name, times, "some" if simplified else "none"))


def statistics_program():
    """OMPL's log-to-database script on PATH: Debian's name, or the one OMPL's own install gives it."""
    return shutil.which("ompl_benchmark_statistics") or shutil.which("ompl_benchmark_statistics.py")


def upstream_name(adsd, cfg, work, statistics):
    """OMPL's own install (a source build, as of OMPL 2.0) names the script with its .py: with only
    that name on PATH the benchmark still writes its database (it stopped, saying the program was
    not on PATH)."""
    path = os.path.join(work, "upstream-path")
    os.makedirs(path)
    os.symlink(os.path.realpath(statistics), os.path.join(path, "ompl_benchmark_statistics.py"))
    out = os.path.join(work, "upstream")
    p = run(adsd, [cfg, "--runs", "1", "--time", "0.2", "--checker", "adsd", "--motion", "discrete", "--out", out],
            env=dict(os.environ, PATH=path))
    if not check(p.returncode == 0, "upstream name: exit status %d\nstderr: %s" % (p.returncode, p.stderr)):
        return
    database = os.path.join(out, "thin_wall.db")
    if check(os.path.isfile(database), "upstream name: thin_wall.db not written"):
        runs = sqlite3.connect(database).execute("SELECT COUNT(*) FROM runs").fetchone()[0]
        check(runs == 1, "upstream name: %d runs in the database, expected 1" % runs)


def repeated_instances(adsd, problems, work):
    """A planner's line repeated (the format's way to run it with other parameters) gives rows of
    their own, numbered: the summary merged their runs into one row. A name with '|' keeps its row
    in one cell; an empty name is refused."""
    cfg = thin_wall_cfg(work, problems, "repeated", "rrtconnect =\nrrtconnect =\nrrtconnect.range = 0.5\nrrt =\n"
                                          "rrt.name = a | b\n")
    out = os.path.join(work, "repeated")
    p = run(adsd, [cfg, "--runs", "1", "--time", "0.2", "--checker", "adsd", "--motion", "discrete", "--out", out])
    if not check(p.returncode == 0, "repeated instances: exit status %d\nstderr: %s" % (p.returncode, p.stderr)):
        return
    for row in ("| RRTConnect | adsd | discrete | 1 |", "| RRTConnect #2 | adsd | discrete | 1 |",
                "| a \\| b | adsd | discrete | 1 |"):
        check(row in p.stdout, "repeated instances: no summary row starting %r:\n%s" % (row, p.stdout))
    check("repeated.cfg:17: key 'planner.rrtconnect': another instance named 'RRTConnect': its results are named "
          "'RRTConnect #2'" in p.stderr, "repeated instances: no warning naming the second line:\n" + p.stderr)
    empty = thin_wall_cfg(work, problems, "empty_name", "rrtconnect =\nrrtconnect.name =\n")
    expect_bad_input(adsd, [empty], "empty_name.cfg:17: key 'planner.rrtconnect.name': a planner's name may not be empty",
                     os.path.join(work, "bad_empty_name"))


def columns(db):
    return {row[1]: row[2] for row in db.execute("PRAGMA table_info(runs)")}


def close(a, b):
    return abs(a - b) <= RELATIVE_ROUNDING * max(abs(a), abs(b))


def full_run(adsd, cfg, work):
    out = os.path.join(work, "full")
    p = run(adsd, [cfg, "--runs", str(RUNS), "--time", str(TIME_LIMIT), "--out", out])
    print(p.stdout)
    if not check(p.returncode == 0, "full run: exit status %d\nstderr: %s" % (p.returncode, p.stderr)):
        return
    for name in ("thin_wall.log", "thin_wall.db", "thin_wall.summary.md"):
        check(os.path.isfile(os.path.join(out, name)), "full run: %s not written" % name)
    for name in ("thin_wall.time.png", "thin_wall.clearance.png", "thin_wall.queries.png"):
        path = os.path.join(out, name)
        if check(os.path.isfile(path), "full run: %s not written" % name):
            with open(path, "rb") as f:
                check(f.read(8) == b"\x89PNG\r\n\x1a\n", "full run: %s is not a PNG" % name)
    check(not [f for f in os.listdir(out) if f.endswith(".tmp")], "full run: temporary files left in " + out)
    for checker, motion in COMBINATIONS:
        check("| RRTConnect | %s | %s | %d |" % (checker, motion, RUNS) in p.stdout,
              "full run: no summary row for RRTConnect %s %s with %d runs" % (checker, motion, RUNS))
    check("FCL ÷ adsd in this benchmark" in p.stdout, "full run: no FCL / adsd ratio table")

    db = sqlite3.connect(os.path.join(out, "thin_wall.db"))
    experiments = db.execute("SELECT name, runcount, timelimit FROM experiments").fetchall()
    check(experiments == [("thin_wall", RUNS, TIME_LIMIT)], "full run: experiments table is %s" % experiments)
    names = sorted(r[0] for r in db.execute("SELECT name FROM plannerConfigs"))
    expected = sorted("geometric_RRTConnect [%s, %s]" % c for c in COMBINATIONS)
    check(names == expected, "full run: planner configurations %s, expected %s" % (names, expected))

    types = columns(db)
    for column, sql_type in list(OUR_COLUMNS.items()) + list(OMPL_COLUMNS.items()):
        check(types.get(column) == sql_type,
              "full run: runs column %s has type %s, expected %s" % (column, types.get(column), sql_type))

    db.row_factory = sqlite3.Row
    rows = db.execute("SELECT plannerConfigs.name AS planner, runs.* FROM runs "
                      "JOIN plannerConfigs ON runs.plannerid = plannerConfigs.id").fetchall()
    check(len(rows) == RUNS * len(COMBINATIONS), "full run: %d runs in the database, expected %d"
          % (len(rows), RUNS * len(COMBINATIONS)))
    seen = {}
    for r in rows:
        where = "full run, %s run %s" % (r["planner"], r["run_index"])
        checker, motion = r["checker"], r["motion_validator"]
        check(r["planner"] == "geometric_RRTConnect [%s, %s]" % (checker, motion),
              "%s: checker %s and motion %s do not match the planner's name" % (where, checker, motion))
        seen.setdefault(r["planner"], []).append(r["run_index"])
        check(r["validity_checks"] + r["clearance_queries"] > 0, where + ": no query counted")
        check(r["motion_checks"] > 0, where + ": no motion check counted")
        check(0 <= r["motions_rejected"] <= r["motion_checks"], where + ": rejected motions out of range")
        for count, total, mean in (("validity_checks", "validity_check_time", "mean_validity_check_time"),
                                   ("clearance_queries", "clearance_query_time", "mean_clearance_query_time")):
            if r[count] > 0:
                check(r[total] > 0 and close(r[mean] * r[count], r[total]),
                      "%s: %s x %s = %r, but %s = %r" % (where, mean, count, r[mean] * r[count], total, r[total]))
            else:
                check(r[mean] is None, "%s: %s given for no queries" % (where, mean))
        if motion == "certified":
            # Each certified step is a clearance query: the two counters are kept apart.
            check(r["certified_clearance_steps"] is not None and r["certified_clearance_steps"] > 0,
                  where + ": no certified clearance steps")
            check(r["certified_clearance_steps"] is not None and
                  r["clearance_queries"] >= r["certified_clearance_steps"],
                  where + ": fewer clearance queries than certified steps")
            check(0.0 <= r["valid_segment_fraction"] <= 1.0, where + ": valid segment fraction out of [0, 1]")
        else:
            check(r["certified_clearance_steps"] is None, where + ": certified steps with the discrete validator")
            check(r["validity_checks"] > 0, where + ": the discrete validator made no validity check")
        if r["solved"]:
            # Every state of a valid path is farther than the safety margin (0) from the obstacles.
            check(r["solution_clearance"] is not None and r["solution_clearance"] > 0,
                  where + ": solved, but solution clearance %r" % r["solution_clearance"])
            # Between its states too, as adsd plan measures it: a discrete path may step over the
            # wall (in contact), a certified one never.
            check(r["path_least_clearance"] is not None and
                  r["path_in_contact"] == (1 if r["path_least_clearance"] <= 0 else 0),
                  "%s: path least clearance %r, in contact %r"
                  % (where, r["path_least_clearance"], r["path_in_contact"]))
            if motion == "certified":
                check(r["path_in_contact"] == 0, where + ": a certified path in contact")
        check(r["query_time_fraction"] is not None and r["query_time_fraction"] > 0,
              where + ": no query time fraction")
        # The planner's own solve lies inside OMPL's timing of it, and RRTConnect's queries (one
        # thread) inside the planner's solve.
        check(r["planner_time"] is not None and 0 < r["planner_time"] <= r["time"],
              "%s: planner_time %r, OMPL's time %r" % (where, r["planner_time"], r["time"]))
        check(r["planner_time"] is not None and
              r["validity_check_time"] + r["clearance_query_time"] <= r["planner_time"],
              "%s: query times %r + %r exceed planner_time %r" % (
                  where, r["validity_check_time"], r["clearance_query_time"], r["planner_time"]))
    for planner, indices in seen.items():
        check(sorted(indices) == list(range(RUNS)), "full run: %s has run indices %s" % (planner, indices))


def seed_of(log):
    with open(log) as f:
        for line in f:
            if line.endswith(" is the random seed\n"):
                return int(line.split()[0])
    return None


def shards(adsd, cfg, work, statistics):
    out = os.path.join(work, "shards")
    common = ["--checker", "adsd", "--motion", "certified", "--time", str(TIME_LIMIT), "--out", out, "--log-only"]
    logs = {}
    for extra, name, seed in ((["--run-range", "0:1"], "thin_wall.runs-0-1.log", 1),
                              (["--run-range", "1:2"], "thin_wall.runs-1-2.log", 2),
                              (["--run-range", "2:3", "--seed", "77"], "thin_wall.runs-2-3.seed-77.log", 77)):
        p = run(adsd, [cfg] + extra + common)
        if not check(p.returncode == 0, "shard %s: exit status %d\nstderr: %s" % (extra, p.returncode, p.stderr)):
            continue
        log = os.path.join(out, name)
        if check(os.path.isfile(log), "shard %s: %s not written" % (extra, name)):
            check(seed_of(log) == seed, "shard %s: seed %s in the log, expected %d" % (extra, seed_of(log), seed))
            logs[name] = log
    check(not [f for f in os.listdir(out) if f.endswith(".db")], "--log-only wrote a database")
    if len(logs) != 3:
        return
    merged = os.path.join(out, "merged.db")
    p = subprocess.run([statistics] + sorted(logs.values()) + ["-d", merged], capture_output=True, text=True)
    if not check(p.returncode == 0, "merging the shards' logs failed:\n" + p.stderr):
        return
    db = sqlite3.connect(merged)
    experiments = db.execute("SELECT name, runcount, seed FROM experiments ORDER BY seed + 0").fetchall()
    check(experiments == [("thin_wall", 1, "1"), ("thin_wall", 1, "2"), ("thin_wall", 1, "77")],
          "merged: experiments %s" % experiments)
    names = [r[0] for r in db.execute("SELECT name FROM plannerConfigs")]
    check(names == ["geometric_RRTConnect [adsd, certified]"],
          "merged: one planner configuration expected (same name and settings in every shard), got %s" % names)
    indices = sorted(r[0] for r in db.execute("SELECT run_index FROM runs"))
    check(indices == [0, 1, 2], "merged: run indices %s" % indices)


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--adsd", required=True)
    parser.add_argument("--problems", required=True)
    parser.add_argument("--work", required=True)
    args = parser.parse_args()
    statistics = statistics_program()
    if statistics is None:
        sys.exit("ompl_benchmark_statistics is not on PATH (Debian package ompl-demos)")
    cfg = os.path.join(args.problems, "thin_wall.cfg")
    if not os.path.isfile(cfg):
        sys.exit("%s is missing: build the target adsd_problems" % cfg)
    shutil.rmtree(args.work, ignore_errors=True)
    os.makedirs(args.work)

    bad_input(args.adsd, cfg, args.problems, args.work)
    full_run(args.adsd, cfg, args.work)
    repeated_instances(args.adsd, args.problems, args.work)
    shards(args.adsd, cfg, args.work, statistics)
    upstream_name(args.adsd, cfg, args.work, statistics)
    clearance_not_simplified(args.adsd, args.problems, args.work)

    if failures:
        print("%d check(s) failed" % len(failures))
        sys.exit(1)
    print("all checks passed")


if __name__ == "__main__":
    main()
