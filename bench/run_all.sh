#!/usr/bin/env bash
# Every benchmark behind the docs' figures, in one command, and the result blocks of
# docs/benchmarks.md and the README's headline table pasted from their output (one command
# produces the CSV, the tables and the plots).
#
#   bench/run_all.sh [BUILD_DIR] [--long] [--no-paste] [--no-planning] [--paste-only] [--page FILE]
#
# About 10 minutes on an idle 2-core machine (the target is under 15). --long: 40 runs instead
# of 20 on the bug trap and the twisted passage, and the controls (FCL's checker against itself),
# 25-30 minutes; the planning figures of docs/benchmarks.md come from it (PRM's rows need the runs
# and the control, see its planning section). Each step's time is in bench/results/run_all.log.
# --paste-only: run nothing, paste bench/results into the blocks again; --page FILE: paste the
# benchmark blocks into FILE instead of docs/benchmarks.md (same layout); --no-paste: paste nothing.
# (--readme FILE and --no-readme are the old names of --page and --no-paste.)
#
# BUILD_DIR (default: build) must hold a Release build of the targets
#   bench_distance_vs_fcl bench_scenes bench_bands bench_scene_counters bench_checker_calls bench_arms adsd
#   adsd_problems
# and the real meshes and robots must be cached (problems/data/fetch_meshes.sh, fetch_robots.sh).
# Writes bench/results/:
#   distance_vs_fcl.txt   bench_distance_vs_fcl (cow x cow from scratch against FCL)
#   scenes.csv, scenes.md, table1.md, time_vs_error.png, time_vs_triangles.png
#                         bench_scenes: every scene, every method, against the oracle
#   scenes.txt            what bench_scenes printed (per scene: checksums beside the oracle's)
#   ratios.md             bench/ratio_summary.py: the distance ratios against FCL from scenes.csv
#   bands.txt, bands.csv, bands_summary.md, bands.png
#                         bench_bands: every query mode against FCL band by band (near, mid, far,
#                         uniform planning states, in collision) on every rigid scene and two more
#                         real pairs; bench/plot_bands.py: time against error per band
#   arms.txt, arms.md     bench_arms: the arm problems (problems/arm), our checker against FCL's per
#                         state (validity, clearance; validity timed alone too) and certified against
#                         discrete motion checks
#   profile_modes.md      bench/profile_modes.py: where exact and 1 % tolerance queries spend their
#                         time, per stage of the traversal (perf; skipped when perf cannot sample)
#   scene_counters.txt    bench_scene_counters: the planning problems' work per query (node pairs,
#                         triangle pairs) per mode beside the time, ours and FCL's (what bounds a ratio)
#   checker_calls.txt, checker_calls_rrtconnect.txt, checker_calls_prm.txt
#                         bench_checker_calls: microseconds per isValid call of each checker on
#                         the planning problems' uniform states, and on the states RRTConnect and
#                         PRM check (the checker's term of the planning rows)
#   checker_calls_clearance.txt, checker_calls_clearance_rrtstar.txt
#                         bench_checker_calls --clearance: microseconds per exact clearance query of
#                         each checker on the same states: every planning problem's uniform states,
#                         and the states RRT* asks clearance for on the five above (paired, where
#                         clearance_queries.md's planning runs are not)
#   planning_solve_times.md, planning_solve_times_maze.md, planning_solve_times_maze_prm.md,
#   planning_solve_times_hard.md
#                         bench/planning/solve_time_ratios.py: the end-to-end rows (RRTConnect
#                         and PRM, median solve time with our checker and FCL's, interleaved)
#   clearance_queries.md  bench/planning/clearance_query_ratios.py: RRT* with the clearance
#                         objective, each checker's time per clearance query, same seeds
#   planning_control.md, planning_control_hard.md (--long only)
#                         the same with FCL's checker in both places (--control fcl): how far
#                         those rows move when nothing differs
#   run_all.log           what each step printed on stderr, and its time
# then bench/paste_results.py pastes them into docs/benchmarks.md's blocks `speed`, `profile`,
# `planning` and `planning_control`, and a few rows of ratios.md into README.md's block `headline`.
# Each step writes into a temporary directory that replaces bench/results only when every step
# succeeded, so a failed run leaves the last good results and the pages as they were.
# Exit status: the first failing step's (bench_scenes: 3 when an answer disagrees with the oracle).
# Do not edit this script or bench/ while it runs: bash reads a script as it goes, and each step
# runs the bench programs and scripts afresh.
set -euo pipefail
cd "$(dirname "$0")/.."

build=build paste=1 planning=1 paste_only=0 page=docs/benchmarks.md long=0
while [[ $# -gt 0 ]]; do
  case "$1" in
    --no-paste|--no-readme) paste=0 ;;
    --no-planning) planning=0 ;;
    --long) long=1 ;;
    --paste-only) paste_only=1 ;;
    --page|--readme) [[ $# -ge 2 ]] || { echo "run_all.sh: $1 needs a file" >&2; exit 2; }; page=$2; shift ;;
    -h|--help) sed -n '2,56p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    -*) echo "run_all.sh: unknown option '$1'" >&2; exit 2 ;;
    *) build=$1 ;;
  esac
  shift
done

# bench_bands' scenes: every rigid scene of bench_scenes (mesh pairs and planning problems) and two
# real pairs that no other benchmark uses, so that the bands are not read off tuned scenes only.
bands_options() {
  local m=${ADSD_DATA_DIR:-$HOME/.cache/adsd/meshes}
  echo "--scenes all --pairs $m/elephant.off:$m/knot.off,$m/man.off:$m/bunny.off --poses 30 --rounds 3"
}

# The planning problems bench_checker_calls times (those the planning rows run).
checker_call_problems() {
  local p="$1/problem_files"
  echo "$p/office.cfg $p/maze.cfg $p/thin_wall.cfg $p/bug_trap.cfg $p/twisted_passage.cfg"
}

# Every planning problem, for the clearance queries timed on uniform states.
all_problems() {
  local p="$1/problem_files"
  echo "$p/office.cfg $p/maze.cfg $p/thin_wall.cfg $p/bug_trap.cfg $p/twisted_passage.cfg $p/alpha_puzzle.cfg" \
    "$p/cow_doorway.cfg"
}

# A planning table's caption: the command that made it, read back from the table's own "Command:"
# line (which names its options but not the build), with the program and problems of $build.
planning_caption() {
  local options
  options=$(sed -n 's/^.*Command: `bench\/planning\/solve_time_ratios.py \([^`]*\)`.*/\1/p' "$1" | head -1)
  echo "bench/planning/solve_time_ratios.py --adsd $build/planner/app/adsd --problems $build/problem_files $options"
}

# Sets `tables` to each named planning table of bench/results (NAME.md) after its caption, the
# arguments paste_results.py takes.
planning_tables() {
  tables=()
  local name
  for name in "$@"; do
    tables+=("$(planning_caption "bench/results/$name.md")" "bench/results/$name.md")
  done
}

# Pastes bench/results into the pages' blocks (the commands shown are those that made them).
paste_results() {
  /usr/bin/python3 bench/paste_results.py "$page" speed \
    "$build/bench/bench_distance_vs_fcl" bench/results/distance_vs_fcl.txt \
    "$build/bench/bench_scenes --out bench/results (the paper's Table 1)" bench/results/table1.md \
    "/usr/bin/python3 bench/ratio_summary.py bench/results/scenes.csv (ratios against FCL, medians)" bench/results/ratios.md \
    "$build/bench/bench_scene_counters --repeat 20 (work per query on the planning problems)" bench/results/scene_counters.txt
  if [[ -f bench/results/profile_modes.md ]]; then
    /usr/bin/python3 bench/paste_results.py "$page" profile \
      "bench/profile_modes.py --counters $build/bench/bench_scene_counters" bench/results/profile_modes.md \
      "bench/profile_modes.py --counters $build/bench/bench_scene_counters --scenes problem_maze,problem_thin_wall,problem_alpha_puzzle,problem_cow_doorway --repeat 50" \
      bench/results/profile_modes_more.md
  fi
  if [[ -f bench/results/planning_solve_times.md ]]; then
    local calls=()  # results from before bench_checker_calls existed have no checker_calls*.txt
    [[ -f bench/results/checker_calls.txt ]] &&
      calls+=("$build/bench/bench_checker_calls $(checker_call_problems "$build")" bench/results/checker_calls.txt)
    local from
    for from in rrtconnect prm; do
      [[ -f bench/results/checker_calls_$from.txt ]] &&
        calls+=("$build/bench/bench_checker_calls --from $from $(checker_call_problems "$build")"
                bench/results/checker_calls_$from.txt)
    done
    planning_tables planning_solve_times planning_solve_times_maze planning_solve_times_maze_prm \
      planning_solve_times_hard
    /usr/bin/python3 bench/paste_results.py "$page" planning "${calls[@]}" "${tables[@]}"
  fi
  if [[ -f bench/results/clearance_queries.md ]]; then
    local paired=()  # results from before --clearance existed have no checker_calls_clearance*.txt
    [[ -f bench/results/checker_calls_clearance.txt ]] &&
      paired+=("$build/bench/bench_checker_calls --clearance --states 20000 $(all_problems "$build")"
               bench/results/checker_calls_clearance.txt)
    [[ -f bench/results/checker_calls_clearance_rrtstar.txt ]] &&
      paired+=("$build/bench/bench_checker_calls --clearance --from rrtstar --states 20000 $(checker_call_problems "$build")"
               bench/results/checker_calls_clearance_rrtstar.txt)
    /usr/bin/python3 bench/paste_results.py "$page" clearance \
      "bench/planning/clearance_query_ratios.py --adsd $build/planner/app/adsd --problems $build/problem_files --seeds 5 --time 2" \
      bench/results/clearance_queries.md "${paired[@]}"
  fi
  if [[ -f bench/results/planning_control.md ]]; then
    planning_tables planning_control planning_control_hard
    /usr/bin/python3 bench/paste_results.py "$page" planning_control "${tables[@]}"
  fi
  if [[ -f bench/results/bands_summary.md ]]; then
    /usr/bin/python3 bench/paste_results.py "$page" bands \
      "$build/bench/bench_bands $(bands_options | sed "s#$HOME#~#g") --summary-md bench/results/bands_summary.md" \
      bench/results/bands_summary.md \
      "$build/bench/bench_bands (the same run, every scene and band)" bench/results/bands.txt
    /usr/bin/python3 bench/paste_results.py README.md headline_bands \
      "$build/bench/bench_bands $(bands_options | sed "s#$HOME#~#g") --summary-md bench/results/bands_summary.md" \
      bench/results/bands_summary.md
  fi
  if [[ -f bench/results/arms.md ]]; then
    /usr/bin/python3 bench/paste_results.py "$page" arms \
      "$build/bench/bench_arms --validity-alone --summary-md bench/results/arms.md" bench/results/arms.md
    # The README's: the medians' line alone (the page has the table).
    local arms
    arms=$(mktemp --suffix=.md)
    grep '^Median' bench/results/arms.md >"$arms"
    /usr/bin/python3 bench/paste_results.py README.md headline_arms \
      "$build/bench/bench_arms --validity-alone --summary-md bench/results/arms.md (its Median line)" "$arms"
    rm -f "$arms"
  fi
  # The README's headline: a few scenes' main ratios, cut from ratios.md (first table only).
  local headline
  headline=$(mktemp --suffix=.md)
  awk -F'|' -v OFS='|' '
    /^\| scene / || /^\|---/ || /^\| (cows|camels|teddies_deforming|problem_office|problem_alpha_puzzle|problem_cow_doorway) / {
      print "", $2, $4, $5, $7, ""
    }
    /^$/ && NR > 1 { exit }' bench/results/ratios.md >"$headline"
  /usr/bin/python3 bench/paste_results.py README.md headline \
    "/usr/bin/python3 bench/ratio_summary.py bench/results/scenes.csv (its columns 1, 3, 4 and 6 for six scenes)" \
    "$headline"
  rm -f "$headline"
}
if [[ $paste_only -eq 1 ]]; then
  paste_results
  exit 0
fi
for program in bench/bench_distance_vs_fcl bench/bench_scenes bench/bench_bands bench/bench_scene_counters \
  bench/bench_checker_calls bench/bench_arms planner/app/adsd; do
  [[ -x "$build/$program" ]] || { echo "run_all.sh: no $build/$program (build the targets first, see --help)" >&2; exit 2; }
done
[[ -d "$build/problem_files" ]] || { echo "run_all.sh: no $build/problem_files (build adsd_problems)" >&2; exit 2; }

# Inside the repository, so that the commands the tables quote are the ones a reader types.
staging=bench/results.new
rm -rf "$staging"
mkdir -p "$staging"
log=$staging/run_all.log
started=$SECONDS
step() {  # step NAME COMMAND...: runs COMMAND, its stderr into the log, and says how long it took
  local name=$1 t=$SECONDS
  shift
  echo "run_all.sh: $name ..." >&2
  echo "=== $name: $*" >>"$log"
  "$@" 2>>"$log"
  echo "=== $name: $((SECONDS - t)) s" >>"$log"
  echo "run_all.sh: $name done in $((SECONDS - t)) s" >&2
}

# Which code the figures belong to: the source tree the build was configured from, its commit, and
# whether its library, planner, problems or benchmark sources differ from that commit (a clean
# export made by `git archive` holds its commit in the file .adsd-commit instead).
source=$(sed -n 's/^CMAKE_HOME_DIRECTORY:INTERNAL=//p' "$build/CMakeCache.txt")
if [[ -f "$source/.adsd-commit" ]]; then
  code="exported commit $(cat "$source/.adsd-commit")"
elif git -C "$source" rev-parse --short HEAD >/dev/null 2>&1; then
  code="commit $(git -C "$source" rev-parse --short HEAD)"
  git -C "$source" diff --quiet HEAD -- adsd bench planner problems || code+=" with uncommitted changes in adsd/ bench/ planner/ problems/"
else
  code="unknown commit"
fi
echo "=== $(date -u '+%Y-%m-%d %H:%M UTC'); binaries of $build, built from $source ($code); $(nproc) cores, load $(cut -d' ' -f1-3 /proc/loadavg)" >"$log"
step distance_vs_fcl sh -c "'$build/bench/bench_distance_vs_fcl' > '$staging/distance_vs_fcl.txt'"
step scenes sh -c "'$build/bench/bench_scenes' --out '$staging' > '$staging/scenes.txt'"
# The tables quote the command that made them; they are read from bench/results.
sed -i "s#$staging/#bench/results/#g; s#--out $staging#--out bench/results#" "$staging/scenes.md" "$staging/table1.md" "$staging/scenes.txt"
step ratios sh -c "/usr/bin/python3 bench/ratio_summary.py '$staging/scenes.csv' > '$staging/ratios.md'"
step bands sh -c "'$build/bench/bench_bands' $(bands_options) --csv '$staging/bands.csv' \
  --summary-md '$staging/bands_summary.md' > '$staging/bands.txt'"
step bands_plot /usr/bin/python3 bench/plot_bands.py "$staging/bands.csv" "$staging/bands.png"
step arms sh -c "'$build/bench/bench_arms' --validity-alone --summary-md '$staging/arms.md' > '$staging/arms.txt'"
step scene_counters sh -c "'$build/bench/bench_scene_counters' --repeat 20 > '$staging/scene_counters.txt'"
step checker_calls sh -c "'$build/bench/bench_checker_calls' $(checker_call_problems "$build") > '$staging/checker_calls.txt'"
for from in rrtconnect prm; do
  step checker_calls_$from sh -c "'$build/bench/bench_checker_calls' --from $from $(checker_call_problems "$build") \
    > '$staging/checker_calls_$from.txt'"
done
step checker_calls_clearance sh -c "'$build/bench/bench_checker_calls' --clearance --states 20000 \
  $(all_problems "$build") > '$staging/checker_calls_clearance.txt'"
step checker_calls_clearance_rrtstar sh -c "'$build/bench/bench_checker_calls' --clearance --from rrtstar \
  --states 20000 $(checker_call_problems "$build") > '$staging/checker_calls_clearance_rrtstar.txt'"
# perf may be installed yet not allowed to sample (kernel.perf_event_paranoid, containers): try it.
if command -v perf >/dev/null && perf record -q -o "$staging/perf-probe.data" true >/dev/null 2>&1; then
  rm -f "$staging/perf-probe.data"
  # perf samples the program's own cycles, which a busy machine moves less than wall times. The
  # first three scenes at 200 repeats, the rest at 50 (the alpha puzzle's and the cow doorway's
  # queries are the dearest, so fewer of them give as many samples).
  step profile sh -c "bench/profile_modes.py --counters '$build/bench/bench_scene_counters' > '$staging/profile_modes.md'"
  step profile_more sh -c "bench/profile_modes.py --counters '$build/bench/bench_scene_counters' \
    --scenes problem_maze,problem_thin_wall,problem_alpha_puzzle,problem_cow_doorway --repeat 50 > '$staging/profile_modes_more.md'"
else
  rm -f "$staging/perf-probe.data"
  echo "run_all.sh: perf missing or not allowed to sample here; profile_modes*.md kept from the last run" >&2
  cp bench/results/profile_modes*.md "$staging/" 2>/dev/null || true
fi
if [[ $planning -eq 1 ]]; then
  # Solve times spread over orders of magnitude between seeds, and PRM's runs are not paired
  # (its two threads), so a row needs many runs: with a handful, a row's median is one pair's
  # ratio and moves from one run of this script to the next on the same core, and PRM's interval
  # stays wide with a few dozen (bench/planning/solve_time_ratios.py prints both). Two hundred on the
  # problems solved in milliseconds (about a minute each); on the bug trap and the twisted passage,
  # whose runs take seconds, twenty, forty with --long. The maze's PRM row gets five: it is
  # censored (neither checker solves it within 5 s) and costs the time limit per run. The cow
  # doorway and the alpha puzzle are left out: RRTConnect and PRM rarely solve them within a
  # minute with either checker (problems/README.md), so their medians would be the time limit,
  # not a solve time.
  fast_runs=200 hard_runs=$((long ? 40 : 20))
  planning_work=$staging/planning
  step planning /usr/bin/python3 bench/planning/solve_time_ratios.py --adsd "$build/planner/app/adsd" \
    --problems "$build/problem_files" --out "$planning_work/fast" --runs $fast_runs --time 5 --only office,thin_wall
  step planning_maze /usr/bin/python3 bench/planning/solve_time_ratios.py --adsd "$build/planner/app/adsd" \
    --problems "$build/problem_files" --out "$planning_work/maze" --runs $fast_runs --time 5 --only maze \
    --planners rrtconnect
  step planning_maze_prm /usr/bin/python3 bench/planning/solve_time_ratios.py --adsd "$build/planner/app/adsd" \
    --problems "$build/problem_files" --out "$planning_work/maze_prm" --runs 5 --time 5 --only maze --planners prm
  step planning_hard /usr/bin/python3 bench/planning/solve_time_ratios.py --adsd "$build/planner/app/adsd" \
    --problems "$build/problem_files" --out "$planning_work/hard" --runs $hard_runs --time 10 \
    --only bug_trap,twisted_passage
  if [[ $long -eq 1 ]]; then
    # The control: FCL's checker against itself, same commands. Its ratios should be 1; how far
    # they are not, with their intervals, is the noise the rows above must be read against.
    step planning_control /usr/bin/python3 bench/planning/solve_time_ratios.py --adsd "$build/planner/app/adsd" \
      --problems "$build/problem_files" --out "$planning_work/control" --runs $fast_runs --time 5 \
      --only office,thin_wall --control fcl
    step planning_control_hard /usr/bin/python3 bench/planning/solve_time_ratios.py --adsd "$build/planner/app/adsd" \
      --problems "$build/problem_files" --out "$planning_work/control_hard" --runs $hard_runs --time 10 \
      --only bug_trap,twisted_passage --control fcl
    cp "$planning_work/control/solve_times.md" "$staging/planning_control.md"
    cp "$planning_work/control_hard/solve_times.md" "$staging/planning_control_hard.md"
  elif ls bench/results/planning_control*.md >/dev/null 2>&1; then
    echo "run_all.sh: no --long: planning_control*.md kept from the last run with --long" >&2
    cp bench/results/planning_control*.md "$staging/"
  fi
  # Clearance-optimal planning: RRT* with the clearance objective, each checker's time per
  # clearance query on the same seeds (RRT* uses its whole time limit).
  step clearance_queries /usr/bin/python3 bench/planning/clearance_query_ratios.py --adsd "$build/planner/app/adsd" \
    --problems "$build/problem_files" --out "$planning_work/clearance" --seeds 5 --time 2
  cp "$planning_work/clearance/clearance_queries.md" "$staging/clearance_queries.md"
  cp "$planning_work/fast/solve_times.md" "$staging/planning_solve_times.md"
  cp "$planning_work/maze/solve_times.md" "$staging/planning_solve_times_maze.md"
  cp "$planning_work/maze_prm/solve_times.md" "$staging/planning_solve_times_maze_prm.md"
  cp "$planning_work/hard/solve_times.md" "$staging/planning_solve_times_hard.md"
  rm -rf "$planning_work"
elif [[ -d bench/results ]]; then
  cp bench/results/planning_*.md bench/results/clearance_queries.md "$staging/" 2>/dev/null || true
fi
# The stress tables are the numerics suite's (tests/stress: the soak and a run of the current core,
# pasted into docs/numerics.md), and prm_thin_wall_repeat*.md two repeats of one planning command
# that docs/benchmarks.md quotes (how far PRM's rows swing), and other_meshes.* the output of
# bench/run_other_meshes.sh (its own command, pasted by hand); keep them.
for kept in bench/results/stress*.txt bench/results/prm_thin_wall_repeat*.md bench/results/other_meshes.*; do
  [[ -f "$kept" ]] && cp "$kept" "$staging/"
done
echo "=== total: $((SECONDS - started)) s" >>"$log"

rm -rf bench/results.old
[[ -d bench/results ]] && mv bench/results bench/results.old
mv "$staging" bench/results
rm -rf bench/results.old

[[ $paste -eq 1 ]] && paste_results
echo "run_all.sh: bench/results written in $((SECONDS - started)) s$([[ $paste -eq 1 ]] && echo ", $page's blocks and README.md's headline pasted")" >&2
