#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""fit_pinned_matrix.py: the fit of noisy retracts with a pinned top, the
figures of docs/fitting.md ("Adhesion hysteresis"). Engine cycles (`mdr
cycle`, paraboloid R 20 nm, E* 1 GPa, w 0.05, machine control, path -10 ->
20 -> -40 nm, 1000 steps per segment, 1024 springs, f64), Gaussian noise of
0, 0.1 %, 1 % and 3 % of the pull-off force on F (8 copies, seed 1), each
fitted with `mdr fit` (the retract alone, and with --approach: rows
"+approach"); per row the status or E*/E and, in parentheses, its distance
from the truth in reported standard errors, with --approach also the
fitted w_adv and its error (noise-free rows: the relative errors of E* and
w).
Usage: python3 host_tests/fit_pinned_matrix.py [build/host/mdr]  (~3 s)"""
import json
import os
import random
import subprocess
import sys
import tempfile

MDR = sys.argv[1] if len(sys.argv) > 1 else "build/host/mdr"


def cycle(wadv, km):
    out = subprocess.run([MDR, "cycle", "--profile", "paraboloid", "--R", "20e-9", "--E", "1e9", "--w", "0.05",
                          "--w-adv", str(wadv), "--control", "machine", "--k-machine", str(km), "--path",
                          "-1e-8,2e-8,-4e-8", "--steps-per-segment", "1000", "--springs", "1024", "--arith", "f64"],
                         capture_output=True, text=True, check=True).stdout
    rows = [line.split(",") for line in out.splitlines()[1:] if line[:1].isdigit()]
    return [float(r[1]) for r in rows], [float(r[3]) for r in rows]


def fit(path, z, F, km, exact=False, extra=()):
    with open(path, "w") as f:
        f.write("z,F\n")
        for a, b in zip(z, F):
            f.write("%r,%r\n" % (a, b))
    r = json.loads(subprocess.run([MDR, "fit", "--curve", path, "--profile", "paraboloid", "--R", "20e-9",
                                   "--k-machine", str(km)] + list(extra), capture_output=True, text=True).stdout)
    if r["status"] != "ok":
        return r["status"].replace("MDR_E_", "")
    if exact:  # noise-free: the relative errors of E* and w
        return "E*/E-1 %.1e w/w-1 %.1e" % (r["E"] / 1e9 - 1, r["w"] / 0.05 - 1)
    if "--approach" in extra:  # and the approach's w_adv with its error
        return "%.2f(%.1f;w_adv %.4f+-%.4f)" % (r["E"] / 1e9, (r["E"] - 1e9) / r["E_err"], r["w_adv"],
                                               r["w_adv_err"])
    return "%.2f(%.1f)" % (r["E"] / 1e9, (r["E"] - 1e9) / r["E_err"])


def main():
    random.seed(1)
    with tempfile.TemporaryDirectory() as d:
        path = os.path.join(d, "c.csv")
        for wadv in (0.0, 0.025, 0.05):
            for km in (0.2, 2.0):
                z, F = cycle(wadv, km)
                fpo = abs(min(F))
                for rel in (0.0, 0.001, 0.01, 0.03):
                    copies = [[f + rel * fpo * random.gauss(0, 1) for f in F] for _ in range(1 if rel == 0 else 8)]
                    for extra in ((), ("--approach",)):
                        res = [fit(path, z, Fn, km, rel == 0, extra) for Fn in copies]
                        print("w_adv %.3f k_m %.1f noise %5.1f %%%s: %s" % (wadv, km, 100 * rel,
                                                                       " +approach" if extra else "", " ".join(res)),
                              flush=True)


if __name__ == "__main__":
    main()
