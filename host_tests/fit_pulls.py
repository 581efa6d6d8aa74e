# SPDX-License-Identifier: MIT
"""fit_pulls.py: how well the fit's reported errors hold over noise draws,
on the scene of docs/fitting.md's plot (paraboloid R = 20 nm, E* = 1 GPa,
w = w_adv = 0.05 J/m^2, a 0.2 N/m lever, the spring engine's curve, noise
of 0.1 nN: 2 % of the pull-off force), with short and long free paths and
the baseline's slope fitted or held (flat_baseline). Per row: the statuses
over the draws and, over the answers, the mean, rms and largest |deviation|
of E* and w from the truth in reported errors (an honest error: mean 0,
rms 1). A scratch measurement for docs/fitting.md, not a test.

    PYTHONPATH=python /usr/bin/python3 host_tests/fit_pulls.py [DRAWS]
"""
import sys

import numpy as np

import mdr


def row(path, steps, flat, draws):
    c = mdr.Contact("paraboloid", E=1e9, w=0.05, R=20e-9)
    run = mdr.Engine(c, springs=1024, w_adv=0.05, k_machine=0.2).run(path, control="machine",
                                                                     steps_per_segment=steps)
    pe, pw, st = [], [], {}
    for seed in range(draws):
        F = run.F + 3e-10 + 1e-10 * np.random.default_rng(seed).standard_normal(len(run.F))
        try:
            r = mdr.fit(run.z + 2e-6, F, "paraboloid", R=20e-9, k_machine=0.2, approach=True, flat_baseline=flat)
        except mdr.Error as e:
            name = mdr.status_name(e.status) if hasattr(mdr, "status_name") else str(e.status)
            st[name] = st.get(name, 0) + 1
            continue
        st["ok"] = st.get("ok", 0) + 1
        pe.append((r.E - 1e9) / r.E_err)
        pw.append((r.w - 0.05) / r.w_err)
    pe, pw = np.array(pe), np.array(pw)
    free = -path[0] if path[0] < 0 else 0
    print("free path of the approach %2.0f nm, %s: %s; E* mean %+.2f rms %.2f max %.2f; w mean %+.2f rms %.2f max "
          "%.2f" % (free * 1e9, "flat_baseline" if flat else "slope fitted ", st, pe.mean(),
                    np.sqrt((pe ** 2).mean()), np.abs(pe).max(), pw.mean(), np.sqrt((pw ** 2).mean()),
                    np.abs(pw).max()))


def main(argv):
    draws = int(argv[0]) if argv else 60
    for path, steps in (([-1e-8, 2e-8, -3.5e-8], 750), ([-6e-8, 2e-8, -6e-8], 2000)):
        for flat in (False, True):
            row(path, steps, flat, draws)


if __name__ == "__main__":
    main(sys.argv[1:])
