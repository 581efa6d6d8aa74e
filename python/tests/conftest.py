"""Shared fixtures of the mdr tests: the package from python/ (built in place
by `make python`), the C CLI for comparisons."""
import os
import sys

import pytest

HERE = os.path.dirname(os.path.abspath(__file__))
PKG = os.path.dirname(HERE)
ROOT = os.path.dirname(PKG)
sys.path.insert(0, PKG)


@pytest.fixture(scope="session")
def cli():
    """The mdr CLI (MDR_CLI, default build/host/mdr): missing is a failure,
    not a skip."""
    path = os.environ.get("MDR_CLI", os.path.join(ROOT, "build", "host", "mdr"))
    if not os.access(path, os.X_OK):
        pytest.fail("the mdr CLI is not built at %s (make build/host/mdr, or set MDR_CLI)" % path)
    return path
