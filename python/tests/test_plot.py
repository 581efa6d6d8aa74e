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


def test_fit_plot_draws_data_model_and_pull_off():
    """mdr.plot.fit: the samples, the fitted model (FitResult.model(), broken
    at the jump-in and at the pull-off) and the pull-off marked at the
    model's (pull_off_z, pull_off_F + F_base)."""
    os.makedirs(OUT, exist_ok=True)
    c = mdr.Contact("paraboloid", E=1e9, w=0.05, R=20e-9)
    run = mdr.Engine(c, springs=1024, w_adv=0.05, k_machine=0.2).run([-1e-8, 2e-8, -4e-8], control="machine",
                                                                    steps_per_segment=1000)
    res = mdr.fit(run.z + 1e-6, run.F + 2e-10, "paraboloid", R=20e-9, k_machine=0.2, approach=True)
    ax = mdr.plot.fit(res)
    ax.figure.savefig(os.path.join(OUT, "fit.png"), dpi=80)
    data, model = ax.get_lines()[:2]
    assert np.array_equal(data.get_data()[0], res.z / 1e-9) and np.array_equal(data.get_data()[1], res.F / 1e-9)
    Fm, top = res.model()
    xm, ym = (np.asarray(v, dtype=float) for v in model.get_data())
    assert np.isnan(xm).sum() == 4 and np.array_equal(ym[~np.isnan(ym)], Fm / 1e-9)
    po = [(res.pull_off_z / 1e-9, (res.pull_off_F + res.F_base) / 1e-9)]
    assert np.allclose(marked(ax, model.get_color()), po, rtol=1e-12)
    # the line breaks at the model's pull-off: the last contact point lies at the marker's z
    brk = np.flatnonzero(np.isnan(xm))[2]
    assert abs(xm[brk - 1] - po[0][0]) < 0.1 and "pull-off" in ax.texts[0].get_text()
    ax2 = mdr.plot.fit(res, ax=ax, data=False, label="again")
    assert ax2 is ax and len(ax.get_lines()) == 7  # data, model, marker, baseline; model, marker, baseline
