# SPDX-License-Identifier: MIT
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


class Worst:
    """within(err, tol, key=tol): err < tol, remembering the worst err per
    key; every file's worst errors are printed at the end of the run, to
    keep each tolerance within 10x of what it measures."""

    files = []

    def __init__(self, name):
        self.name = name
        self.seen = {}
        Worst.files.append(self)

    def __call__(self, err, tol, key=None):
        key = "%.3g" % tol if key is None else key
        self.seen[key] = max(self.seen.get(key, 0.0), err)
        return err < tol


def pytest_terminal_summary(terminalreporter):
    for w in Worst.files:
        if w.seen:
            terminalreporter.write_line("%s worst errors: %s" % (w.name, ", ".join(
                "%s: %.2g" % kv for kv in sorted(w.seen.items()))))
