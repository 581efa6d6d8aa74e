#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""Fit an AFM force curve: E*, work of adhesion, contact point and baseline
(mdr.fit, libmdr's fit kernel, the same code as `mdr fit --curve`), with
the tip as a closed-form paraboloid and as its sampled (worn) profile,
plotted over the data.

Without a curve file the script makes one as an instrument would record
it: a worn tip (R = 20 nm ground flat to b = 1.5 nm, given as samples) on
a polymer (E* = 1 GPa, w = 0.05 J/m^2), a 0.2 N/m cantilever, an
approach-retract cycle through the spring engine, 1 % force noise, the
piezo's offset z0 = 2 um and a force baseline of 0.3 nN. It is then fitted
twice: with the tip as a paraboloid of R = 20 nm (what one assumes without
a tip image) and with the worn tip's samples.

    make python
    PYTHONPATH=python /usr/bin/python3 examples/fit_curve.py [out.png] [curve.csv]

curve.csv: a header line, then z,F rows in time order (z the base position
[m], increasing toward the sample; F the force [N], compressive positive),
as `mdr fit --curve` reads. Copy the script and put in your tip, your
cantilever's stiffness and your curve.
"""
import sys

import numpy as np

import mdr

R, b = 20e-9, 1.5e-9  # tip radius, radius of the worn flat [m]
k = 0.2               # cantilever stiffness [N/m]

# the worn tip, sampled every 0.25 nm to 40 nm: flat for r < b, then the paraboloid
r = np.arange(161) * 0.25e-9
f = np.where(r < b, 0.0, (r * r - b * b) / (2 * R))

if len(sys.argv) > 2:
    z, F = np.loadtxt(sys.argv[2], delimiter=",", skiprows=1, unpack=True)
else:
    E, w, z0, F_base = 1e9, 0.05, 2e-6, 0.3e-9  # the "unknowns"
    tip = mdr.Contact("table", E=E, w=w, r=r, f=f)
    run = mdr.Engine(tip, springs=1024, w_adv=w, k_machine=k).run([-10e-9, 20e-9, -40e-9], control="machine",
                                                                   steps_per_segment=750)
    noise = 0.01 * np.max(np.abs(run.F)) * np.random.default_rng(7).standard_normal(len(run))
    z, F = run.z + z0, run.F + F_base + noise
    print("curve made with E* = %.4g Pa, w = %.4g J/m^2, z0 = %.6g m, F_base = %.4g N" % (E, w, z0, F_base))

fits = {
    "paraboloid R = 20 nm": mdr.fit(z, F, "paraboloid", R=R, k_machine=k, approach=True),
    "worn tip (samples)": mdr.fit(z, F, "table", r=r, f=f, k_machine=k, approach=True),
}
for name, res in fits.items():
    print("%-21s E* = %.4g +- %.2g Pa, w = %.4g +- %.2g J/m^2, w_adv = %.4g J/m^2, z0 = %.7g m, "
          "F_base = %.4g N, pull-off %.4g N, mu = %.2f (%s), rms %.2g N, %d iterations" % (
              name, res.E, res.E_err, res.w, res.w_err, res.w_adv, res.z0, res.F_base, res.pull_off_F, res.mu,
              res.regime, res.rms, res.iterations))

try:
    import matplotlib

    matplotlib.use("Agg")
except ImportError:
    sys.exit("(matplotlib not installed: no plot)")
ax = None
for i, (name, res) in enumerate(fits.items()):
    ax = mdr.plot.fit(res, ax=ax, data=i == 0, label="%s: E* = %.3g GPa, w = %.3g mJ/m\u00b2" % (
        name, res.E / 1e9, res.w * 1e3), lw=1.2)
ax.set_title("AFM force curve fitted by mdr.fit (k = %.2g N/m)" % k)
out = sys.argv[1] if len(sys.argv) > 1 else "fit_curve.png"
ax.figure.tight_layout()
ax.figure.savefig(out, dpi=130)
print("plot:", out)
