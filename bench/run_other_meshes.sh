#!/usr/bin/env bash
# The band benchmark (bench_bands) on 22 pairs of real meshes that no benchmark, test or tuning of
# the library used before: the check that a speed-up measured on the shipped scenes holds on
# models it was not tuned on.
#
#   bench/run_other_meshes.sh [BUILD_DIR] [--poses N] [--rounds R] [--bands LIST] [--scratch] [--out DIR]
#
# The meshes are 38 more models of the CGAL data (Debian libcgal-demo), picked for variety: scans
# and sculpted shapes (homer, bull, lion, dino), CAD parts with flat faces and sharp edges
# (fandisk, couplingdown, ALSTOM_TEST4, b9_mesh), thin sheets and fins (blade, turbine), tubes
# (knot1, knot2, cylinder), and pairs whose sizes differ 100-fold (cheese and mannequin-devil,
# lion and elk). Pairs are side by side as listed below; bench_bands places them near, mid range
# and far apart along random lines and in collision, and checks every answer against FCL's.
# About 10 minutes on an idle 2-core machine (20 poses, 2 rounds).
#
# --bands passes bench_bands' band list (default: its five; touching,distant measures the gaps
# below and beyond them); --scratch adds bench_bands' from-scratch column (no trees: our query
# against FCL rebuilding its trees, what a deforming mesh gets). BUILD_DIR (default: build) must
# hold a Release build of bench_bands. Fetches the meshes first (problems/data/fetch_meshes.sh
# --others, into the same cache). Writes into DIR (default bench/results; CI's bench-smoke test
# runs 2 poses, 1 round into its build tree):
#   other_meshes.txt      what bench_bands printed (per pair and band, with the work counters)
#   other_meshes.csv      one row per query, method and round
#   other_meshes.md       the summary per band: median of the pairs' ratios, and the worst pair
# Exit status: bench_bands' (3 when an answer disagrees with FCL's), 1 when the meshes cannot be
# fetched, 2 for a bad command line.
set -euo pipefail
cd "$(dirname "$0")/.."

build=build poses=20 rounds=2 out=bench/results bands="" scratch=""
while [[ $# -gt 0 ]]; do
  case "$1" in
    --poses) [[ $# -ge 2 ]] || { echo "run_other_meshes.sh: --poses needs a number" >&2; exit 2; }; poses=$2; shift ;;
    --rounds) [[ $# -ge 2 ]] || { echo "run_other_meshes.sh: --rounds needs a number" >&2; exit 2; }; rounds=$2; shift ;;
    --bands) [[ $# -ge 2 ]] || { echo "run_other_meshes.sh: --bands needs a list" >&2; exit 2; }; bands=$2; shift ;;
    --scratch) scratch=--scratch ;;
    --out) [[ $# -ge 2 ]] || { echo "run_other_meshes.sh: --out needs a directory" >&2; exit 2; }; out=$2; shift ;;
    -h|--help) sed -n '2,26p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    -*) echo "run_other_meshes.sh: unknown option '$1'" >&2; exit 2 ;;
    *) build=$1 ;;
  esac
  shift
done
[[ -x "$build/bench/bench_bands" ]] || { echo "run_other_meshes.sh: $build/bench/bench_bands not found (build the bench targets first)" >&2; exit 2; }

meshes="${ADSD_DATA_DIR:-$HOME/.cache/adsd/meshes}"
problems/data/fetch_meshes.sh --others --dir "$meshes" >/dev/null || exit 1

readonly PAIRS=(homer:bull dino:triceratops femur:hand fandisk:rotor_small lion:elk mushroom:anchor_dense
  turbine:blade ChineseDragon-10kv:diplodocus cheese:mannequin-devil holes:knot2 ALSTOM_TEST4:boeing
  cylinder:handle mask_cone:horizons elk:three_peaks couplingdown:knot1 rotor_small:retinal
  b9_mesh:mech-holes-shark fandisk_large:polygon_mesh refined_elephant:bear_bis
  cylinder_locally_refined:lion-head turbine:homer blade:bull)
list=""
for p in "${PAIRS[@]}"; do list+="${list:+,}$meshes/${p%%:*}.off:$meshes/${p##*:}.off"; done

mkdir -p "$out"
tmp="$(mktemp -d "${TMPDIR:-/tmp}/adsd-other-meshes.XXXXXX")"
trap 'rm -rf "$tmp"' EXIT
"$build/bench/bench_bands" --scenes "" --pairs "$list" ${bands:+--bands "$bands"} $scratch --poses "$poses" --rounds "$rounds" --counters \
  --csv "$tmp/other_meshes.csv" --summary-md "$tmp/other_meshes.md" > "$tmp/other_meshes.txt"
# Replaced only after a complete run, so a failed one leaves the last good results.
mv -f "$tmp"/other_meshes.{txt,csv,md} "$out"/
echo "run_other_meshes.sh: $out/other_meshes.{txt,csv,md}"
cat "$out/other_meshes.md"
