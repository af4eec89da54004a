"""pytest configuration of the MCA package tests (see mcatest.py)."""

import pathlib
import sys

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent / "python"))

import mcatest  # noqa: E402


def pytest_generate_tests(metafunc):
    if "build" in metafunc.fixturenames:
        metafunc.parametrize("build", mcatest.builds(), ids=[b.name for b in mcatest.builds()])


