# SPDX-License-Identifier: MIT
"""mdr: adhesive (JKR-type) contact mechanics by the Method of
Dimensionality Reduction, over the C library libmdr (the same code the
firmware runs; cffi in API mode, compiled against the library's headers).

    import mdr
    c = mdr.Contact("paraboloid", E=1e6, w=0.05, R=10e-6)
    c.critical("load").F                 # -1.5 pi w R
    e = c.eq(np.linspace(1e-7, 5e-6, 100))   # e.d, e.F, e.K_I, e.stable_load, ...
    eng = mdr.Engine(c, springs=1024, w_adv=0.025, k_machine=0.2)
    run = eng.run([0, 1e-6, -3e-6], control="machine", steps_per_segment=1000)
    mdr.plot.fd(run)                     # needs matplotlib
    res = mdr.fit(z, F, "paraboloid", R=20e-9, k_machine=0.2)   # res.E, res.w, res.z0, ...

SI units everywhere; compressive force and depth into the surface positive;
w is the work of adhesion. Every refusal of the library raises mdr.Error
(.status, e.g. "MDR_E_RADIUS", and the library's text).
"""
from ._core import Error, ResolutionWarning, event_name, ffi, lib, status_text
from .contact import PROFILES, Contact, Critical, EqState, Profile, State
from .engine import Engine, Event, Run
from .fitting import FitResult, fit

__version__ = "%d.%d" % (lib.MDR_VERSION_MAJOR, lib.MDR_VERSION_MINOR)
__all__ = ["Contact", "Engine", "Error", "ResolutionWarning", "fit", "FitResult", "Run", "Event", "EqState", "State", "Critical", "Profile", "PROFILES",
           "plot", "status_text", "event_name", "ffi", "lib"]  # ffi, lib: the extension itself


def __getattr__(name):
    # mdr.plot imports matplotlib only when it is used
    if name == "plot":
        import importlib

        return importlib.import_module(".plot", __name__)
    raise AttributeError("module 'mdr' has no attribute %r" % (name,))
