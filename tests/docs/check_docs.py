#!/usr/bin/python3
"""Checks the README and docs/*.md the way a reader would find their faults:

- every relative link and image resolves to a file of the repository (and a #fragment to a
  heading of the linked page);
- every figure block (a fenced block of output, or a table with numbers) names the command that
  made it: a command of the project (`bench/...`, `build/...`, `tests/...`, `adsd ...`) in the
  lines just above it;
- README.md is a page: at most 200 lines, the two commands first;
- the README's library and OMPL examples are the programs tests/find_package builds (every line
  of each example appears, in order, in the part of the program marked as the README's).

    tests/docs/check_docs.py REPOSITORY_ROOT

Prints one line per fault (FILE:LINE: what) and exits 1 when there is any.
"""
import pathlib
import re
import sys

MAX_README_LINES = 200
# How far above a figure block its command may be named (lines; a caption paragraph and the
# command line above it fit).
CAPTION_WINDOW = 14
COMMAND = re.compile(r"(?:^|[\s`(])(?:/usr/bin/python3 )?(?:\S*/)?(?:bench|build[^\s/]*|tests|problems)/\S+"
                     r"|`adsd (?:distance|plan|benchmark)\b")
LINK = re.compile(r"!?\[[^\]]*\]\(([^)\s]+)\)")
NUMBER_CELL = re.compile(r"^\s*\**[-+]?[\d.,]*\d[\d.,e+\-–× %()]*\**\s*$")

faults = []


def fault(path, line, what):
    faults.append(f"{path}:{line}: {what}")


def slug(heading):
    """GitHub's anchor for a heading: lower case, punctuation dropped, spaces to hyphens."""
    text = re.sub(r"[`*_]", "", heading.strip().lower())
    text = re.sub(r"[^\w\- ]", "", text)
    return text.replace(" ", "-")


def anchors(path):
    return {slug(m.group(1)) for m in re.finditer(r"^#+ (.*)$", path.read_text(), re.M)}


def fences(lines):
    """(start, end, language) of each fenced block, 0-based line numbers of the fences."""
    blocks, start, language = [], None, ""
    for i, line in enumerate(lines):
        if line.startswith("```"):
            if start is None:
                start, language = i, line[3:].strip()
            else:
                blocks.append((start, i, language))
                start = None
    return blocks


def check_links(root, path, lines, in_fence):
    for i, line in enumerate(lines):
        if in_fence[i]:
            continue
        for target in LINK.findall(re.sub(r"`[^`]*`", "", line)):
            if re.match(r"^[a-z]+:", target):  # http:, https:, mailto:
                continue
            file_part, _, fragment = target.partition("#")
            linked = (path.parent / file_part).resolve() if file_part else path
            if not linked.exists():
                fault(path.relative_to(root), i + 1, f"link to {target}: no such file")
            elif not str(linked).startswith(str(root)):
                fault(path.relative_to(root), i + 1, f"link to {target}: outside the repository")
            elif fragment and linked.suffix == ".md" and fragment not in anchors(linked):
                fault(path.relative_to(root), i + 1, f"link to {target}: no heading #{fragment} there")


def names_a_command(lines, start):
    for line in reversed(lines[max(0, start - CAPTION_WINDOW):start]):
        if line.startswith("#"):
            break
        if COMMAND.search(line):
            return True
    return False


def check_figures(root, path, lines, in_fence):
    for start, _, language in fences(lines):
        if language in ("", "text", "console") and not names_a_command(lines, start):
            fault(path.relative_to(root), start + 1, "a block of results without the command that made it")
    i = 0
    while i < len(lines):
        if not in_fence[i] and lines[i].startswith("|"):
            end = i
            while end < len(lines) and lines[end].startswith("|"):
                end += 1
            cells = [c for row in lines[i + 2:end] for c in row.strip().strip("|").split("|")]
            if any(NUMBER_CELL.match(c) for c in cells) and not names_a_command(lines, i):
                fault(path.relative_to(root), i + 1, "a table of figures without the command that made it")
            i = end
        else:
            i += 1


def check_readme_shape(root, readme, lines):
    if len(lines) > MAX_README_LINES:
        fault("README.md", len(lines), f"{len(lines)} lines, more than {MAX_README_LINES}")
    sections = [l for l in lines if l.startswith("## ")]
    if not sections or not sections[0].startswith("## Two commands"):
        fault("README.md", 1, "the first section is not the two commands")


def marked_region(program):
    lines = program.read_text().split("\n")
    begin = next((k for k, l in enumerate(lines) if "README: the" in l), None)
    end = next((k for k, l in enumerate(lines) if begin is not None and k > begin and "end of the README example" in l), None)
    return None if begin is None or end is None else [l.strip() for l in lines[begin + 1:end]]


def check_examples(root, lines):
    examples = {"## The library": root / "tests/find_package/consumer/main.cpp",
                "## In an OMPL program": root / "tests/find_package/consumer/plan_with_ompl.cpp"}
    blocks = fences(lines)
    for heading, program in examples.items():
        at = next((k for k, l in enumerate(lines) if l.strip() == heading), None)
        block = next((b for b in blocks if at is not None and b[0] > at and b[2] == "cpp"), None)
        region = marked_region(program)
        if block is None or region is None:
            fault("README.md", (at or 0) + 1, f"no '{heading}' example, or no README region in {program.relative_to(root)}")
            continue
        wanted = [l.strip() for l in lines[block[0] + 1:block[1]]
                  if l.strip() and not l.startswith("#include") and not l.startswith("namespace ")]
        k = 0
        for n, line in enumerate(wanted):
            while k < len(region) and region[k] != line:
                k += 1
            if k == len(region):
                fault("README.md", block[0] + 2 + n,
                      f"example line not in {program.relative_to(root)} (in this order): {line}")
                break
            k += 1


def main(argv):
    if len(argv) != 2:
        sys.exit(__doc__)
    root = pathlib.Path(argv[1]).resolve()
    pages = [root / "README.md"] + sorted((root / "docs").glob("*.md"))
    for path in pages:
        lines = path.read_text().split("\n")
        in_fence = [False] * len(lines)
        for start, end, _ in fences(lines):
            for k in range(start, end + 1):
                in_fence[k] = True
        check_links(root, path, lines, in_fence)
        check_figures(root, path, lines, in_fence)
        if path.name == "README.md" and path.parent == root:
            check_readme_shape(root, path, lines)
            check_examples(root, lines)
    for f in faults:
        print(f)
    print(f"check_docs: {len(pages)} pages, {len(faults)} faults")
    return 1 if faults else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
