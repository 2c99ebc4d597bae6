#!/usr/bin/python3
"""Opt-in test (ADSD_LONG_TESTS=ON, ctest -L long): issue 7's "10^7 triangles (memory reported,
no crash)" through a file and the adsd program. Writes a binary STL of a flat grid of
2 x 2237^2 = 10 008 338 triangles (500 MB) and a unit box 0.25 above it, runs
`adsd distance grid.stl box.obj`, checks the exit status and the distance, and reports the wall
time and the program's peak resident memory. The files are removed afterwards.

    huge_stl_cli.py ADSD_PROGRAM WORK_DIR [CELLS]
"""
import os
import re
import resource
import shutil
import struct
import subprocess
import sys
import time

CELLS = 2237          # 2 * CELLS^2 >= 10^7 triangles
SIZE = 100.0          # the grid spans [-50, 50]^2 in z = 0
EXPECTED = 0.25       # the box's lowest face is 0.25 above the grid
TOLERANCE = 1e-6      # STL stores float32: the grid's coordinates are rounded to ~4e-6 at 50; z = 0 exactly


def write_grid_stl(path, cells):
    count = 2 * cells * cells
    step = SIZE / cells
    facet = struct.Struct("<12fH")
    with open(path, "wb") as out:
        out.write(b"adsd huge grid".ljust(80, b" ") + struct.pack("<I", count))
        for j in range(cells):
            y0, y1 = j * step - SIZE / 2, (j + 1) * step - SIZE / 2
            row = bytearray()
            for i in range(cells):
                x0, x1 = i * step - SIZE / 2, (i + 1) * step - SIZE / 2
                row += facet.pack(0, 0, 1, x0, y0, 0, x1, y0, 0, x1, y1, 0, 0)
                row += facet.pack(0, 0, 1, x0, y0, 0, x1, y1, 0, x0, y1, 0, 0)
            out.write(row)
    return count


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    adsd, work = sys.argv[1], sys.argv[2]
    cells = int(sys.argv[3]) if len(sys.argv) > 3 else CELLS
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    try:
        grid = os.path.join(work, "grid.stl")
        started = time.time()
        count = write_grid_stl(grid, cells)
        print("wrote %s: %d triangles, %d bytes, %.1f s" % (grid, count, os.path.getsize(grid), time.time() - started))
        box = os.path.join(work, "box.obj")
        with open(box, "w") as f:
            f.write("v -0.5 -0.5 0.25\nv 0.5 -0.5 0.25\nv 0.5 0.5 0.25\nv -0.5 0.5 0.25\n"
                    "v -0.5 -0.5 1.25\nv 0.5 -0.5 1.25\nv 0.5 0.5 1.25\nv -0.5 0.5 1.25\n"
                    "f 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 2 3 7 6\nf 3 4 8 7\nf 4 1 5 8\n")
        started = time.time()
        run = subprocess.run([adsd, "distance", grid, box], capture_output=True, text=True, timeout=3000)
        seconds = time.time() - started
        peak_mib = resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss / 1024.0
        print(run.stdout, end="")
        print(run.stderr, end="", file=sys.stderr)
        print("adsd distance: exit %d, %.1f s, peak resident %.0f MiB (%.1f bytes per triangle)"
              % (run.returncode, seconds, peak_mib, peak_mib * 1048576 / count))
        if run.returncode != 0:
            sys.exit("FAIL: exit status %d" % run.returncode)
        match = re.search(r"^distance\s+(\S+)", run.stdout, re.MULTILINE)
        if not match or abs(float(match.group(1)) - EXPECTED) > TOLERANCE:
            sys.exit("FAIL: expected distance %g, got %s" % (EXPECTED, match.group(1) if match else "nothing"))
        print("ok")
    finally:
        shutil.rmtree(work, ignore_errors=True)


if __name__ == "__main__":
    main()
