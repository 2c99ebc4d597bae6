#!/usr/bin/python3
"""Pastes benchmark output into a Markdown page (docs/benchmarks.md, docs/numerics.md, README.md)
between <!-- results:NAME:begin --> and <!-- results:NAME:end -->, so that every figure of the
docs is what a command printed.

    bench/paste_results.py PAGE.md NAME "COMMAND" OUTPUT [ "COMMAND" OUTPUT ... ]

Each OUTPUT is shown under the command that produced it: a Markdown file (.md) as it is, anything
else as a preformatted block. The section is replaced whole; nothing outside the markers changes.
"""
import datetime
import pathlib
import re
import sys


def render(pairs):
    today = datetime.date.today().isoformat()
    parts = [f"<!-- pasted by bench/paste_results.py on {today}; do not edit by hand -->"]
    for command, output in pairs:
        path = pathlib.Path(output)
        text = path.read_text().rstrip()
        parts.append(f"`{command}`:")
        if path.suffix == ".md":
            text = re.sub(r"^<!--.*?-->\n", "", text, flags=re.S)
            parts.append(text)
        else:
            parts.append("```\n" + text + "\n```")
    return "\n\n".join(parts)


def main(argv):
    if len(argv) < 5 or len(argv) % 2 == 0:
        sys.exit(__doc__)
    page, name = pathlib.Path(argv[1]), argv[2]
    pairs = list(zip(argv[3::2], argv[4::2]))
    begin, end = f"<!-- results:{name}:begin -->", f"<!-- results:{name}:end -->"
    text = page.read_text()
    if begin not in text or end not in text:
        sys.exit(f"{page}: no markers {begin} ... {end}")
    head, rest = text.split(begin, 1)
    _, tail = rest.split(end, 1)
    page.write_text(head + begin + "\n" + render(pairs) + "\n" + end + tail)


if __name__ == "__main__":
    main(sys.argv)
