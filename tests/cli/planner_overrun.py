#!/usr/bin/env python3
"""A planner that never tests its time limit does not hang `adsd plan` or `adsd benchmark`.

  planner_overrun.py ADSD

OMPL 1.5.2's BIT* asks its informed sampler for samples until it has them. In an SE(2) problem
4 cm wide whose goal turns a 2 mm robot half round, the yaw's share of the distance puts almost
every informed sample outside the bounds, and `adsd plan --planner bitstar --time 1` never
returned (an outside review found it with a CGAL mushroom; two boxes do the same). Both commands
must come back within the limit and PlannerWatchdog's grace (10 s) with exit status 0 or 1; when
the watchdog ended them, with one line naming the planner and nothing written (not even the
benchmark's output directory, which it makes before the runs). An OMPL whose BIT*
does return passes this too, by planning.
"""
import os
import subprocess
import sys
import tempfile
import time

from script_checks import check, report


def box(cx, cy, hx, hy, h):
    """An axis-aligned box's OBJ lines: centre (cx, cy, 0), half extents hx, hy, h."""
    corners = [(cx + sx * hx, cy + sy * hy, sz * h) for sx in (-1, 1) for sy in (-1, 1) for sz in (-1, 1)]
    faces = [(0, 1, 3, 2), (4, 6, 7, 5), (0, 4, 5, 1), (2, 3, 7, 6), (0, 2, 6, 4), (1, 5, 7, 3)]
    return [f"v {x!r} {y!r} {z!r}" for x, y, z in corners] + ["f " + " ".join(str(i + 1) for i in f) for f in faces]


PROBLEM = """[problem]
name = tiny_turn
robot = robot.obj
world = world.obj
start.x = -0.015
start.y = 0
start.theta = 0
goal.x = 0.015
goal.y = 0
goal.theta = 3.14159
volume.min.x = -0.02
volume.min.y = -0.02
volume.max.x = 0.02
volume.max.y = 0.02
"""


def expect_back(adsd, args, cwd, written):
    """Runs adsd with args in cwd: back within 60 s, and either planned (exit 0) or stopped by the
    watchdog (exit 1, one line naming the planner, nothing in `written`, a list of paths)."""
    label = " ".join(args)
    started = time.monotonic()
    try:
        r = subprocess.run([adsd] + args, capture_output=True, text=True, timeout=60, cwd=cwd)
    except subprocess.TimeoutExpired:
        check(False, f"{label}: still running after 60 s")
        return
    took = time.monotonic() - started
    stopped = "did not stop at its time limit" in r.stderr
    check(r.returncode == 0 or (stopped and r.returncode == 1),
          f"{label}: exit {r.returncode}, neither planned nor stopped ({r.stderr.strip()[-300:]})")
    if stopped:
        line = [s for s in r.stderr.splitlines() if "did not stop" in s]
        check(len(line) == 1 and "bitstar" in line[0].lower(),
              f"{label}: the line does not name the planner: {r.stderr!r}")
        for path in written:
            check(not os.path.exists(path), f"{label}: left {path} though stopped")
    outcome = "stopped by the watchdog" if stopped else "returned by itself"
    print(f"{label}: exit {r.returncode} in {took:.1f} s, {outcome}")


def main():
    adsd = os.path.abspath(sys.argv[1])
    with tempfile.TemporaryDirectory() as work:
        with open(os.path.join(work, "robot.obj"), "w") as f:
            f.write("\n".join(box(0, 0, 0.001, 0.0005, 0.0005)) + "\n")
        with open(os.path.join(work, "world.obj"), "w") as f:
            f.write("\n".join(box(0, 0, 0.002, 0.006, 0.002)) + "\n")
        with open(os.path.join(work, "tiny_turn.cfg"), "w") as f:
            f.write(PROBLEM)
        expect_back(adsd, ["plan", "tiny_turn.cfg", "--planner", "bitstar", "--time", "1", "--seed", "1", "--path",
                           "out.path", "--html", "out.html"], work,
                    [os.path.join(work, "out.path"), os.path.join(work, "out.html")])
        # --log-only: the log alone, so that nothing but the planner can fail the run (the plots
        # need the plotting script beside the program); the directory it made is removed when stopped.
        expect_back(adsd, ["benchmark", "tiny_turn.cfg", "--planner", "bitstar", "--checker", "adsd", "--motion",
                           "discrete", "--runs", "1", "--time", "1", "--seed", "1", "--log-only", "--out", "results"],
                    work, [os.path.join(work, "results")])
    return report()


if __name__ == "__main__":
    sys.exit(main())
