#!/usr/bin/env bash
# pip installs the module from the checkout into a fresh venv that sees
# Debian's packages (--system-site-packages: NumPy, setuptools), offline
# (--no-index), reusing the CMake build BUILD_DIR; the installed package then
# imports from elsewhere, says the CMake project's version and plans.
#   tests/python/pip_install.sh SOURCE_DIR BUILD_DIR PYTHON
set -euo pipefail
src="$1" build="$2" python="$3"
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT
"$python" -m venv --system-site-packages "$tmp/venv"
DEEPGUIDE_BUILD_DIR="$build" "$tmp/venv/bin/python" -m pip install --quiet --no-build-isolation --no-index "$src" \
  >"$tmp/pip.log" 2>&1 || { cat "$tmp/pip.log" >&2; exit 1; }
want=$(sed -n 's/^project(deepguide VERSION \([0-9.]*\).*/\1/p' "$src/CMakeLists.txt")
cd "$tmp"
"$tmp/venv/bin/python" - "$want" "$src/data/sample_obstacles.geojson" <<'PY'
import importlib.metadata, sys
import deepguide
want, sample = sys.argv[1], sys.argv[2]
assert "venv" in deepguide.__file__, deepguide.__file__
assert deepguide.__version__ == want == importlib.metadata.version("deepguide"), (
    deepguide.__version__, want, importlib.metadata.version("deepguide"))
route = deepguide.plan((10.2405, 54.4470), (10.2640, 54.4560), obstacles=[sample])
assert route.length_m > 1800.0, route
print("pip install: deepguide", deepguide.__version__, "from", deepguide.__file__, "plans", route)
PY
