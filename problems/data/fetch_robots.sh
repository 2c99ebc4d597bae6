#!/usr/bin/env bash
# Fetches the real arms of issue 17 into a cache directory, without installing anything
# system-wide: the KUKA KR5 sixx R650 and the Barrett WAM, URDF files with their meshes, from
# Debian's dart-doc package (DART's examples; BSD-2-clause, `Files: *` of the package's copyright
# file, recorded in README.md's "Licences of data" and docs/arms.md). Never committed.
#
#   problems/data/fetch_robots.sh [--dir DIR] [--force]
#
#   --dir DIR   cache directory (default: ${ADSD_ROBOT_DIR:-$HOME/.cache/adsd/robots})
#   --force     fetch again even when the cache is complete
#
# Result: DIR/KR5/"KR5 sixx R650.urdf" with DIR/KR5/meshes/*.STL, DIR/wam/wam.urdf with
# DIR/wam/meshes/wam/* (its package://herb_description/ URIs resolve with DIR/wam on the search
# path), and DIR/dart-doc.copyright, the package's licence file.
# Idempotent; the cache is filled through a temporary directory and renamed into place, so an
# interrupted run leaves nothing half-written. Exit status 0 on success, 1 with a one-line message.
set -euo pipefail

cache_dir="${ADSD_ROBOT_DIR:-$HOME/.cache/adsd/robots}"
force=0
die() { echo "fetch_robots.sh: error: $*" >&2; exit 1; }
say() { echo "fetch_robots.sh: $*"; }

while [[ $# -gt 0 ]]; do
  case "$1" in
    --dir) [[ $# -ge 2 ]] || die "--dir needs a directory"; cache_dir="$2"; shift 2 ;;
    --force) force=1; shift ;;
    -h|--help) sed -n '2,17p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    *) die "unknown argument '$1' (see --help)" ;;
  esac
done

complete() {
  [[ -s "$cache_dir/KR5/KR5 sixx R650.urdf" && -s "$cache_dir/KR5/meshes/palm.STL" &&
     -s "$cache_dir/wam/wam.urdf" && -s "$cache_dir/wam/meshes/wam/wam7_collision.STL" &&
     -s "$cache_dir/dart-doc.copyright" ]]
}
if [[ $force -eq 0 ]] && complete; then
  say "robots already cached in $cache_dir"
  exit 0
fi

command -v apt-get >/dev/null || die "apt-get not found: the robots come from Debian's dart-doc package"
command -v dpkg >/dev/null || die "dpkg not found: needed to unpack dart-doc"
mkdir -p "$cache_dir" || die "cannot create cache directory $cache_dir"
cache_dir="$(cd "$cache_dir" && pwd)"
work_dir="$(mktemp -d "${TMPDIR:-/tmp}/adsd-robots.XXXXXX")" || die "cannot create a temporary directory"
chmod 0755 "$work_dir"
trap 'rm -rf "$work_dir"' EXIT

apt_knows() { apt-cache show dart-doc >/dev/null 2>&1; }
if ! apt_knows; then
  if [[ $(id -u) -eq 0 ]]; then
    say "apt package lists do not know dart-doc: running apt-get update"
    apt-get update -qq || die "apt-get update failed"
    apt_knows || die "dart-doc is not in the apt sources even after apt-get update"
  else
    die "apt package lists do not know dart-doc; run 'sudo apt-get update' once, then run this again"
  fi
fi

deb_dir="$work_dir/deb"
mkdir -p "$deb_dir"
chmod 0777 "$deb_dir"  # apt's sandbox user writes the .deb here
say "downloading Debian package dart-doc (not installed)"
(cd "$deb_dir" && apt-get download -qq dart-doc) || die "apt-get download dart-doc failed"
deb="$(ls "$deb_dir"/dart-doc_*.deb 2>/dev/null | head -n1)"
[[ -n "$deb" ]] || die "apt-get download left no dart-doc_*.deb"
dpkg -x "$deb" "$work_dir/x" || die "dpkg -x $deb failed"
urdf="$work_dir/x/usr/share/doc/dart/data/urdf"
[[ -d "$urdf/KR5" && -d "$urdf/wam" ]] || die "$deb has no data/urdf/KR5 and data/urdf/wam"
[[ -f "$work_dir/x/usr/share/doc/dart-doc/copyright" ]] || die "$deb has no copyright file"

stage="$cache_dir/.partial.$$"
rm -rf "$stage"
mkdir -p "$stage"
cp -r "$urdf/KR5" "$urdf/wam" "$stage/" || die "cannot copy into $stage"
cp "$work_dir/x/usr/share/doc/dart-doc/copyright" "$stage/dart-doc.copyright"
for item in KR5 wam dart-doc.copyright; do
  rm -rf "${cache_dir:?}/$item"
  mv "$stage/$item" "$cache_dir/$item" || die "cannot move $item into $cache_dir"
done
rmdir "$stage"
complete || die "the cache in $cache_dir is incomplete after fetching"
say "KR5 and WAM cached in $cache_dir"
