#!/usr/bin/env python3
"""Every program's answer to bad numbers on its command line, under a German locale (decimal comma).

  bad_numbers.py NAME=PATH...      (NAME: adsd, adsd_stress, adsd_soak, bench_scenes, bench_distance_vs_fcl,
                                    bench_bands, bench_scene_counters, bench_checker_calls,
                                    bench_mesh_info, bench_arms)

Checks, for each program given: a malformed or out-of-range number ("abc", "-1", "1e3x", "0,5", 0
where a count must be positive) stops it with exit status 2, exactly one line on stderr naming the
option, and nothing on stdout; an unknown option likewise. For adsd and adsd_stress, numbers with a
decimal point are also taken and answered (the German locale reads "0,5"; ours must not care).
The locale comes from LOCPATH (tests/cli's fixture compiles de_DE.UTF-8 there).
"""
import os
import subprocess
import sys
import tempfile

from script_checks import check, report

# (arguments, the text the one line must hold)
BAD = {
    "adsd": [
        (["plan", "--time", "abc"], "--time"),
        (["plan", "--time", "-1"], "--time"),
        (["plan", "--time", "0,5"], "--time"),
        (["plan", "--seed", "1e3x"], "--seed"),
        (["plan", "--seed", "0"], "--seed"),
        (["plan", "--bogus"], "--bogus"),
        (["benchmark", "--runs", "-1"], "--runs"),
        (["benchmark", "--runs", "1e3"], "--runs"),
        (["benchmark", "--time", "1e3x"], "--time"),
        (["benchmark", "--run-range", "1:x"], "--run-range"),
        (["benchmark", "--seed", "abc"], "--seed"),
        (["benchmark", "--bogus"], "--bogus"),
        (["distance", "a.obj", "b.obj", "--threshold", "1e3x"], "--threshold"),
        (["distance", "a.obj", "b.obj", "--cap", "0"], "--cap"),
        (["distance", "a.obj", "b.obj", "--abs-tol", "nan"], "--abs-tol"),
        (["distance", "a.obj", "b.obj", "--rel-tol", "-1"], "--rel-tol"),
        (["distance", "a.obj", "b.obj", "--bogus"], "--bogus"),
    ],
    "adsd_stress": [
        (["--cases", "-1"], "--cases"),
        (["--cases", "1e3x"], "--cases"),
        (["--seed", "abc"], "--seed"),
        (["--scale", "abc"], "--scale"),
        (["--progress", "0"], "--progress"),
        (["--threads", "0,5"], "--threads"),
        (["--bogus"], "--bogus"),
    ],
    "adsd_soak": [
        ([], "PROBLEM.cfg MINUTES"),
        (["x.cfg", "abc"], "MINUTES"),
        (["x.cfg", "1", "0,5"], "SECONDS_PER_RUN"),
        (["x.cfg", "-1"], "'-1'"),  # a negative positional reads as an option: refused all the same
    ],
    "bench_scenes": [
        (["--oracle", "-1"], "--oracle"),
        (["--oracle", "1e3x"], "--oracle"),
        (["--bogus"], "--bogus"),
    ],
    "bench_distance_vs_fcl": [
        (["--poses", "1e3x"], "--poses"),
        (["--rounds", "0"], "--rounds"),
        (["--seed", "-1"], "--seed"),
        (["--bogus"], "--bogus"),
    ],
    "bench_bands": [
        (["--poses", "0"], "--poses"),
        (["--poses", "1e3x"], "--poses"),
        (["--rounds", "-1"], "--rounds"),
        (["--seed", "abc"], "--seed"),
        (["--bands", "nearby"], "--bands"),
        (["--pairs", "a.off"], "--pairs"),
        (["--bogus"], "--bogus"),
    ],
    "bench_scene_counters": [
        (["--repeat", "0"], "--repeat"),
        (["--repeat", "abc"], "--repeat"),
        (["--bogus"], "--bogus"),
    ],
    "bench_mesh_info": [
        ([], "mesh files"),
        (["--bogus", "x.obj"], "--bogus"),
    ],
    "bench_arms": [
        (["--states", "0"], "--states"),
        (["--motions", "1e3x"], "--motions"),
        (["--step", "0,3"], "--step"),
        (["--step", "-1"], "--step"),
        (["--rounds", "abc"], "--rounds"),
        (["--bogus"], "--bogus"),
    ],
    "bench_checker_calls": [
        (["--states", "-1", "x.cfg"], "--states"),
        (["--states", "1e3x", "x.cfg"], "--states"),
        (["--seed", "abc", "x.cfg"], "--seed"),
        (["--bogus", "x.cfg"], "--bogus"),
    ],
}

CUBE = """v 0 0 0
v 1 0 0
v 1 1 0
v 0 1 0
v 0 0 1
v 1 0 1
v 1 1 1
v 0 1 1
f 1 3 2
f 1 4 3
f 5 6 7
f 5 7 8
f 1 2 6
f 1 6 5
f 2 3 7
f 2 7 6
f 3 4 8
f 3 8 7
f 4 1 5
f 4 5 8
"""


def run(program, args, cwd):
    env = dict(os.environ, LC_ALL="de_DE.UTF-8", LANG="de_DE.UTF-8")
    return subprocess.run([program] + args, cwd=cwd, env=env, capture_output=True, text=True, timeout=120)


def main():
    programs = dict(arg.split("=", 1) for arg in sys.argv[1:])
    unknown = set(programs) - set(BAD)
    if not programs or unknown:
        sys.exit("usage: bad_numbers.py NAME=PATH... (NAME one of %s)" % ", ".join(sorted(BAD)))
    with tempfile.TemporaryDirectory() as work:
        for name, path in sorted(programs.items()):
            for args, needle in BAD[name]:
                shown = "%s %s" % (name, " ".join(args))
                p = run(path, args, work)
                lines = p.stderr.splitlines()
                print("%-60s -> %d: %s" % (shown, p.returncode, p.stderr.strip()), flush=True)
                check(p.returncode == 2, "%s: exit status %d, expected 2" % (shown, p.returncode))
                check(len(lines) == 1, "%s: %d lines on stderr, expected one:\n%s" % (shown, len(lines), p.stderr))
                check(needle in p.stderr, "%s: stderr does not name %s: %s" % (shown, needle, p.stderr))
                check(p.stdout == "", "%s: wrote to stdout:\n%s" % (shown, p.stdout))
        # Decimal points taken under the German locale.
        if "adsd" in programs:
            with open(os.path.join(work, "cube.obj"), "w") as f:
                f.write(CUBE)
            p = run(programs["adsd"], ["distance", "cube.obj", "cube.obj", "--threshold", "0.5"], work)
            check(p.returncode == 0 and "threshold 0.5 " in p.stdout,
                  "adsd distance --threshold 0.5: exit %d\n%s%s" % (p.returncode, p.stdout, p.stderr))
            p = run(programs["adsd"], ["distance", "cube.obj", "cube.obj", "--cap", "2.5e-1"], work)
            check(p.returncode == 0 and "cap 0.25 " in p.stdout,
                  "adsd distance --cap 2.5e-1: exit %d\n%s%s" % (p.returncode, p.stdout, p.stderr))
        if "adsd_stress" in programs:
            p = run(programs["adsd_stress"], ["--family", "tri/", "--cases", "2", "--threads", "1", "--scale", "0.5"],
                    work)
            check(p.returncode == 0, "adsd_stress --scale 0.5: exit %d\n%s%s" % (p.returncode, p.stdout, p.stderr))
    return report()


if __name__ == "__main__":
    sys.exit(main())
