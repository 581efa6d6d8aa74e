#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""Pull-off of a worn AFM tip, from its sampled profile, through the spring
engine: an approach-retract cycle of a cantilever, plotted.

A silicon-nitride tip of radius R = 20 nm worn flat at the apex (a flat of
radius b = 6 nm, as a tip-reconstruction image would show it) on a polymer
(E* = 1 GPa, work of adhesion w = 0.05 J/m^2), a 0.2 N/m cantilever. The
worn tip is given as samples f(r_i) only: mdr.Engine.from_tip builds its
spring table (the Abel transform of the samples) and the engine runs the
cycle as the firmware would. The fresh tip's pull-off comes from the closed
forms (mdr.Contact.critical) and from the same engine, for comparison.

    make python
    PYTHONPATH=python /usr/bin/python3 examples/afm_worn_tip.py [out.png]

Copy it and put in your tip's samples, material and cantilever.
"""
import sys

import numpy as np

import mdr

R, b = 20e-9, 6e-9            # tip radius, radius of the worn flat [m]
E, w = 1e9, 0.05              # effective modulus [Pa], work of adhesion [J/m^2]
k = 0.2                       # cantilever stiffness [N/m]
path = [-5e-9, 2e-9, -120e-9]  # base position z: approach to +2 nm, retract [m]
steps = 2000                  # ticks per segment

# the worn tip, sampled every 0.15 nm out to 18 nm: flat for r < b, then the sphere
r = np.linspace(0.0, 18e-9, 121)
f = np.where(r < b, 0.0, np.sqrt(R**2 - b**2) - np.sqrt(R**2 - r**2))

fresh = mdr.Contact("sphere", E=E, w=w, R=R)
worn = mdr.Engine.from_tip(r, f, E=E, w=w, springs=1024, w_adv=w, k_machine=k)
runs = {
    "fresh tip": mdr.Engine(fresh, springs=1024, w_adv=w, k_machine=k).run(path, control="machine",
                                                                           steps_per_segment=steps),
    "worn tip (sampled)": worn.run(path, control="machine", steps_per_segment=steps),
}

print("pull-off through a %.2g N/m cantilever:" % k)
crit = fresh.critical("machine", k_machine=k)
print("  fresh tip, closed form (mdr_critical)   F = %7.3f nN  at d = %6.3f nm" % (crit.F * 1e9, crit.d * 1e9))
for name, run in runs.items():
    po = run.pull_off
    print("  %-38s F = %7.3f nN  at z = %6.2f nm, contact radius %.2f nm" % (
        name + ", spring engine", po.F0 * 1e9, (po.d0 + po.F0 / k) * 1e9, po.a0 * 1e9))
flat = mdr.Contact("flattip", E=E, w=w, R=R, b=b).critical("machine", k_machine=k)
print("  paraboloid with a %.0f nm flat, closed form F = %7.3f nN" % (b * 1e9, flat.F * 1e9))
print("  JKR estimate -1.5 pi w R                F = %7.3f nN" % (-1.5 * np.pi * w * R * 1e9))
print("energy dissipated in the cycle: fresh %.3g aJ, worn %.3g aJ" % tuple(
    run.dissipated * 1e18 for run in runs.values()))

try:
    import matplotlib

    matplotlib.use("Agg")
except ImportError:
    sys.exit("matplotlib is not installed: no plot (Debian: apt-get install python3-matplotlib)")
ax = None
for name, run in runs.items():
    ax = mdr.plot.fd(run, x="z", ax=ax, label=name)
ax.set_title("approach-retract, R = %.0f nm, E* = %.0f GPa, w = %.2f J/m$^2$, k = %.1f N/m"
             % (R * 1e9, E * 1e-9, w, k), fontsize=9)
out = sys.argv[1] if len(sys.argv) > 1 else "afm_worn_tip.png"
ax.figure.savefig(out, dpi=110)
print("plot: %s" % out)
