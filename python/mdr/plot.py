# SPDX-License-Identifier: MIT
"""mdr.plot: force curves of engine runs (needs matplotlib, imported when a
function here is called).

    ax = mdr.plot.fd(run)                  # F-d, nm and nN
    ax = mdr.plot.fd(run, x="z", contact=c)   # F-z with the equilibrium curve
    ax.figure.savefig("cycle.png")
    ax = mdr.plot.fit(mdr.fit(z, F, "paraboloid", R=20e-9, k_machine=0.2))   # data and fitted model
"""
import numpy as np

from .contact import Contact

LENGTH_UNITS = {"m": 1.0, "mm": 1e-3, "um": 1e-6, "nm": 1e-9}
FORCE_UNITS = {"N": 1.0, "mN": 1e-3, "uN": 1e-6, "nN": 1e-9, "pN": 1e-12}
_LABEL = {"um": "\u00b5m", "uN": "\u00b5N"}
JUMPS = ("pull-off", "jump-in", "jump")
# marker and colour of each event kind
_STYLE = {
    "pull-off": ("v", "tab:red"),
    "jump-in": ("^", "tab:green"),
    "jump": ("D", "tab:orange"),
    "contact": ("o", "tab:gray"),
    "re-contact": ("o", "tab:gray"),
    "separation": ("x", "tab:purple"),
}


def _pyplot():
    try:
        import matplotlib.pyplot as plt
    except ImportError as e:  # matplotlib is optional for the rest of mdr
        raise ImportError("mdr.plot needs matplotlib (Debian: apt-get install python3-matplotlib)") from e
    return plt


def fd(run, x=None, ax=None, contact=None, length_unit="nm", force_unit="nN", label=None, events=True,
       **line_kw):
    """Plot the force of an Engine run against the depth d (x="d") or the
    machine's base position z (x="z"; the default for a run with a
    machine, as an AFM records it), in length_unit and force_unit (nm, nN
    by default), with its events marked: the pull-off (the last stable
    state before separation, its force written beside it), jump-in and the
    jumps of a wavy profile, each a dashed line from the state before to the
    state after (the curve itself is broken there). In an F-d plot of a run
    with a machine the separated body's d follows z far away: the view is
    limited to the ticks in contact.

    contact: an mdr.Contact whose equilibrium curve F(d) (x="d") or z(F)
    (x="z", z = d + F/k_machine) is drawn for comparison, over the radii
    the run reached. ax: matplotlib Axes to draw into (default: a new
    figure). line_kw: passed to the curve's plot(). Returns the Axes.
    """
    if x is None:
        x = "z" if run.k_machine > 0 else "d"
    if x not in ("d", "z"):
        raise ValueError("fd: x is 'd' or 'z', not %r" % (x,))
    lu, fu = LENGTH_UNITS[length_unit], FORCE_UNITS[force_unit]
    plt = _pyplot()
    if ax is None:
        ax = plt.figure(figsize=(7, 4.5)).add_subplot()
    k = run.k_machine

    def xof(d, F):
        d, F = np.asarray(d), np.asarray(F)
        return (d + F / k if x == "z" and k > 0 else d) / lu

    if contact is not None:
        if not isinstance(contact, Contact):
            raise TypeError("fd: contact must be an mdr.Contact")
        amax = float(np.max(run.a)) if len(run.a) else 0.0
        if amax > 0:
            e = contact.eq(np.linspace(amax * 1e-3, amax, 400))
            ax.plot(xof(e.d, e.F), e.F / fu, color="0.6", lw=1, ls=":", label="equilibrium (%s)" % contact.profile)
    xs, Fs = (run.z if x == "z" else run.d) / lu, run.F / fu
    # break the curve where it jumps (the dashed event lines show the jumps)
    brk = np.flatnonzero(np.isin([ev.kind for ev in run.events], JUMPS))
    at = np.array([run.events[i].step for i in brk], dtype=int)
    at = at[at > 0]
    ax.plot(np.insert(xs, at, np.nan), np.insert(Fs, at, np.nan), label=label or "%s, %s" % (run.arith, run.control),
            **line_kw)
    if x == "d" and k > 0 and np.any(run.a > 0):
        inside = xs[run.a > 0]
        lo, hi = float(np.min(inside)), float(np.max(inside))
        ax.set_xlim(lo - 0.25 * (hi - lo), hi + 0.1 * (hi - lo))
    if events:
        seen = set(ax.get_legend_handles_labels()[1])  # each kind once in the legend
        for ev in run.events:
            marker, colour = _STYLE.get(ev.kind, ("s", "k"))
            x0, x1 = xof(ev.d0, ev.F0), xof(ev.d1, ev.F1)
            if ev.kind in JUMPS:
                ax.plot([x0, x1], [ev.F0 / fu, ev.F1 / fu], ls="--", lw=0.8, color=colour)
            ax.plot([x0], [ev.F0 / fu], marker=marker, color=colour, ls="none", ms=7,
                    label=ev.kind if ev.kind not in seen else None)
            seen.add(ev.kind)
            if ev.kind == "pull-off":
                ax.annotate("pull-off\n%.4g %s" % (ev.F0 / fu, _LABEL.get(force_unit, force_unit)),
                            (x0, ev.F0 / fu), textcoords="offset points", xytext=(8, 2), va="center", fontsize=8,
                            color=colour)
    ax.axhline(0, color="0.8", lw=0.6, zorder=0)
    ax.set_xlabel("%s [%s]" % ("base position z" if x == "z" else "indentation d", _LABEL.get(length_unit, length_unit)))
    ax.set_ylabel("force F [%s]" % _LABEL.get(force_unit, force_unit))
    ax.legend(fontsize=8, loc="best")
    return ax


def fit(res, ax=None, length_unit="nm", force_unit="nN", label=None, data=True, **line_kw):
    """Plot a force curve and the model fitted to it (an mdr.fit result):
    the samples F(z) as dots, the model (FitResult.model(): approach and
    retract branches) as a line, the model's pull-off marked with its force
    (relative to the baseline F_base, as FitResult.pull_off_F).

    ax: matplotlib Axes (default: a new figure); data: also draw the
    samples (False to overlay a second fit on the same data); label: the
    model's legend entry (default: its E*, w); line_kw: passed to the
    model's plot(). Returns the Axes."""
    lu, fu = LENGTH_UNITS[length_unit], FORCE_UNITS[force_unit]
    plt = _pyplot()
    if ax is None:
        ax = plt.figure(figsize=(7, 4.5)).add_subplot()
    Fm, top = res.model()
    if data:
        ax.plot(res.z / lu, res.F / fu, ".", ms=2, color="0.6", label="data (%d points)" % res.z.size)
    if label is None:
        label = "fit (%s): E* = %.4g GPa, w = %.4g mJ/m\u00b2" % (res.contact.profile, res.E / 1e9, res.w * 1e3)
    # the model jumps in on the approach and off at its fold on the retract:
    # the line broken at each branch's largest step
    zs, Fs = [], []
    for lo, hi in ((0, top), (top, res.z.size)):
        zb, Fb = res.z[lo:hi], Fm[lo:hi]
        j = int(np.argmax(np.abs(np.diff(Fb)))) + 1 if Fb.size > 1 else 0
        zs += [zb[:j], [np.nan], zb[j:], [np.nan]]
        Fs += [Fb[:j], [np.nan], Fb[j:], [np.nan]]
    zs, Fs = np.concatenate(zs), np.concatenate(Fs)
    line_kw.setdefault("zorder", 3)  # over the data
    line = ax.plot(zs / lu, Fs / fu, label=label, **line_kw)[0]

    def base(zz):  # the fitted baseline
        return res.F_base + res.F_slope * (zz - res.z0)

    F0 = (res.pull_off_F + base(res.pull_off_z)) / fu
    ax.plot([res.pull_off_z / lu], [F0], "v", color=line.get_color(), ms=7)
    ax.annotate("pull-off %.4g %s" % (res.pull_off_F / fu, _LABEL.get(force_unit, force_unit)),
                (res.pull_off_z / lu, F0), textcoords="offset points", xytext=(8, -4), va="center", fontsize=8,
                color=line.get_color())
    zb = np.array([res.z.min(), res.z.max()])
    ax.plot(zb / lu, base(zb) / fu, color="0.8", lw=0.6, zorder=0)
    ax.set_xlabel("base position z [%s]" % _LABEL.get(length_unit, length_unit))
    ax.set_ylabel("force F [%s]" % _LABEL.get(force_unit, force_unit))
    ax.legend(fontsize=8, loc="best")
    return ax
