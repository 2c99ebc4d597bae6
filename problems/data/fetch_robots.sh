#!/usr/bin/env bash
# Fetches the robots of the arm problems (issue 17) from Debian's dart-doc package into a cache
# directory, without installing anything system-wide. Nothing of it is committed.
#
#   problems/data/fetch_robots.sh [--dir DIR]
#
#   --dir DIR   cache directory (default: ${ADSD_ROBOTS:-$HOME/.cache/adsd/robots}, the directory
#               ${ADSD_ROBOTS} means in an arm problem's .cfg)
#
# Leaves DIR/KR5 (the KUKA KR5 sixx R650: "KR5 sixx R650.urdf" and meshes/), DIR/wam (the Barrett
# WAM: wam.urdf and meshes/), DIR/herb_description -> wam (the package the WAM's package:// URIs
# name), DIR/drchubo (DRC-Hubo, problems/arm_other: drchubo.urdf and meshes/), DIR/atlas (Boston
# Dynamics' Atlas as DART ships it: atlas_v3_no_head.urdf and its meshes, the example of
# `adsd srdf` in docs/commands.md) and DIR/dart-doc.copyright (BSD-2-clause, `Files: *`;
# docs/problem-files.md). Idempotent: does nothing when the four URDFs are there. Exit status 0
# on success, 1 with a one-line message.
set -euo pipefail

cache_dir="${ADSD_ROBOTS:-$HOME/.cache/adsd/robots}"
die() { echo "fetch_robots.sh: error: $*" >&2; exit 1; }
while [[ $# -gt 0 ]]; do
  case "$1" in
    --dir) [[ $# -ge 2 ]] || die "--dir needs a directory"; cache_dir="$2"; shift 2 ;;
    -h|--help) sed -n '2,16p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    *) die "unknown argument '$1' (see --help)" ;;
  esac
done

if [[ -s "$cache_dir/KR5/KR5 sixx R650.urdf" && -s "$cache_dir/wam/wam.urdf" && -s "$cache_dir/drchubo/drchubo.urdf" &&
      -s "$cache_dir/atlas/atlas_v3_no_head.urdf" ]]; then
  [[ -e "$cache_dir/herb_description" ]] || ln -sfn wam "$cache_dir/herb_description"
  echo "fetch_robots.sh: robots already cached in $cache_dir"
  exit 0
fi
command -v apt-get >/dev/null || die "apt-get not found: the robots come from Debian's dart-doc package"
policy="$(apt-cache policy dart-doc 2>/dev/null || true)"
if [[ ! "$policy" =~ Candidate:\ [0-9] ]]; then
  [[ $(id -u) -eq 0 ]] || die "apt does not know dart-doc; run 'sudo apt-get update' once, then run this again"
  apt-get update -qq || die "apt-get update failed"
fi

mkdir -p "$cache_dir" || die "cannot create $cache_dir"
work="$(mktemp -d "${TMPDIR:-/tmp}/adsd-robots.XXXXXX")"
trap 'rm -rf "$work"' EXIT
chmod 0777 "$work"  # apt's sandbox user writes the .deb here
echo "fetch_robots.sh: downloading Debian package dart-doc (not installed)"
(cd "$work" && apt-get download -qq dart-doc) || die "apt-get download dart-doc failed"
deb="$(ls "$work"/dart-doc_*.deb 2>/dev/null | head -n1)"
[[ -n "$deb" ]] || die "apt-get download left no dart-doc_*.deb"
dpkg -x "$deb" "$work/x" || die "dpkg -x $deb failed"
urdf="$work/x/usr/share/doc/dart/data/urdf"
[[ -d "$urdf/KR5" && -d "$urdf/wam" && -d "$urdf/drchubo" ]] || die "$deb has no data/urdf/KR5, wam and drchubo"
[[ -d "$urdf/../sdf/atlas" ]] || die "$deb has no data/sdf/atlas"
for robot in KR5 wam drchubo atlas; do
  source="$urdf/$robot"
  [[ "$robot" == atlas ]] && source="$urdf/../sdf/atlas"
  rm -rf "$cache_dir/.$robot.partial"
  cp -r "$source" "$cache_dir/.$robot.partial"
  rm -rf "$cache_dir/$robot"
  mv "$cache_dir/.$robot.partial" "$cache_dir/$robot"
done
ln -sfn wam "$cache_dir/herb_description"
cp "$work/x/usr/share/doc/dart-doc/copyright" "$cache_dir/dart-doc.copyright"
echo "fetch_robots.sh: cached KR5, wam, drchubo and atlas from $(basename "$deb") in $cache_dir"
