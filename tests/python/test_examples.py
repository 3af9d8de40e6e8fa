"""docs/PYTHON.md's worked examples cannot rot: each script under
docs/examples runs as a reader would run it and makes its figure, and the
document shows each script as it is."""

import os
import re
import subprocess
import sys

import pytest

from conftest import SOURCE, real_file

EXAMPLES = SOURCE / "docs" / "examples"


def run(script, *args):
    done = subprocess.run([sys.executable, str(EXAMPLES / script), *map(str, args)], capture_output=True, text=True,
                          env=dict(os.environ))
    assert done.returncode == 0, done.stderr
    return done


def is_png(path):
    return path.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n" and path.stat().st_size > 10000


def test_the_document_shows_each_example_as_it_is():
    text = (SOURCE / "docs" / "PYTHON.md").read_text()
    blocks = re.findall(r"```python\n# docs/examples/(\S+)\n(.*?)```", text, re.S)
    assert sorted(name for name, _ in blocks) == sorted(p.name for p in EXAMPLES.glob("*.py"))
    for name, body in blocks:
        assert body == (EXAMPLES / name).read_text(), name


def test_turning_rates(tmp_path):
    pytest.importorskip("matplotlib")
    run("turning_rates.py", tmp_path / "rates.png")
    assert is_png(tmp_path / "rates.png")


def test_plan_on_a_chart(tmp_path):
    pytest.importorskip("matplotlib")
    cell = real_file("noaa-enc-US4MD81M/US4MD81M.000")
    run("plan_on_a_chart.py", cell, tmp_path / "chart.png")
    assert is_png(tmp_path / "chart.png")
