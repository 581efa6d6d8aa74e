# SPDX-License-Identifier: MIT
"""mdr.plot.fd renders F-d and F-z curves in nm and nN with the events
marked (the PNGs are written to build/python/plots/ to look at). Tolerances:
the marked points are the events' states to 1e-12 relative (unit scaling
only)."""
import os
import subprocess
import sys

import matplotlib
import numpy as np

import mdr
from conftest import PKG, ROOT

matplotlib.use("Agg")
OUT = os.path.join(ROOT, "build", "python", "plots")


def marked(ax, colour):
    """(x, y) of the single-point markers of a colour."""
    pts = []
    for ln in ax.get_lines():
        x, y = ln.get_data()
        if len(x) == 1 and ln.get_color() == colour:
            pts.append((float(x[0]), float(y[0])))
    return pts


def test_fd_marks_pull_off_and_jumps():
    os.makedirs(OUT, exist_ok=True)
    # the seed's wavy profile (4.54: h/lam = 0.03, lam/R = 0.05, 2 pi w/(E* R) = 0.05)
    c = mdr.Contact("wavy", E=1e6, w=0.0796, R=10e-6, h=1.5e-8, lam=5e-7)
    run = mdr.Engine(c, springs=4096, w_adv=0.0796, k_machine=2.0).run([0, 4e-6, -20e-6], control="machine",
                                                                      steps_per_segment=4000)
    kinds = [e.kind for e in run.events]
    assert "pull-off" in kinds and kinds.count("jump") >= 3
    for x in ("d", "z"):
        ax = mdr.plot.fd(run, x=x, contact=c, length_unit="nm", force_unit="uN")
        ax.figure.savefig(os.path.join(OUT, "wavy_F%s.png" % x), dpi=80)
        po = run.pull_off
        xpo = (po.d0 + po.F0 / 2.0 if x == "z" else po.d0) / 1e-9
        assert np.allclose(marked(ax, "tab:red"), [(xpo, po.F0 / 1e-6)], rtol=1e-12)
        jumps = [e for e in run.events if e.kind == "jump"]
        want = [((e.d0 + e.F0 / 2.0 if x == "z" else e.d0) / 1e-9, e.F0 / 1e-6) for e in jumps]
        assert np.allclose(marked(ax, "tab:orange"), want, rtol=1e-12)
        assert "pull-off" in " ".join(t.get_text() for t in ax.texts)
        assert ax.get_xlabel() == ("base position z [nm]" if x == "z" else "indentation d [nm]")
        assert ax.get_ylabel() == "force F [\u00b5N]"
        assert os.path.getsize(os.path.join(OUT, "wavy_F%s.png" % x)) > 10000


def test_import_mdr_does_not_import_matplotlib():
    code = "import sys; import mdr; print('matplotlib' in sys.modules)"
    out = subprocess.run([sys.executable, "-c", code], cwd=PKG, capture_output=True, text=True, check=True)
    assert out.stdout.strip() == "False"
