# SPDX-License-Identifier: MIT
"""The example a scientist copies (examples/afm_worn_tip.py), the README's
Python quick start and the longer one of docs/python.md run as written; the example writes its plot, and its
fresh-tip pull-off through the engine agrees with the closed form to the 4
digits it prints. Tolerance: the printed digits."""
import os
import re
import subprocess
import sys

from conftest import PKG, ROOT


def test_afm_worn_tip(tmp_path):
    out = tmp_path / "cycle.png"
    env = dict(os.environ, PYTHONPATH=PKG, MPLBACKEND="Agg")
    p = subprocess.run([sys.executable, os.path.join(ROOT, "examples", "afm_worn_tip.py"), str(out)],
                       env=env, capture_output=True, text=True, timeout=300)
    assert p.returncode == 0, p.stderr
    F = {m[0].strip(): float(m[1]) for m in re.findall(r"^  (.*?)F = *(-?[0-9.]+) nN", p.stdout, re.M)}
    assert F["fresh tip, closed form (mdr_critical)"] == F["fresh tip, spring engine"] < 0
    assert F["worn tip (sampled), spring engine"] < 3 * F["fresh tip, spring engine"]  # the flat holds on
    assert out.stat().st_size > 20000


def test_readme_quick_start(capsys):
    """The README's Python quick start runs as written and prints -1.5 pi w R."""
    with open(os.path.join(ROOT, "README.md")) as f:
        text = f.read()
    block = re.search(r"^## Python quick start\n.*?^```python\n(.*?)^```", text, re.S | re.M).group(1)
    exec(compile(block, "README.md (Python quick start)", "exec"), {})
    ref = -1.5 * 3.141592653589793 * 0.05 * 10e-6
    # measured: equal to the last bit; 1e-15 relative (about 5 ulp) for other libms
    assert abs(float(capsys.readouterr().out) / ref - 1) < 1e-15


def test_docs_quick_start(tmp_path, monkeypatch):
    """The quick start of docs/python.md runs as written."""
    with open(os.path.join(ROOT, "docs", "python.md")) as f:
        text = f.read()
    block = re.search(r"^## Python\n.*?^```python\n(.*?)^```", text, re.S | re.M).group(1)
    monkeypatch.chdir(tmp_path)
    scope = {}
    exec(compile(block, "docs/python.md (Python quick start)", "exec"), scope)
    assert scope["s"].F < 0 and scope["run"].pull_off is not None and (tmp_path / "cycle.png").exists()


def test_fit_curve_example(tmp_path):
    """examples/fit_curve.py: both fits of its noisy worn-tip curve find E*
    and w within 3 of their standard errors (1 % noise: E* to about 4 %),
    and the plot is written."""
    out = tmp_path / "fit.png"
    env = dict(os.environ, PYTHONPATH=PKG, MPLBACKEND="Agg")
    p = subprocess.run([sys.executable, os.path.join(ROOT, "examples", "fit_curve.py"), str(out)],
                       env=env, capture_output=True, text=True, timeout=300)
    assert p.returncode == 0, p.stderr
    rows = re.findall(r"^(paraboloid R = 20 nm|worn tip \(samples\)) +E\* = (\S+) \+- (\S+) Pa, w = (\S+) \+- (\S+) J",
                      p.stdout, re.M)
    assert len(rows) == 2, p.stdout
    for _, E, dE, w, dw in rows:
        assert abs(float(E) - 1e9) < 3 * float(dE) and abs(float(w) - 0.05) < 3 * float(dw), p.stdout
    assert out.stat().st_size > 20000
