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
    keep each tolerance within 10x of what it measures. With pytest-xdist
    (make python-test runs two workers) each worker sends its worst errors
    to the controller, which prints them merged."""

    files = []
    merged = {}  # (the controller's: name -> {key: worst err} of every worker)

    def __init__(self, name):
        self.name = name
        self.seen = {}
        Worst.files.append(self)

    def __call__(self, err, tol, key=None):
        Worst.keep(self.seen, [("%.3g" % tol if key is None else key, err)])
        return err < tol

    @staticmethod
    def keep(seen, pairs):
        """The worst err per key of pairs (key, err) into seen."""
        for key, err in pairs:
            seen[key] = max(seen.get(key, 0.0), err)


def pytest_sessionfinish(session):
    """A worker's worst errors, for the controller (xdist's workeroutput)."""
    out = getattr(session.config, "workeroutput", None)
    if out is not None:
        out["mdr_worst"] = [[w.name, [[k, float(v)] for k, v in w.seen.items()]] for w in Worst.files if w.seen]


@pytest.hookimpl(optionalhook=True)
def pytest_testnodedown(node, error):
    """The controller: a worker's worst errors into Worst.merged."""
    for name, pairs in getattr(node, "workeroutput", {}).get("mdr_worst", []):
        Worst.keep(Worst.merged.setdefault(name, {}), pairs)


def pytest_terminal_summary(terminalreporter):
    for w in Worst.files:
        if w.seen:
            Worst.keep(Worst.merged.setdefault(w.name, {}), w.seen.items())
    for name in sorted(Worst.merged):
        terminalreporter.write_line("%s worst errors: %s" % (name, ", ".join(
            "%s: %.2g" % kv for kv in sorted(Worst.merged[name].items()))))
