"""Fixtures for the Python module's tests: the CLI built beside the module
(DEEPGUIDE_CLI), the source tree (DEEPGUIDE_SOURCE) and the shared real data
beside it; ctest sets both (tests/CMakeLists.txt)."""

import json
import os
import pathlib
import subprocess

import pytest

SOURCE = pathlib.Path(os.environ.get("DEEPGUIDE_SOURCE", pathlib.Path(__file__).resolve().parents[2]))
REAL = SOURCE.parent / "shared" / "data" / "real"


@pytest.fixture(scope="session")
def cli():
    path = os.environ.get("DEEPGUIDE_CLI")
    if not path or not os.access(path, os.X_OK):
        pytest.skip("DEEPGUIDE_CLI names no deepguide command (run through ctest)")

    def run(*args, check=True):
        done = subprocess.run([path, *map(str, args)], capture_output=True, text=True)
        if check and done.returncode != 0:
            raise AssertionError(f"deepguide {' '.join(map(str, args))}: exit {done.returncode}: {done.stderr}")
        return done

    return run


@pytest.fixture(scope="session")
def sample():
    return SOURCE / "data" / "sample_obstacles.geojson"


def real_file(relative):
    path = REAL / relative
    if not path.exists():
        pytest.skip(f"{path} is absent (the shared real data)")
    return path


def cli_json(done):
    return json.loads(done.stdout)
