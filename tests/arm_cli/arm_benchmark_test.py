#!/usr/bin/python3
"""`adsd benchmark` on arm problems (issue 17), run as a user runs it, with tiny runs.

usage: arm_benchmark_test.py --adsd PROGRAM --problems problems/arm --work DIR

Checks: one arm problem with --runs 2 --time 1 writes a log and a database whose runs hold every
checker x motion validator combination with our run properties (checker, motion validator, validity
checks, ...); a directory of arm problems writes one log per problem, and is refused before any run
when two problems share a name or a later one is bad; KPIECE and SBL run (the arm space's projection)
and CForest is refused. Exits 77 (skipped) naming
problems/data/fetch_robots.sh when the robots are not cached.
"""
import argparse
import os
import shutil
import sqlite3
import subprocess
import sys

failures = []
COMBINATIONS = {("adsd", "discrete"), ("adsd", "certified"), ("fcl", "discrete"), ("fcl", "certified")}
RUNS = 2


def check(condition, what):
    if not condition:
        failures.append(what)
        print("FAIL: " + what, flush=True)
    return condition


def run(adsd, args):
    print("$ " + " ".join(["adsd", "benchmark"] + args), flush=True)
    p = subprocess.run([adsd, "benchmark"] + args, capture_output=True, text=True, timeout=600)
    print("  -> exit %d" % p.returncode, flush=True)
    return p


def robots_directory():
    return os.environ.get("ADSD_ROBOTS") or os.path.join(os.path.expanduser("~"), ".cache", "adsd", "robots")


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--adsd", required=True)
    parser.add_argument("--problems", required=True)
    parser.add_argument("--work", required=True)
    args = parser.parse_args()
    robot = os.path.join(robots_directory(), "wam", "wam.urdf")
    if not os.path.exists(robot):
        print("skipped: the robots are not cached (%s): run problems/data/fetch_robots.sh" % robot)
        return 77
    shutil.rmtree(args.work, ignore_errors=True)
    os.makedirs(args.work)

    # One problem, every combination.
    out = os.path.join(args.work, "one")
    # The WAM: along the KR5's paths the clearance stays at 4 to 6 mm (some pair of its links, it
    # seems), so certified motions split deeply and OMPL's simplification of a run takes a minute.
    cfg = os.path.join(args.problems, "wam_box", "problem.cfg")
    p = run(args.adsd, [cfg, "--runs", str(RUNS), "--time", "1", "--out", out, "--no-plots"])
    if check(p.returncode == 0, "one problem: exit %d\n%s%s" % (p.returncode, p.stdout, p.stderr)):
        check("(arm " in p.stdout, "the header names the arm: " + p.stdout)
        log = os.path.join(out, "wam_box.log")
        db = os.path.join(out, "wam_box.db")
        check(os.path.isfile(log), "no log " + log)
        if check(os.path.isfile(db), "no database " + db):
            con = sqlite3.connect(db)
            columns = {row[1] for row in con.execute("PRAGMA table_info(runs)")}
            for c in ("checker", "motion_validator", "validity_checks", "clearance_queries", "motion_checks",
                      "mean_validity_check_time", "planner_time"):
                check(c in columns, "runs has no column " + c)
            rows = con.execute("SELECT checker, motion_validator, validity_checks, motion_checks, "
                               "certified_clearance_steps FROM runs").fetchall()
            check(len(rows) == RUNS * len(COMBINATIONS), "%d runs, expected %d" % (len(rows), RUNS * len(COMBINATIONS)))
            check({(r[0], r[1]) for r in rows} == COMBINATIONS, "combinations: %s" % sorted({(r[0], r[1]) for r in rows}))
            for r in rows:
                check(r[2] is not None and r[2] > 0, "a run without validity checks: %r" % (r,))
                check(r[3] is not None and r[3] > 0, "a run without motion checks: %r" % (r,))
                check((r[4] is not None) == (r[1] == "certified"), "certified steps only for certified: %r" % (r,))
            experiments = con.execute("SELECT name FROM experiments").fetchall()
            check(experiments == [("wam_box",)], "experiments: %r" % experiments)

    # A directory of MotionBenchMaker-style folders: one log per problem.
    folders = os.path.join(args.work, "folders")
    shipped = os.path.join(os.path.abspath(args.problems), "wam_box")
    for name in ("a_first", "b_second"):
        os.makedirs(os.path.join(folders, name))
        with open(os.path.join(folders, name, "problem.cfg"), "w") as f:
            f.write("[problem]\nname = %s\nrobot = ${ADSD_ROBOTS}/wam/wam.urdf\nsrdf = %s/../wam.srdf\n"
                    "scene = %s/scene.yaml\nrequest = %s/request.yaml\npackage_path = ${ADSD_ROBOTS}\n"
                    % (name, shipped, shipped, shipped))
    # A folder linked in from elsewhere is a problem too; a link back up (a loop) and a second link
    # to a listed folder are not entered again (the loop hung the listing, or ran one problem twice).
    linked = os.path.join(args.work, "elsewhere", "c_linked")
    os.makedirs(linked)
    with open(os.path.join(linked, "problem.cfg"), "w") as f:
        f.write("[problem]\nname = c_linked\nrobot = ${ADSD_ROBOTS}/wam/wam.urdf\nsrdf = %s/../wam.srdf\n"
                "scene = %s/scene.yaml\nrequest = %s/request.yaml\npackage_path = ${ADSD_ROBOTS}\n"
                % (shipped, shipped, shipped))
    os.symlink(linked, os.path.join(folders, "c_linked"))
    os.symlink(folders, os.path.join(folders, "a_first", "loop"))
    os.symlink(os.path.join(folders, "b_second"), os.path.join(folders, "d_again"))
    out = os.path.join(args.work, "many")
    p = run(args.adsd, [folders, "--runs", "1", "--time", "0.5", "--checker", "adsd", "--motion", "discrete",
                        "--out", out, "--log-only"])
    if check(p.returncode == 0, "a directory: exit %d\n%s%s" % (p.returncode, p.stdout, p.stderr)):
        for name in ("a_first", "b_second", "c_linked"):
            check(os.path.isfile(os.path.join(out, name + ".log")), "no log for " + name)
        check(sorted(os.listdir(out)) == ["a_first.log", "b_second.log", "c_linked.log"],
              "a directory with links: wrote %s" % sorted(os.listdir(out)))

    # Two problems of one name would write the same files: refused before any run, naming both.
    same = os.path.join(args.work, "same")
    for name in ("a", "b"):
        os.makedirs(os.path.join(same, name))
        with open(os.path.join(same, name, "problem.cfg"), "w") as f:
            f.write("[problem]\nrobot = ${ADSD_ROBOTS}/wam/wam.urdf\nsrdf = %s/../wam.srdf\n"
                    "scene = %s/scene.yaml\nrequest = %s/request.yaml\npackage_path = ${ADSD_ROBOTS}\n"
                    % (shipped, shipped, shipped))
    out = os.path.join(args.work, "same_out")
    p = run(args.adsd, [same, "--runs", "1", "--time", "0.5", "--out", out, "--log-only"])
    check(p.returncode == 2 and "would overwrite" in p.stderr and os.path.join("a", "problem.cfg") in p.stderr,
          "two problems of one name: exit %d, %r" % (p.returncode, p.stderr))
    check(not os.path.exists(os.path.join(out, "problem.log")), "two problems of one name: a run was made")

    # A bad problem after a good one stops the command before the good one's runs.
    with open(os.path.join(folders, "b_second", "problem.cfg"), "a") as f:
        f.write("robot = ${ADSD_ROBOTS}/wam/no_such.urdf\n")
    out = os.path.join(args.work, "later_bad")
    p = run(args.adsd, [folders, "--runs", "1", "--time", "0.5", "--out", out, "--log-only"])
    check(p.returncode == 2 and "b_second" in p.stderr, "a bad second problem: exit %d, %r" % (p.returncode, p.stderr))
    check(not os.path.exists(os.path.join(out, "a_first.log")), "a bad second problem: the first one was run")

    # The grid planners have a projection of the arm's joints (KPIECE solves); planners OMPL's
    # informed sampling stops in an arm's joint space are refused before any run (CForest aborted
    # the program).
    out = os.path.join(args.work, "planners")
    p = run(args.adsd, [cfg, "--planner", "kpiece,sbl", "--runs", "1", "--time", "1", "--checker", "adsd",
                        "--motion", "discrete", "--out", out, "--log-only"])
    check(p.returncode == 0, "kpiece and sbl: exit %d\n%s%s" % (p.returncode, p.stdout, p.stderr))
    out = os.path.join(args.work, "refused")
    p = run(args.adsd, [cfg, "--planner", "rrtconnect,cforest", "--runs", "1", "--time", "1", "--out", out])
    check(p.returncode == 2 and "cforest cannot plan for path length in this state space" in p.stderr,
          "cforest: exit %d, %r" % (p.returncode, p.stderr))
    check(not os.path.exists(out), "cforest: wrote " + out)

    # Bad input: an unknown planner is a usage error before anything is written.
    out = os.path.join(args.work, "bad")
    p = run(args.adsd, [cfg, "--planner", "rrtconnect,nosuch", "--out", out])
    check(p.returncode == 2 and len(p.stderr.splitlines()) == 1 and "nosuch" in p.stderr,
          "unknown planner: exit %d, %r" % (p.returncode, p.stderr))
    check(not os.path.exists(out), "unknown planner: wrote " + out)

    if failures:
        print("%d failure(s)" % len(failures))
        return 1
    print("ok")
    return 0


if __name__ == "__main__":
    sys.exit(main())
