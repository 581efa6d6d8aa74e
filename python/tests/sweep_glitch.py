# SPDX-License-Identifier: MIT
"""The figures of docs/fitting.md's "A glitch in a pinned top" (stop 77):
helper-80's noisy curve with a pinned top (seeds 342, 1, 2), one sample of
the retract's first 200 (every 4th) moved by -0.3, -0.14, -0.05 and +0.14
pull-off forces: the fits answered, refused, and the answers beyond 5
reported errors (and where their glitch lay). Not a test (about 20 s):
    PYTHONPATH=python /usr/bin/python3 python/tests/sweep_glitch.py
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import jkr_curves  # noqa: E402
import mdr  # noqa: E402
from test_fit import H80_GLITCH as CURVE  # noqa: E402  (the curve of test_pinned_glitch)


def main():
    R, E, w, _, k = CURVE[:5]
    answered = refused = 0
    off = []
    for seed in (342, 1, 2):
        z, F0, Fc = jkr_curves.curve(*CURVE, seed=seed)
        top = F0.size // 2
        for pos in range(top, top + 200, 4):
            for size in (0.05, 0.14, 0.3, -0.14):
                F = F0.copy()
                F[pos] -= size * abs(Fc)
                try:
                    r = mdr.fit(z, F, "paraboloid", R=R, k_machine=k)
                except mdr.Error:
                    refused += 1
                    continue
                answered += 1
                dev = max(abs(r.E - E) / r.E_err, abs(r.w - w) / r.w_err)
                if dev > 5:
                    off.append((seed, pos - top, -size, dev, r.n_pinned))
    print(f"{answered} answered, {refused} refused, {len(off)} beyond 5 reported errors")
    for seed, pos, size, dev, npin in off[:20]:
        print(f"  seed {seed}: glitch of {size:+.2f} pull-off forces at the retract's sample {pos}: "
              f"{dev:.1f} errors off, n_pinned {npin}")


if __name__ == "__main__":
    main()
