# SPDX-License-Identifier: MIT
"""mdr.Engine: libmdr's real-time spring engine (lib/include/mdr_engine_t.h,
mdr_q31.h) driven along a piecewise-linear path of the controlled variable,
the same way as `mdr cycle` (examples/mdr_cli.c): the same table, the same
tick values, for q31 the same SI <-> raw conversion (examples/mdr_host.h).
The ticks run in C (python/src/mdr_py.c); Python sees whole arrays.
"""
import collections
import warnings

import numpy as np

from ._core import ARITHS, Error, ResolutionWarning, check, control_code, dptr, event_name, f32_shape, ffi, lib, narrow, real_array
from .contact import Contact

#: one event of a run (MDR_EV_*): kind ("contact", "jump-in", "jump",
#: "pull-off", "re-contact", "separation"), the tick it happened at, the last
#: stable state before the jump (a0 [m], d0 [m], F0 [N]) and the state right
#: after it at the same control value (a1, d1, F1), and the jumps in that tick
Event = collections.namedtuple("Event", "kind step a0 d0 F0 a1 d1 F1 jumps")


class Run:
    """The result of Engine.run().

    z, d, F, a: arrays, one value per tick [m, m, N, m] (z = d + F/k_machine,
    or d without a machine; under control="machine" in f32 and f64 the
    control as given, d + F/k_machine to the equilibrium's rounding); event: the MDR_EV_* code of each tick;
    events: list of Event; dissipated: energy dissipated [J] by the cycles
    completed in this run (cycles of them); path, control, steps_per_segment,
    k_machine, arith: what was run."""

    def __init__(self, **kw):
        self.__dict__.update(kw)

    @property
    def pull_off(self):
        """The last pull-off Event of the run, or None."""
        po = [e for e in self.events if e.kind == "pull-off"]
        return po[-1] if po else None

    def __len__(self):
        return len(self.d)

    def __repr__(self):
        return "<mdr.Run %s %s, %d ticks, %d events, dissipated %.6g J>" % (
            self.arith, self.control, len(self.d), len(self.events), self.dissipated)


class Engine:
    """The spring engine of a contact: a table of springs and a contact state
    that remembers its history (attached springs, pull-off, re-contact).

        eng = mdr.Engine(c, springs=1024, w_adv=0.025, k_machine=0.2, arith="f32")
        run = eng.run([0, 50e-9, -200e-9], control="machine", steps_per_segment=1000)

    c: an mdr.Contact (its profile, E* and w; the engine builds its own table
    in its arithmetic). springs: 2 ... 16384 (q31: a power of two).
    w_adv: work of adhesion on approach, 0 <= w_adv <= w [J/m^2] (0:
    non-adhesive loading, w: reversible JKR). k_machine: stiffness of the
    machine between the controlled base z and the contact [N/m], 0 for none
    (then control "machine" is refused). arith: "f64" (default), "f32" (the
    firmware's float engine), "q31" (the fixed-point engine on the f64 table,
    SI values converted in double as `mdr cycle --arith q31`; values beyond
    its documented input range are refused, not saturated).
    a_max: table extent [m]; None: chosen at the first run() as `mdr cycle`
    does (1.25 x the radius where the equilibrium curve reaches the path's
    largest value; q31: doubled, at most 8 times, until the q31 table exists
    and every tick of that run's path fits its ranges), so errors of the table or of the engine's parameters
    appear there (springs out of range, and not a power of two for q31, are
    refused at once: MDR_E_SIZE; a string or bool where a number goes:
    TypeError). A sampled tip: Engine(mdr.Contact("table", r=..., f=...,
    E=..., w=...)) or Engine.from_tip(r, f, E=..., w=...), the same table
    (to the last sample r[-1]; a_max is not taken). A wavy profile's table
    with fewer than 8 springs per wavelength, which does not resolve its
    waves, issues an mdr.ResolutionWarning (when the table is made).
    An Engine holds state: run it from one thread at a time (the C loop
    runs without the GIL); Contacts are read-only and may be shared.
    """

    def __init__(self, contact, *, springs=1024, w_adv=0.0, k_machine=0.0, arith="f64", a_max=None):
        if not isinstance(contact, Contact):
            raise TypeError("Engine(contact): an mdr.Contact (a sampled tip: Engine.from_tip(r, f, ...))")
        self._setup(contact.E, contact.w, springs, w_adv, k_machine, arith)
        if arith == "f32" and contact.profile != "table":
            f32_shape(contact.kind, contact.p, list(contact.params), "Engine(arith='f32')")
        self.contact = contact
        self.tip = None
        self.a_max = None
        if contact.profile == "table":
            if a_max is not None:
                raise TypeError("Engine(Contact('table', ...)): the table extends to the last sample r[-1]; "
                                "a_max is not taken")
            self._init_tip(contact.r, contact.f, "Engine(Contact('table'))")
        elif a_max is not None:
            self._build(narrow(arith, "Engine", a_max=a_max)[0])

    @classmethod
    def from_tip(cls, r, f, *, E, w, springs=1024, w_adv=0.0, k_machine=0.0, arith="f64"):
        """Engine on a sampled gap profile f(r_i) [m] of a measured or worn
        tip at radii r_i [m] (r_0 = 0, strictly increasing, at least
        MDR_TABLE_MIN_POINTS points; f' linear on each interval, the Abel
        transform integrated exactly, the slopes formed in double as `mdr
        cycle --profile table` forms them). The table extends to r[-1].
        E [Pa], w [J/m^2] and the rest as Engine()."""
        self = cls.__new__(cls)
        self._setup(E, w, springs, w_adv, k_machine, arith)
        self.contact = None
        self._init_tip(r, f, "Engine.from_tip")
        return self

    def _init_tip(self, r, f, what):
        r = np.ascontiguousarray(real_array(r, what, "r"))  # (real numbers, none masked: Contact('table'))
        f = np.ascontiguousarray(real_array(f, what, "f"))
        if r.ndim != 1 or r.shape != f.shape or r.size > 65535:
            raise Error(lib.MDR_E_TABLE, "%s: r and f must be 1-D arrays of one length "
                        "<= 65535 (got %s and %s)" % (what, r.shape, f.shape))
        self.tip = (r, f)
        self.a_max = float(r[-1]) if r.size else None
        self._x = ffi.new("mdrpy_engine *")
        nodes = self._alloc()
        st = lib.mdrpy_engine_tip(self._x, self._arith, dptr(r), dptr(f), r.size, self.E, self.w, self.w_adv,
                                  self.k_machine, self.springs, *nodes)
        check(st, "%s(%d points, springs=%d, arith=%r)%s" % (what, r.size, self.springs, self.arith,
                                                               self._q31_tip_hint(st)))
        self._nodes = nodes

    def _q31_tip_hint(self, st):
        """What a sampled tip's q31 MDR_E_OVERFLOW can mean, as `mdr cycle
        --arith q31` names it (helper-64, stop 70: a bare status before): a
        spring too steep for Q3.28 at a rim or kink (the table ends at the
        last sample: fewer springs), or too few springs for the profile's
        curvature."""
        if self.arith != "q31" or st != lib.MDR_E_OVERFLOW:
            return ""
        return (": the q31 table cannot hold the profile (a spring too steep for Q3.28 at a rim or kink: fewer "
                "springs; too few springs for its curvature: more springs; `mdr cycle --arith q31` names which)")

    def _setup(self, E, w, springs, w_adv, k_machine, arith):
        if arith not in ARITHS:
            raise ValueError("Engine: arith must be 'f32', 'f64' or 'q31', not %r" % (arith,))
        if isinstance(springs, bool) or not isinstance(springs, (int, np.integer)):
            raise TypeError("Engine: springs must be an integer, not %r" % (springs,))
        # refused here, not at the first run's table (helper-22, stop 54)
        if not lib.MDR_SPRINGS_MIN <= springs <= lib.MDR_SPRINGS_MAX or (arith == "q31" and springs & (springs - 1)):
            raise Error(lib.MDR_E_SIZE, "Engine: springs = %d (%d ... %d; q31: a power of two)" % (
                springs, lib.MDR_SPRINGS_MIN, lib.MDR_SPRINGS_MAX))
        # numbers only (narrow: a bool or a string was taken, k_machine=True as
        # 1 N/m, E=True as 1 Pa; helper-30, stop 57)
        self.E, self.w, self.w_adv, self.k_machine = narrow(arith, "Engine", E=E, w=w, w_adv=w_adv,
                                                            k_machine=k_machine)
        # the engine init's material and machine checks, here where they are
        # given, not at the first run's table (helper-30, stop 57); q31's
        # init checks them in double
        check(getattr(lib, "mdr_engine_check_f32" if arith == "f32" else "mdr_engine_check_f64")(
            self.E, self.w, self.w_adv, self.k_machine),
            "Engine(E=%.9g, w=%.9g, w_adv=%.9g, k_machine=%.9g, arith=%r)" % (
                self.E, self.w, self.w_adv, self.k_machine, arith))
        self.springs = int(springs)
        self.arith = arith
        self._arith = ARITHS[arith]
        self._x = None

    def _alloc(self):
        # MDR_TABLE_NODES(n): the n + 1 nodes and two of bounds per block
        blk = lib.MDR_TABLE_BLOCK
        n = self.springs + 1 + 2 * ((self.springs + blk - 1) // blk)
        n32 = ffi.new("mdr_node_f32[]", n) if self.arith == "f32" else ffi.NULL
        n64 = ffi.new("mdr_node_f64[]", n) if self.arith != "f32" else ffi.NULL
        nq = ffi.new("mdr_node_q31[]", n) if self.arith == "q31" else ffi.NULL
        return n32, n64, nq

    def _build(self, a_max, path=None):
        c = self.contact
        x = ffi.new("mdrpy_engine *")
        nodes = self._alloc()
        # (an a_max taken from the path says so: run([0, 1e300]) named an
        # a_max = 1e30 the caller never gave; helper-30, stop 57)
        check(lib.mdrpy_engine_profile(x, self._arith, c.kind, list(c.p), self.E, self.w, self.w_adv,
                                       self.k_machine, self.springs, a_max, *nodes),
              "Engine(%r, springs=%d, w_adv=%.9g, k_machine=%.9g, arith=%r, a_max=%.9g%s)" % (
                  c.profile, self.springs, self.w_adv, self.k_machine, self.arith, a_max,
                  "" if path is None else ", chosen from the run's path, whose largest value is %.9g" %
                  float(np.max(path))))
        self._x, self._nodes, self.a_max = x, nodes, a_max
        if c.profile == "wavy":
            spw = c.params["lam"] * self.springs / a_max
            if spw < lib.MDR_WAVY_SPRINGS_PER_WAVELENGTH:
                warnings.warn(ResolutionWarning(
                    "Engine(%r, springs=%d, a_max=%.9g): %.3g springs per wavelength (lam %.9g m): below %g the "
                    "waves are not resolved; more springs or a lower a_max" % (
                        c.profile, self.springs, a_max, spw, c.params["lam"], lib.MDR_WAVY_SPRINGS_PER_WAVELENGTH)),
                    stacklevel=3)

    def _info(self):
        if self._x is None:
            return None
        o = ffi.new("mdrpy_info *")
        lib.mdrpy_engine_info(self._x, o)
        return o

    @property
    def state(self):
        """(a [m], d [m], F [N], in_contact) after the last tick (before any
        run: separated)."""
        o = self._info()
        return (0.0, 0.0, 0.0, False) if o is None else (o.a, o.d, o.F, bool(o.contact))

    @property
    def dissipated(self):
        """Energy dissipated over the cycles completed since the engine was
        built or reset [J]."""
        o = self._info()
        return 0.0 if o is None else o.dissipated

    @property
    def cycles(self):
        """Cycles (approach, then complete separation) completed."""
        o = self._info()
        return 0 if o is None else int(o.cycles)

    @property
    def flags(self):
        """Sticky MDR_FLAG_* bits of the engine."""
        o = self._info()
        return 0 if o is None else int(o.flags)

    @property
    def q31_units(self):
        """q31: the SI units of the Q formats {L, D0, F0, Z0} [m, m, N, m]
        (a: Q1.30 of L; d, F, z: Q2.29 of D0, F0, Z0); None otherwise."""
        o = self._info()
        if o is None or self.arith != "q31":
            return None
        return {"L": o.L, "D0": o.D0, "F0": o.F0, "Z0": o.Z0}

    def __copy__(self):
        # (copy.copy shared the C engine: running the copy moved the original;
        # helper-30, stop 57. deepcopy and pickle refuse too)
        raise TypeError("mdr.Engine holds the C engine's state and cannot be copied; make another with "
                        "mdr.Engine(contact, ...)")

    def reset(self):
        """Back to separated, without history or dissipated energy, on the
        same table."""
        if self._x is not None:
            check(lib.mdrpy_engine_reset(self._x), "Engine.reset")

    def _check_path(self, ctl, path, pp):
        bad = ffi.new("size_t *")
        st = lib.mdrpy_check_path(self._x if self._x is not None else ffi.NULL, ctl, pp, path.size, bad)
        if st != lib.MDR_OK:
            v = float(path[bad[0]])
            hint = ""
            if st == lib.MDR_E_OVERFLOW and self.arith == "q31":
                u = self.q31_units
                unit = u["D0"] if ctl == lib.MDR_CONTROL_GRIPS else u["F0"] if ctl == lib.MDR_CONTROL_LOAD else u["Z0"]
                if abs(v) <= 2 * unit:  # in range: it rounds to 0 LSB (mdr_host_q31_lost, as `mdr cycle`)
                    hint = ("below half a q31 LSB (%.3g) of its unit: it rounds to 0, a cycle the q31 engine never "
                            "makes; use f32 or f64" % (unit / 2**29))
                else:
                    hint = "q31 takes |value| <= 2 units of %(D0).3g m (d), %(F0).3g N (F), %(Z0).3g m (z)" % u
            raise Error(st, "Engine.run: path[%d] = %.9g" % (bad[0], v), index=int(bad[0]), value=v, hint=hint)

    def run(self, path, *, control, steps_per_segment):
        """Drive the engine along the piecewise-linear path of the controlled
        variable: control "grips" (path of d [m]), "load" (F [N]) or
        "machine" (base position z [m], needs k_machine). Tick 0 is path[0],
        then steps_per_segment ticks per segment: 1 + (len(path) - 1) *
        steps_per_segment ticks. The engine keeps its state: a second run
        continues from where the first ended.

        Returns a Run. A refused tick raises mdr.Error with .index the tick,
        .value the control value and .partial the Run of the ticks before it
        (the engine stays as after the last of them)."""
        ctl = control_code(control, "Engine.run")
        path = np.ascontiguousarray(real_array(path, "Engine.run", "path"))
        if path.ndim != 1 or path.size < 2:
            raise Error(lib.MDR_E_PARAM, "Engine.run: path must be a 1-D sequence of 2 or more values")
        steps = steps_per_segment
        if isinstance(steps, bool) or not isinstance(steps, (int, np.integer)) or not 1 <= steps <= 2**31 - 1:
            raise Error(lib.MDR_E_PARAM, "Engine.run: steps_per_segment must be an integer >= 1, not %r" % (steps,))
        steps = int(steps)
        pp = dptr(path)
        if self._x is None:
            self._check_path(ctl, path, pp)  # finite, before the table extent is taken from it
            c = self.contact
            a_max = ffi.new("double *")
            if self.arith == "q31":  # widened until the q31 engine takes this run's path, as `mdr cycle`
                check(lib.mdrpy_extent_q31(c.kind, list(c.p), self.E, self.w, self.w_adv, ctl, self.k_machine,
                                           self.springs, pp, path.size, steps, a_max), "Engine.run: default a_max")
            else:
                check(lib.mdrpy_extent(self._arith, c.kind, list(c.p), self.E, self.w, ctl, self.k_machine, pp,
                                       path.size, a_max), "Engine.run: default a_max")
            self._build(a_max[0], path)
        self._check_path(ctl, path, pp)
        n = 1 + (path.size - 1) * steps
        z, d, F, a = (np.empty(n) for _ in range(4))
        event = np.empty(n, dtype=np.uint8)
        cap = 64
        ev_step = np.empty(cap, dtype=np.uintp)
        ev_code = np.empty((cap, 2), dtype=np.uint8)
        ev_val = np.empty((cap, lib.MDRPY_EV_N))
        ev_n = ffi.new("size_t *", 0)
        done = ffi.new("size_t *")
        before = self._info()
        t0 = 0
        zp, dp, Fp, ap, ep = dptr(z), dptr(d), dptr(F), dptr(a), ffi.from_buffer("uint8_t[]", event)
        while True:
            st = lib.mdrpy_run(self._x, ctl, pp, path.size, steps, t0, n - t0, zp + t0, dp + t0, Fp + t0,
                               ap + t0, ep + t0, cap, ev_n, ffi.from_buffer("size_t[]", ev_step),
                               ffi.from_buffer("uint8_t[]", ev_code), dptr(ev_val), done)
            t0 += done[0]
            if st != lib.MDRPY_MORE:
                break
            cap *= 2  # room for more events, then on from tick t0
            ev_step = np.concatenate([ev_step, np.empty_like(ev_step)])
            ev_code = np.concatenate([ev_code, np.empty_like(ev_code)])
            ev_val = np.concatenate([ev_val, np.empty_like(ev_val)])
        k = ev_n[0]
        cols = [lib.MDRPY_EV_A0, lib.MDRPY_EV_D0, lib.MDRPY_EV_F0, lib.MDRPY_EV_A1, lib.MDRPY_EV_D1, lib.MDRPY_EV_F1]
        events = [Event(event_name(ev_code[i, 0]), int(ev_step[i]), *map(float, ev_val[i, cols]),
                        jumps=int(ev_code[i, 1])) for i in range(k) if ev_step[i] < t0]  # (q31: not the saturated tick's)
        after = self._info()
        result = Run(z=z[:t0], d=d[:t0], F=F[:t0], a=a[:t0], event=event[:t0], events=events,
                     dissipated=after.dissipated - before.dissipated, cycles=after.cycles - before.cycles,
                     path=path, control=control, steps_per_segment=steps, k_machine=self.k_machine,
                     arith=self.arith)
        if st != lib.MDR_OK:
            v = _path_value(path, steps, t0)
            raise Error(st, "Engine.run: tick %d (%s = %.9g)" % (t0, {"grips": "d", "load": "F"}.get(control, "z"), v),
                        index=t0, value=v, partial=result,
                        hint="raise a_max (now %.9g m)" % self.a_max if st == lib.MDR_E_OUTSIDE else
                        _saturated(self.q31_units, control) if st == lib.MDR_E_OVERFLOW and self.arith == "q31"
                        else "")
        return result

    def __repr__(self):
        src = repr(self.contact) if self.contact is not None else "tip of %d points" % self.tip[0].size
        return "<mdr.Engine %s on %s, %d springs, a_max %s, w_adv %.9g, k_machine %.9g>" % (
            self.arith, src, self.springs, "%.9g m" % self.a_max if self.a_max else "(at first run)",
            self.w_adv, self.k_machine)


def _saturated(units, control):
    """The hint of a q31 run's MDR_E_OVERFLOW: an output beyond 2 units, or
    the energy sums (Q15.48 of F0 D0) full after very many cycles; the
    machine's separated d only through a machine (helper-60: a grips run
    whose energy sum filled was told about z)."""
    out = ("d beyond 2 units of %(D0).3g m or F beyond 2 units of %(F0).3g N" % units if control != "machine" else
           "d, F or z beyond 2 units of %(D0).3g m, %(F0).3g N, %(Z0).3g m (a separated machine's d follows z: "
           "end the path nearer the surface)" % units)
    return ("a q31 value saturated: %s, or the energy sums full (Q15.48 of F0 D0, after very many cycles: "
            "reset() empties them); or use f64" % out)


def _path_value(path, steps, t):
    """The control value of tick t (mdr_host_path_value, as the C loop)."""
    seg, j = (0, 0) if t == 0 else divmod(t - 1, steps)
    return lib.mdr_host_path_value(dptr(path), steps, seg, j + (t > 0))
