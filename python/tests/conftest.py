"""What the tests share: the command-line binary to compare with, and the repository's scenes."""

import os
import pathlib
import subprocess

import pytest

REPOSITORY = pathlib.Path(os.environ.get("DATOMSIM_SOURCE_DIR", pathlib.Path(__file__).parents[2]))


@pytest.fixture
def cli(tmp_path):
    """Runs the datomsim command line (the DATOMSIM binary) in tmp_path; returns the process."""
    binary = os.environ.get("DATOMSIM")
    if not binary:
        pytest.fail("DATOMSIM names no binary: run the tests through ctest (Python.Tests)")

    def run(*arguments):
        return subprocess.run(
            [binary, "--quiet", *map(str, arguments)],
            cwd=tmp_path,
            capture_output=True,
            text=True,
            check=False,
        )

    return run


@pytest.fixture
def scenes():
    return REPOSITORY / "scenes"
