#!/usr/bin/python3
"""Where an exact and a 1 % tolerance query spend their time on the prebuilt trees: a perf
profile of bench_scene_counters per mode, our code's samples grouped by the stage of the traversal
they belong to (issue 6: "if a ratio cannot be met, say which, with the profile and counters that
show what bounds it").

usage: profile_modes.py --counters PROGRAM [--scenes a,b,...] [--modes exact,tol] [--repeat N] [--verbose]

PROGRAM is a Release build of bench/bench_scene_counters. For each mode, runs
  perf record -o TMP PROGRAM --scenes SCENES --modes MODE --repeat N
then `perf report --no-children --sort dso,symbol` and keeps the samples in PROGRAM itself (our core
is linked into it; FCL's comparison queries run in libfcl and are left out). Mode `known` is not
useful here: its untimed exact query, which finds the answer it is told, is profiled with it.
Each of our symbols falls in one stage by its name:
  node pairs         the box lower bounds of node pairs and the traversal that tests and splits them
                     (boxLowerBound, traverseTrees and its lambdas, placedBox)
  queue              the best-first heap of pending node pairs (std::*_heap on PendingNodePair)
  triangle filters   the tests that drop a leaf's triangles against a box or a triangle pair by a
                     separating axis before any distance is computed (triangleFartherFromBox,
                     trianglesFartherThan, trianglesNearBox)
  triangle distance  the exact triangle-triangle distances (triangleDistanceUpTo and its helpers,
                     testLeafPair)
  hulls              GJK on node pairs and convex parts, its support searches and the triangle
                     pair it measures (hullBound, gjkOnNodes, nodeSupport, convexNodesBound,
                     settleConvexPair and their helpers)
  other              anything else, listed with --verbose
Inlining moves work between symbols, so the stages are approximate. Every mode makes the same
queries (scenes x poses x repeat) and perf samples at a fixed rate, so a mode's sample count is
its time: each stage is shown in per cent of the first mode's samples of our code, and the row's
total is that mode's time relative to the first mode's. A tolerance can only save the work it
lets the query skip: the table shows which stages that is.
Exit status: 0; 1 when perf or the program fails; 2 on bad usage.
"""
import argparse
import collections
import os
import re
import shutil
import subprocess
import sys
import tempfile

STAGES = [
    ("hulls", re.compile(r"nodeSupport|hullBound|gjkOnNodes|convexNodesBound|measureAtHullPoints|settleConvexPair|"
                         r"runGjk|closestPointOfSimplex|nearestTriangle|pointTriangleDistance2|supportVertex")),
    ("queue", re.compile(r"_heap<.*PendingNodePair|PendingNodePair.*_heap")),
    ("triangle filters", re.compile(r"triangleFartherFromBox|trianglesFartherThan|trianglesNearBox")),
    ("triangle distance", re.compile(r"triangleDistance|closestOn|segmentPiercesFace|Face::Face|testLeafPair|"
                                     r"segmentSegment|signedVolume")),
    ("node pairs", re.compile(r"boxLowerBound|traverseTrees|placedBox|OrientedBox|refineLeaves")),
]
SAMPLE = re.compile(r"^\s*[\d.]+%\s+(\d+)\s+(\S+)\s+\[\.\]\s+(.*?)\s*$")


def stage_of(symbol):
    for name, pattern in STAGES:
        if pattern.search(symbol):
            return name
    return "other"


def profile(program, scenes, mode, repeat, workdir):
    """{stage: samples} of our code, and {symbol: samples} of the stage 'other'."""
    data = os.path.join(workdir, "perf-%s.data" % mode)
    record = ["perf", "record", "-q", "-o", data, program, "--scenes", scenes, "--modes", mode,
              "--repeat", str(repeat)]
    result = subprocess.run(record, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
    if result.returncode != 0:
        sys.stderr.write(result.stderr)
        sys.exit("profile_modes.py: %s failed (exit %d)" % (" ".join(record), result.returncode))
    report = subprocess.run(["perf", "report", "-i", data, "-n", "--no-children", "--sort", "dso,symbol",
                             "--stdio"],
                            stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, text=True)
    if report.returncode != 0:
        sys.exit("profile_modes.py: perf report failed on %s" % data)
    ours = os.path.basename(program)
    stages, others = collections.Counter(), collections.Counter()
    for line in report.stdout.splitlines():
        m = SAMPLE.match(line)
        if not m or m.group(2) != ours:
            continue
        # perf pads the symbol column; drop the trailing annotation columns it may add.
        samples, symbol = int(m.group(1)), re.split(r"\s{3,}", m.group(3))[0]
        stage = stage_of(symbol)
        stages[stage] += samples
        if stage == "other":
            others[symbol] += samples
    return stages, others


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--counters", required=True, help="the bench_scene_counters program")
    parser.add_argument("--scenes", default="problem_office,problem_bug_trap,problem_twisted_passage",
                        help="scenes, as bench_scene_counters names them")
    parser.add_argument("--modes", default="exact,tol", help="modes (default exact,tol)")
    parser.add_argument("--repeat", type=int, default=200, help="bench_scene_counters --repeat (default 200)")
    parser.add_argument("--verbose", action="store_true", help="list the symbols counted as other")
    args = parser.parse_args()
    if args.repeat < 1:
        parser.error("--repeat must be positive")
    if not os.access(args.counters, os.X_OK):
        parser.error("no program at '%s'" % args.counters)
    if shutil.which("perf") is None:
        sys.exit("profile_modes.py: no perf on PATH (Debian: apt-get install linux-perf)")

    names = [name for name, _ in STAGES[::-1]] + ["other"]
    modes = args.modes.split(",")
    print("Command: `bench/profile_modes.py --scenes %s --modes %s --repeat %d`. Samples of our code (FCL's left "
          "out) per stage of the traversal, over the scenes together, in %% of mode %s's samples: a row's total is "
          "its time relative to %s's." % (args.scenes, args.modes, args.repeat, modes[0], modes[0]))
    print()
    print("| mode | total | " + " | ".join(names) + " |")
    print("|---|" + "---:|" * (len(names) + 1))
    first_total = None
    with tempfile.TemporaryDirectory(prefix="adsd-profile-") as workdir:
        for mode in modes:
            stages, others = profile(args.counters, args.scenes, mode, args.repeat, workdir)
            total = sum(stages.values())
            if total <= 0:
                sys.exit("profile_modes.py: no samples in %s for mode %s" % (os.path.basename(args.counters), mode))
            first_total = first_total or total
            print("| %s | %.0f %% | " % (mode, 100 * total / first_total) +
                  " | ".join("%.0f %%" % (100 * stages[n] / first_total) for n in names) + " |")
            if args.verbose:
                for symbol, samples in others.most_common(10):
                    share = 100 * samples / first_total
                    print("  %s, other: %.1f %% %s" % (mode, share, symbol[:120]), file=sys.stderr)


if __name__ == "__main__":
    main()
