#!/usr/bin/env bash
# Shared set-up for the README's commands: installs the Debian packages
# deepguide needs (only those missing), then configures and builds.
# Usage (sourced): deepguide_setup BUILD_DIR [extra CMake arguments...]
# (everything: the library, the CLI, the tests and benchmarks), or
# deepguide_setup_cli BUILD_DIR: only the `deepguide` command and its library,
# for the README's main job (about half the time on a fresh 2-core machine).
set -euo pipefail

DEEPGUIDE_ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
DEEPGUIDE_PACKAGES=(
  g++ cmake ninja-build pkg-config git
  libeigen3-dev libboost-dev libboost-graph-dev
  libgdal-dev libgeos-dev gdal-bin libcli11-dev libyaml-cpp-dev nlohmann-json3-dev
  libcairo2-dev libxml2-dev zlib1g-dev libgtest-dev libgmock-dev libbenchmark-dev libcgal-dev
  python3-dev pybind11-dev python3-numpy python3-pytest python3-venv python3-pip python3-setuptools
  python3-matplotlib
  # The web map: Leaflet, inlined into every page; Chromium, headless, tests the pages.
  libjs-leaflet chromium
  # The size check (scripts/check_sizes.sh, ctest `sizes`) finds functions with it.
  universal-ctags
)

deepguide_install_packages() {
  local missing=()
  for p in "${DEEPGUIDE_PACKAGES[@]}"; do
    if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
      missing+=("$p")
    fi
  done
  if [ ${#missing[@]} -eq 0 ]; then
    return 0
  fi
  echo "deepguide: installing Debian packages: ${missing[*]}" >&2
  if [ "$(id -u)" -ne 0 ]; then
    if command -v sudo >/dev/null 2>&1 && sudo -n true 2>/dev/null; then
      sudo apt-get update -qq && sudo DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends "${missing[@]}"
      return 0
    fi
    echo "deepguide: these packages are missing and this is not root. Run:" >&2
    echo "  sudo apt-get install -y ${missing[*]}" >&2
    exit 1
  fi
  apt-get update -qq
  DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
}

deepguide_configure() {
  local build_dir="$1"
  shift
  deepguide_install_packages
  cmake -S "$DEEPGUIDE_ROOT" -B "$build_dir" -G Ninja -DCMAKE_BUILD_TYPE=Release \
        -DDEEPGUIDE_WERROR=ON "$@" >/dev/null
}

deepguide_setup() {
  deepguide_configure "$@"
  cmake --build "$1" -j "$(nproc)"
}

deepguide_setup_cli() {
  deepguide_configure "$@"
  cmake --build "$1" -j "$(nproc)" --target deepguide_cli
}
