#!/usr/bin/env python3
"""`adsd --help` and each command's help: the same layout, and the options docs/commands.md lists.

  help_and_docs.py ADSD REPOSITORY_ROOT

Checks that `adsd --help` names every command, and that `adsd` alone or with an unknown command
is one line on stderr and exit status 2; that `adsd COMMAND --help` (and -h, and --help
after other arguments, bad or not) exits 0 with nothing on stderr and prints "usage: adsd COMMAND",
a description, "options:" and "-h [ --help ]"; and that the options listed there are exactly the
options docs/commands.md's section "## `adsd COMMAND`" names.
"""
import pathlib
import re
import subprocess
import sys

from script_checks import check, report

COMMANDS = ["distance", "plan", "benchmark", "view", "srdf"]


def run(adsd, args):
    return subprocess.run([adsd] + args, capture_output=True, text=True, timeout=60)


def docs_options(page, command):
    text = page.read_text()
    match = re.search(r"^## `adsd %s`\n(.*?)(?=^## )" % command, text, re.M | re.S)
    if not check(match is not None, "docs/commands.md: no section '## `adsd %s`'" % command):
        return set()
    return set(re.findall(r"`(--[a-z][a-z-]*)", match.group(1)))


def help_options(text):
    listed = text.split("\noptions:\n", 1)[1] if "\noptions:\n" in text else ""
    return {m for m in re.findall(r"^\s+(?:-\w \[ )?(--[a-z][a-z-]*)", listed, re.M)} - {"--help"}


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    adsd, root = sys.argv[1], pathlib.Path(sys.argv[2])
    p = run(adsd, ["--help"])
    check(p.returncode == 0 and p.stderr == "", "adsd --help: exit %d, stderr %r" % (p.returncode, p.stderr))
    check(p.stdout.startswith("usage: adsd <command>"), "adsd --help does not start with its usage:\n" + p.stdout)
    for command in COMMANDS:
        check(re.search(r"^  %s\s" % command, p.stdout, re.M) is not None, "adsd --help does not list " + command)
    for args in ([], ["no-such-command"]):
        p = run(adsd, args)
        check(p.returncode == 2 and p.stdout == "" and len(p.stderr.splitlines()) == 1,
              "adsd %s: exit %d, expected 2 and one line on stderr, got %r" % (" ".join(args), p.returncode, p.stderr))
    for command in COMMANDS:
        for args in (["--help"], ["-h"], ["--bogus", "--help"], ["x", "y", "--time", "abc", "-h"]):
            p = run(adsd, [command] + args)
            shown = "adsd %s %s" % (command, " ".join(args))
            check(p.returncode == 0 and p.stderr == "", "%s: exit %d, stderr %r" % (shown, p.returncode, p.stderr))
            check(p.stdout.startswith("usage: adsd %s " % command), "%s does not start with its usage:\n%s"
                  % (shown, p.stdout))
            for part in ("\n\n", "\noptions:\n", "-h [ --help ]", "Exit status"):
                check(part in p.stdout, "%s: no %r in:\n%s" % (shown, part, p.stdout))
        listed = help_options(run(adsd, [command, "--help"]).stdout)
        documented = docs_options(root / "docs" / "commands.md", command)
        check(bool(listed), "adsd %s --help lists no option" % command)
        check(listed == documented, "adsd %s: --help lists %s, docs/commands.md %s (only in help: %s, only in docs: %s)"
              % (command, sorted(listed), sorted(documented), sorted(listed - documented), sorted(documented - listed)))
    return report()


if __name__ == "__main__":
    sys.exit(main())
