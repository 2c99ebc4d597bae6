#!/usr/bin/env python3
"""Output files checked before the work, and path files read as other tools write them.

  output_and_path_files.py ADSD OFFICE_CFG

OFFICE_CFG: the shipped office problem as the build writes it (its meshes beside it).

`adsd plan --planner fmt|bfmt --objective clearance` (OMPL's FMT* crashed with it) is refused.
`adsd plan --path/--html` and `adsd view --html` naming an empty name, a directory or a file in a
directory that does not exist: exit status 2 with one line on stderr naming the option, nothing on
stdout (no plan was made first). `adsd view` of a rigid problem's path file: a yaw outside
[-pi, pi] (as tools that write [0, 2 pi) or unwrapped angles give it) and a comment after a
state's numbers are taken; a state outside the problem's bounds is refused naming its line, and
no page is written; a byte-order mark before the first state is skipped. A start in collision is
refused by `adsd plan` and shown, with a warning naming its line, by `adsd view`. `adsd benchmark
--out` does not make a missing parent directory, and says so of a file. Outputs over the meshes a
problem file names, and inputs without end (/dev/zero), are refused, and so are outputs in /dev,
/proc or /sys that lead to a plain file (/dev/stdout redirected into one).
`adsd plan`'s least clearance along the path, between its states too, finds where a discrete path
steps over the thin wall. Past a file-size limit (ulimit -f), a page, a report and the standard
output are failures said in one line (exit status 2 or 1), not a silent kill leaving a .partial.
The seed `adsd plan` prints when OMPL chose it, given back with --seed, plans the same path.
A shipped problem's bare name where no such file is says where the shipped one is.
"""
import math
import os
import pathlib
import resource
import subprocess
import sys
import tempfile

from script_checks import check, report


def run(adsd, args, cwd):
    return subprocess.run([adsd] + args, capture_output=True, text=True, timeout=300, cwd=cwd)


def expect_refused(adsd, args, cwd, start):
    r = run(adsd, args, cwd)
    label = " ".join(args)
    check(r.returncode == 2, f"{label}: exit {r.returncode}, expected 2 ({r.stderr.strip()})")
    check(r.stdout == "", f"{label}: printed on stdout before refusing: {r.stdout[:200]!r}")
    check(r.stderr.count("\n") == 1 and r.stderr.startswith(start),
          f"{label}: stderr {r.stderr!r}, expected one line starting {start!r}")


def main():
    adsd, office = sys.argv[1], sys.argv[2]
    with tempfile.TemporaryDirectory() as work:
        missing = os.path.join(work, "no_such_dir", "x.path")
        for command, option in (("plan", "--path"), ("plan", "--html"), ("view", "--html")):
            extra = ["--html", os.path.join(work, "ok.html")] if command == "view" and option != "--html" else []
            expect_refused(adsd, [command, office, option, missing] + extra, work,
                           f"adsd {command}: error: {option}: '{missing}': directory '{os.path.dirname(missing)}'"
                           " does not exist")
            expect_refused(adsd, [command, office, option, ""] + extra, work,
                           f"adsd {command}: error: {option}: expected a file name, got ''")
            expect_refused(adsd, [command, office, option, work] + extra, work,
                           f"adsd {command}: error: {option}: '{work}' is a directory, not a file")
            # A device would be replaced by a plain file (the write goes through a rename).
            expect_refused(adsd, [command, office, option, "/dev/null"] + extra, work,
                           f"adsd {command}: error: {option}: '/dev/null' is a device, a pipe or a socket")

        # A name in /dev or /proc that leads to a plain file (/dev/stdout, the standard output
        # redirected into one) stands for a stream: the rename replaced the link itself with a
        # file, as root the machine's /dev/stdout. Tried through a link of our own to
        # /proc/self/fd/1, so that a failure harms no file of the system.
        stream = os.path.join(work, "stdout.path")
        os.symlink("/proc/self/fd/1", stream)
        redirected = os.path.join(work, "redirected.txt")
        for command, option in (("plan", "--path"), ("plan", "--html"), ("view", "--html")):
            with open(redirected, "w") as out:
                r = subprocess.run([adsd, command, office, option, stream], stdout=out,
                                   stderr=subprocess.PIPE, text=True, timeout=300, cwd=work)
            check(r.returncode == 2 and r.stderr.startswith(
                f"adsd {command}: error: {option}: '{stream}' is in /dev, /proc or /sys (a device or a stream)"),
                f"{command} {option} through a link to /proc/self/fd/1: exit {r.returncode}, {r.stderr!r}")
            check(os.path.islink(stream), f"{command} {option}: the link to /proc/self/fd/1 was replaced by a file")
        r = run(adsd, ["benchmark", office, "--runs", "1", "--time", "0.1", "--out", "/proc/self"], work)
        check(r.returncode == 2 and "--out: '/proc/self' is in /dev, /proc or /sys" in r.stderr,
              f"benchmark --out /proc/self: exit {r.returncode}, {r.stderr!r}")

        # A link planted at NAME.partial, the temporary the file is written under, had the output
        # written into its target (here the world mesh, an input --path refuses by name) and NAME
        # left a link to it (an adversarial review). The temporary is created anew instead.
        world_mesh = os.path.join(os.path.dirname(office), "office_env.obj")
        world_before = pathlib.Path(world_mesh).read_bytes()
        for command, option, extra in (("plan", "--path", ["--seed", "1", "--time", "1"]), ("view", "--html", [])):
            target = os.path.join(work, f"planted.{command}")
            os.symlink(world_mesh, target + ".partial")
            r = run(adsd, [command, office] + extra + [option, target], work)
            check(r.returncode == 0, f"{command} {option} beside a planted .partial link: exit {r.returncode}, "
                  f"{r.stderr!r}")
            if pathlib.Path(world_mesh).read_bytes() != world_before:
                pathlib.Path(world_mesh).write_bytes(world_before)  # the build's mesh, for the tests after
                check(False, f"{command} {option} wrote through the link at {target}.partial into the world mesh")
            check(os.path.isfile(target) and not os.path.islink(target) and not os.path.lexists(target + ".partial"),
                  f"{command} {option}: {target} is not a plain file, or the temporary is left")
        # A path file of 300 000 states took 42 s and wrote a 73 MB page (an adversarial review).
        many = os.path.join(work, "many.path")
        pathlib.Path(many).write_text("0 0 0\n" * 100001)
        expect_refused(adsd, ["view", office, "--path", many, "--html", os.path.join(work, "many.html")], work,
                       f"adsd view: error: {many}:100001: more than 100000 states")
        # A name that fits alone but not with '.partial' added failed after the planning was done.
        long_name = os.path.join(work, "n" * 250)
        expect_refused(adsd, ["plan", office, "--seed", "1", "--time", "1", "--path", long_name], work,
                       f"adsd plan: error: --path: '{long_name}': the name is 250 bytes long; with '.partial' added")

        # An output that is an input, or the other output, is refused: `view p.cfg --html p.cfg`
        # replaced the problem file with a page.
        before = pathlib.Path(office).read_bytes()
        expect_refused(adsd, ["view", office, "--html", office], work,
                       f"adsd view: error: --html: '{office}' is the problem file")
        expect_refused(adsd, ["plan", office, "--path", office], work,
                       f"adsd plan: error: --path: '{office}' is the problem file")
        both = os.path.join(work, "both.out")
        expect_refused(adsd, ["plan", office, "--path", both, "--html", both], work,
                       f"adsd plan: error: --html: '{both}' is the --path file")
        check(pathlib.Path(office).read_bytes() == before, "the problem file was changed")
        check(not os.path.exists(both), "a refused plan wrote " + both)
        # Nor the meshes the problem file names: `--path office_robot.obj` wrote the path over the
        # robot, and the next run found no triangles in it.
        robot = os.path.join(os.path.dirname(office), "office_robot.obj")
        world = os.path.join(os.path.dirname(office), "office_env.obj")
        meshes = {robot: pathlib.Path(robot).read_bytes(), world: pathlib.Path(world).read_bytes()}
        expect_refused(adsd, ["plan", office, "--seed", "1", "--time", "1", "--path", robot], work,
                       f"adsd plan: error: --path: '{robot}' is the robot mesh")
        expect_refused(adsd, ["plan", office, "--seed", "1", "--time", "1", "--html", world], work,
                       f"adsd plan: error: --html: '{world}' is the world mesh")
        expect_refused(adsd, ["view", office, "--html", robot], work,
                       f"adsd view: error: --html: '{robot}' is the robot mesh")
        check(all(pathlib.Path(m).read_bytes() == b for m, b in meshes.items()), "a problem's mesh was changed")

        # Inputs that never end: /dev/zero is one line without end, read to the memory's limit
        # ("internal error: std::bad_alloc" under a 2 GB limit).
        for command in ("plan", "view", "benchmark"):
            extra = ["--html", os.path.join(work, "zero.html")] if command == "view" else []
            expect_refused(adsd, [command, "/dev/zero"] + extra, work,
                           f"adsd {command}: error: /dev/zero: is a device, a pipe or a socket, not a problem file")
        expect_refused(adsd, ["distance", robot, world, "--poses", "/dev/zero"], work,
                       "adsd distance: error: /dev/zero: is a device, a pipe or a socket, not a pose file")
        # `--out` naming a file: said so, where it read "cannot write in directory ...: File exists".
        expect_refused(adsd, ["benchmark", office, "--runs", "1", "--time", "1", "--out", office], work,
                       f"adsd benchmark: error: --out: '{office}' is a file, not a directory")

        # OMPL's FMT* and BFMT* crashed (a segmentation fault) with the clearance objective; TRRT
        # and BiTRRT timed out with it on every problem (they keep the objective's cost low).
        for planner in ("fmt", "bfmt", "trrt", "bitrrt"):
            expect_refused(adsd, ["plan", office, "--planner", planner, "--objective", "clearance", "--time", "0.2"], work,
                           f"adsd plan: error: --planner: planner {planner} cannot plan for the clearance objective")

        page = os.path.join(work, "page.html")
        turned = os.path.join(work, "turned.path")
        pathlib.Path(turned).write_text("-6 2.5 0  # the start\n0 0 4\n6 -2.5 7.853981633974483\n")
        r = run(adsd, ["view", office, "--path", turned, "--html", page], work)
        check(r.returncode == 0, f"view of yaws outside [-pi, pi]: exit {r.returncode} ({r.stderr.strip()})")
        check(os.path.isfile(page), "view of yaws outside [-pi, pi]: no page written")
        # A path file beginning with a UTF-8 byte-order mark, as Windows editors write it: the mark
        # was read as part of the first number ("'\ufeff-6' is not a finite number").
        marked = os.path.join(work, "marked.path")
        pathlib.Path(marked).write_bytes(b"\xef\xbb\xbf" + pathlib.Path(turned).read_bytes())
        m = run(adsd, ["view", office, "--path", marked, "--html", os.path.join(work, "marked.html")], work)
        check(m.returncode == 0 and [line for line in m.stdout.splitlines() if line.startswith("clearance")] ==
              [line for line in r.stdout.splitlines() if line.startswith("clearance")],
              f"view of a path file with a byte-order mark: exit {m.returncode} ({m.stderr.strip()})")
        # Lone carriage returns end lines (classic Mac OS text; read as one line of 9 numbers before),
        # and so do CRLF pairs: the same states, so the same clearance printed.
        for name, end in (("mac", b"\r"), ("dos", b"\r\n")):
            ended = os.path.join(work, name + ".path")
            pathlib.Path(ended).write_bytes(pathlib.Path(turned).read_bytes().replace(b"\n", end))
            e = run(adsd, ["view", office, "--path", ended, "--html", os.path.join(work, name + ".html")], work)
            check(e.returncode == 0 and [line for line in e.stdout.splitlines() if line.startswith("clearance")] ==
                  [line for line in r.stdout.splitlines() if line.startswith("clearance")],
                  f"view of a path file with {end!r} line ends: exit {e.returncode} ({e.stderr.strip()})")
        # A line of millions of numbers is refused by its length, naming it, before its numbers are
        # kept (a 200 MB line took 2.3 GB).
        endless = os.path.join(work, "endless.path")
        pathlib.Path(endless).write_text("-6 2.5 0\n" + "1 " * 600000 + "\n")
        expect_refused(adsd, ["view", office, "--path", endless, "--html", os.path.join(work, "endless.html")], work,
                       f"adsd view: error: {endless}:2: line longer than 1048576 bytes (not a path file?)")
        check(not os.path.exists(os.path.join(work, "endless.html")), "view of an endless line wrote a page")
        # The same turns written within [-pi, pi]: the same states, so the same clearance printed.
        wrapped = os.path.join(work, "wrapped.path")
        pathlib.Path(wrapped).write_text(f"-6 2.5 0\n0 0 {4 - 2 * math.pi!r}\n6 -2.5 {math.pi / 2!r}\n")
        w = run(adsd, ["view", office, "--path", wrapped, "--html", os.path.join(work, "wrapped.html")], work)
        clearance = [line for line in r.stdout.splitlines() if line.startswith("clearance")]
        check(clearance and clearance == [line for line in w.stdout.splitlines() if line.startswith("clearance")],
              f"yaws 4 and 4 - 2 pi printed different clearances:\n{r.stdout}\n{w.stdout}")

        # printAsMatrix's six digits may round a state on a bound outward (x = 10 at x <= 10).
        rounded = os.path.join(work, "rounded.path")
        pathlib.Path(rounded).write_text("-6 2.5 0\n10.00001 -2.5 0\n")
        r = run(adsd, ["view", office, "--path", rounded, "--html", os.path.join(work, "rounded.html")], work)
        check(r.returncode == 0, f"view of a state rounded past a bound: exit {r.returncode} ({r.stderr.strip()})")

        outside = os.path.join(work, "outside.path")
        pathlib.Path(outside).write_text("-6 2.5 0\n1e150 0 0\n")
        os.remove(page)
        expect_refused(adsd, ["view", office, "--path", outside, "--html", page], work,
                       f"adsd view: error: {outside}:2: the state lies outside the problem's bounds (x in [-10, 10]")
        check(not os.path.exists(page), "view of a state outside the bounds wrote a page")

        # `adsd benchmark --out` makes its directory, but not a missing parent: a mistyped name
        # made a tree and filled it.
        nested = os.path.join(work, "no_such_parent", "results")
        expect_refused(adsd, ["benchmark", office, "--runs", "1", "--time", "1", "--out", nested], work,
                       f"adsd benchmark: error: --out: cannot make directory '{nested}': directory "
                       f"'{os.path.dirname(nested)}' does not exist")
        check(not os.path.exists(os.path.dirname(nested)), "benchmark --out made a missing parent")

        # The thin wall, planned with the discrete validator: RRTConnect's path steps over the wall
        # (its states at the resolution are clear), and the `along` line, which measures between
        # them too, finds it at 0: a contact line and exit 1. Certified motions go round.
        thin = os.path.join(os.path.dirname(os.path.abspath(office)), "thin_wall.cfg")
        thin_path = os.path.join(work, "thin.path")
        r = run(adsd, ["plan", thin, "--seed", "1", "--time", "5", "--planner", "rrtconnect", "--path", thin_path],
                work)
        check(r.returncode == 1 and "\nalong       min 0 between the states" in r.stdout
              and "\ncontact     " in r.stdout,
              f"plan thin_wall.cfg, discrete: exit {r.returncode}, stdout {r.stdout!r}")
        # `adsd view` of that path gives the same verdict: its page shows the states' clearances
        # (0.01 here), and nothing said the path steps through the wall (an adversarial review).
        r = run(adsd, ["view", thin, "--path", thin_path, "--html", os.path.join(work, "thin.html")], work)
        check(r.returncode == 0 and "\nalong       min 0 between the states" in r.stdout
              and "\ncontact     the path comes within the safety margin (0) along its motions" in r.stdout
              and os.path.exists(os.path.join(work, "thin.html")),
              f"view thin_wall.cfg --path: exit {r.returncode}, stdout {r.stdout!r}")
        r = run(adsd, ["plan", thin, "--seed", "1", "--time", "5", "--planner", "rrtconnect", "--motion", "certified"],
                work)
        check(r.returncode == 0 and "\nalong       min 0." in r.stdout and "contact" not in r.stdout,
              f"plan thin_wall.cfg, certified: exit {r.returncode}, stdout {r.stdout!r}")

        # A start in collision (x = -9.95: the robot in the office's outer wall): `adsd plan`
        # refuses it, `adsd view` shows it with a warning naming the line.
        folder = os.path.dirname(os.path.abspath(office))
        text = pathlib.Path(office).read_text()
        text = text.replace("start.x = -6", "start.x = -9.95").replace("start.y = 2.5", "start.y = 0")
        text = text.replace("= office_", f"= {folder}/office_")
        touching = os.path.join(work, "touching.cfg")
        pathlib.Path(touching).write_text(text)
        expect_refused(adsd, ["plan", touching, "--time", "1"], work,
                       f"adsd plan: error: {touching}:8: key 'problem.start.x': the start state is in collision")
        shown = os.path.join(work, "touching.html")
        r = run(adsd, ["view", touching, "--html", shown], work)
        check(r.returncode == 0, f"view of a start in collision: exit {r.returncode} ({r.stderr.strip()})")
        check(r.stderr.startswith(f"adsd view: warning: {touching}:8: key 'problem.start.x': the start state is in "
                                  "collision (clearance 0"), f"view of a start in collision: stderr {r.stderr!r}")
        check("clearance   min 0 " in r.stdout, f"view of a start in collision: stdout {r.stdout!r}")
        check(os.path.isfile(shown), "view of a start in collision wrote no page")

        # Past a file-size limit the kernel's SIGXFSZ killed adsd silently (exit 153 from a shell)
        # and left capped.html.partial; the failed write is now an error and nothing is left.
        def capped(args, limit, stdout):
            def lower_limit():
                resource.setrlimit(resource.RLIMIT_FSIZE, (limit, limit))
            return subprocess.run([adsd] + args, stdout=stdout, stderr=subprocess.PIPE, text=True, timeout=300,
                                  cwd=work, preexec_fn=lower_limit)
        r = capped(["view", office, "--html", "capped.html"], 64 * 1024, subprocess.PIPE)
        # With the system's reason: "failed" alone left the user to guess (outside review).
        check(r.returncode == 2
              and r.stderr == "adsd view: error: capped.html: writing the viewer page failed: File too large\n",
              f"view past a file-size limit: exit {r.returncode}, stderr {r.stderr!r}")
        check(not any(name.startswith("capped.html") for name in os.listdir(work)),
              f"view past a file-size limit left {sorted(n for n in os.listdir(work) if n.startswith('capped'))}")
        poses = os.path.join(work, "many.poses")
        pathlib.Path(poses).write_text("".join(f"0 0 {i * 0.001!r} 1 0 0 0 0 0 0 1 0 0 0\n" for i in range(2000)))
        with open(os.path.join(work, "many.out"), "w") as out:
            r = capped(["distance", robot, world, "--poses", poses], 64 * 1024, out)
        check(r.returncode == 1 and r.stderr == "adsd distance: error: cannot write the output: File too large\n",
              f"distance past a file-size limit: exit {r.returncode}, stderr {r.stderr!r}")
        with open(os.path.join(work, "plan.out"), "w") as out:
            r = capped(["plan", office, "--time", "1", "--seed", "1"], 100, out)
        check(r.returncode == 1 and r.stderr == "adsd plan: error: cannot write the standard output\n",
              f"plan past a file-size limit: exit {r.returncode}, stderr {r.stderr!r}")
        # OMPL's own seed comes from the clock in microseconds (16 digits), and --seed took 32 bits
        # only: the printed seed could not be given back (outside review).
        first = run(adsd, ["plan", office, "--path", "chosen.path"], work)
        seed = next((line.split()[1] for line in first.stdout.splitlines() if line.startswith("seed ")), "")
        again = run(adsd, ["plan", office, "--seed", seed, "--path", "again.path"], work)
        # Exit status 1 is a path found within the safety margin between its states, as some seeds give.
        check(first.returncode in (0, 1) and again.returncode == first.returncode
              and f"seed        {seed} (--seed)" in again.stdout,
              f"plan --seed {seed} (as printed): exit {again.returncode} after {first.returncode}, "
              f"{again.stderr.strip() or again.stdout}")
        if again.returncode in (0, 1):
            check(pathlib.Path(work, "chosen.path").read_text() == pathlib.Path(work, "again.path").read_text(),
                  f"plan --seed {seed} (as printed) planned another path")
        # --time took less than 1e7 s where a .cfg's time_limit takes up to 1e8 (outside review):
        # one limit, the clock's, for both.
        longest = run(adsd, ["plan", office, "--seed", "1", "--time", "1e8"], work)
        check(longest.returncode in (0, 1), f"plan --time 1e8: exit {longest.returncode}, {longest.stderr.strip()}")
        expect_refused(adsd, ["plan", office, "--time", "1.5e8"], work,
                       "adsd plan: error: --time: expected a finite number > 0 and <= 1e+08, got '1.5e8'")
        expect_refused(adsd, ["benchmark", office, "--time", "1.5e8"], work,
                       "adsd benchmark: error: --time: expected a finite number > 0 and <= 1e+08, got '1.5e8'")
        # The program's own help and version were printed outside that check: exit 0 into a full
        # disk, as for every command before (outside review).
        with open("/dev/full", "w") as full:
            for args in (["--version"], ["--help"], ["plan", "--help"]):
                r = subprocess.run([adsd] + args, stdout=full, stderr=subprocess.PIPE, text=True, timeout=60)
                check(r.returncode == 1 and r.stderr.endswith("error: cannot write the standard output\n"),
                      f"{' '.join(args)} into a full disk: exit {r.returncode}, stderr {r.stderr!r}")
        # A shipped problem's bare name, run where it is not (the README's `adsd plan office.cfg`
        # outside the problems' directory): refused, pointing to the shipped one.
        for command in (["plan"], ["view", "--html", os.path.join(work, "bare.html")], ["benchmark"]):
            r = run(adsd, [command[0], "office.cfg"] + command[1:], work)
            shipped = r.stderr.strip().rsplit(" ", 1)[-1]
            check(r.returncode == 2 and "the shipped problem of that name is" in r.stderr and os.path.isfile(shipped),
                  f"{command[0]} office.cfg outside its directory: exit {r.returncode}, stderr {r.stderr!r}")
    return report()


if __name__ == "__main__":
    sys.exit(main())
