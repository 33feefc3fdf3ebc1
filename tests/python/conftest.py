"""Shared fixtures of the trimlab module tests: the built command line (to compare the
module with it on the same input), the repository's small test files and an output
folder. CTest sets PYTHONPATH to the build tree's package and TRIMLAB_CLI to the binary."""

import os
import pathlib
import subprocess

import pytest

REPO = pathlib.Path(__file__).resolve().parents[2]
DATA = REPO / "tests" / "data"


@pytest.fixture(scope="session")
def cli():
    path = os.environ.get("TRIMLAB_CLI", str(REPO / "build" / "app" / "trimlab"))
    if not os.access(path, os.X_OK):
        pytest.fail(f"the trimlab command line is not built at {path} (set TRIMLAB_CLI)")
    return path


@pytest.fixture(scope="session")
def run_cli(cli):
    """Runs `trimlab ARGS...`; returns (exit code, stdout, stderr)."""

    def run(*arguments):
        done = subprocess.run([cli, *arguments], capture_output=True, text=True, timeout=120,
                              env={**os.environ, "QT_QPA_PLATFORM": "offscreen"})
        return done.returncode, done.stdout, done.stderr

    return run


@pytest.fixture(scope="session")
def data():
    return DATA


@pytest.fixture
def out(tmp_path):
    return tmp_path
