"""Shared fixtures of the Python module's tests (run by ctest: tests/python/CMakeLists.txt
passes POLYDEM_BINARY and POLYDEM_SOURCE_DIR, and PYTHONPATH=build/python)."""
import os
import subprocess
import sys

import pytest

sys.path.insert(0, os.path.dirname(__file__))  # compare_outputs

SOURCE = os.environ.get("POLYDEM_SOURCE_DIR", os.path.abspath(os.path.join(os.path.dirname(__file__), "..", "..")))
BINARY = os.environ.get("POLYDEM_BINARY", os.path.join(SOURCE, "build", "polydem"))


@pytest.fixture
def source():
    return SOURCE


def deck(path):
    return os.path.join(SOURCE, path)


def polydem_cli(*args):
    """Runs the command line; returns the CompletedProcess."""
    return subprocess.run([BINARY, *map(str, args)], capture_output=True, text=True,
                          env=dict(os.environ, OMP_NUM_THREADS="2"))
