"""Shared fixtures: the command-line binary the Python results are compared with."""
import os
import subprocess

import pytest


@pytest.fixture(scope="session")
def aapat_cli():
    """Runs the aapat executable of the same build (AAPAT_BINARY, set by ctest)."""
    binary = os.environ.get("AAPAT_BINARY")
    if not binary:
        pytest.skip("AAPAT_BINARY is not set (run through ctest)")

    def run(*args):
        return subprocess.run([binary, *args], check=True, capture_output=True, text=True).stdout

    return run
