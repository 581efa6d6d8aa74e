# SPDX-License-Identifier: MIT
"""The extension cannot drift from the library's headers: the package's
declarations compile against them, and each kind of mismatch a changed
header could cause fails the build (here planted in a copy of the
declarations, compiled without the library). The package knows every status
code and every status text of the library, and compiles the library with
the Makefile's flags. Tolerances: none."""
import os
import re
import subprocess
import sys

import pytest

from conftest import ROOT

sys.path.insert(0, os.path.join(ROOT, "python", "mdr"))
import _build  # noqa: E402  (python/mdr/_build.py, as setup.py uses it)

sys.path.pop(0)

def compiles(tmp_path, **planted):
    """Compile the extension module from the package's declarations with
    the planted changes (not linked with the library: only the module's
    compilation against the headers is tested)."""
    ffi = _build.make_ffibuilder(*_build.declarations(**planted))
    try:
        ffi.compile(tmpdir=str(tmp_path), verbose=False)
    except Exception as e:  # cffi.VerificationError, distutils CompileError
        return "%s: %s" % (type(e).__name__, e)
    return None


def test_declarations_compile(tmp_path):
    assert compiles(tmp_path) is None


def decls(old, new):
    text = _build.all_decls()
    assert text.count(old) == 1, "not in the declarations: %s" % old
    return dict(decls=text.replace(old, new))


def field(struct, i, new):
    structs = _build.all_structs()
    structs[struct] = list(structs[struct])
    if i is None:
        structs[struct].append(new)
    else:
        structs[struct][i] = new
    return dict(structs=structs)


def constant(old, new):
    return dict(constants=[new if c == old else c for c in _build.CONSTANTS])


# each mismatch as a change of a header would make it, and the compiler's
# complaint that must stop the build
PTR = "incompatible pointer type"
MISMATCHES = {
    "argument type": (PTR, decls("uint8_t control, double k_m, double a_start,\n                            mdr_critstate_f64",
                                 "uint8_t control, float k_m, double a_start,\n                            mdr_critstate_f64")),
    "argument count": (PTR, decls("mdr_default_start_f32(const mdr_contact_f32 *c, float *a_start)",
                                  "mdr_default_start_f32(const mdr_contact_f32 *c, float *a_start, int more)")),
    "argument constness": (PTR, decls("mdr_status mdrpy_engine_reset(mdrpy_engine *x);",
                                      "mdr_status mdrpy_engine_reset(const mdrpy_engine *x);")),
    "argument signedness": (PTR, decls("const char *mdr_event_str(uint8_t event);",
                                       "const char *mdr_event_str(int8_t event);")),
    "return type": (PTR, decls("const char *mdr_event_str(uint8_t event);",
                               "const signed char *mdr_event_str(uint8_t event);")),
    "missing function": ("undeclared", decls("mdr_status mdrpy_engine_reset(mdrpy_engine *x);",
                                             "mdr_status mdrpy_engine_restart(mdrpy_engine *x);")),
    "the status type": ("conflicting types", decls("typedef int8_t mdr_status;", "typedef int32_t mdr_status;")),
    "field type": (PTR, field("mdr_critstate_f64", 0, ("float", "a"))),
    "field signedness": ("differ in signedness", field("mdr_critstate_f32", 3, ("int16_t", "jumps"))),
    "field width": (PTR, field("mdrpy_info", -1, ("uint16_t", "flags"))),
    "missing field": ("has no member named", field("mdrpy_info", None, ("uint8_t", "sticky"))),
    "missing constant": ("undeclared", constant("MDR_EV_PULL_OFF", "MDR_EV_PULL_AWAY")),
}


@pytest.mark.parametrize("what", list(MISMATCHES))
def test_mismatch_fails_the_build(tmp_path, capfd, what):
    reason, planted = MISMATCHES[what]
    assert compiles(tmp_path, **planted) is not None, "a %s mismatch compiled" % what
    assert reason in capfd.readouterr().err


def test_every_status_is_known():
    """Every MDR_E_* of mdr_types.h is declared to cffi (so mdr.Error names
    it), and its text is the one of lib/src/mdr_status.c."""
    import mdr

    header = read("lib", "include", "mdr_types.h")
    names = set(re.findall(r"^#define (MDR_E_[A-Z_]+) ", header, re.M)) | {"MDR_OK"}
    assert names == set(_build.STATUS_NAMES)
    assert set(mdr._core.STATUS_NAMES.values()) == names
    src = read("lib", "src", "mdr_status.c")
    texts = dict(re.findall(r'case (MDR_[A-Z_]+): return "([^"]*)";', src))
    for name in names:
        assert mdr.status_text(getattr(mdr.lib, name)) == texts[name]
    events = set(re.findall(r"^#define (MDR_EV_[A-Z_]+) ", read("lib", "include", "mdr_engine.h"), re.M))
    assert events == {"MDR_EV_" + e for e in _build.EVENT_NAMES}


def read(*path):
    with open(os.path.join(ROOT, *path)) as f:
        return f.read()


def make_var(makefile_args, var):
    """A variable of the Makefile, as make expands it."""
    out = subprocess.run(["make", "--no-print-directory", "-s", "-C", ROOT] + makefile_args +
                         ["-f", "-", "print-var"], input="print-var:\n\t@echo $(%s)\n" % var,
                         capture_output=True, text=True, check=True)
    return out.stdout.split()


def test_library_flags_are_the_makefiles():
    assert make_var(["-f", "lib/Filelists.mk"], "MDR_REQUIRED_CFLAGS") == _build.LIB_CFLAGS
    assert make_var(["-f", "Makefile"], "WARN") == _build.WARN
    # MDR_ROOT is "." there
    assert sorted(make_var(["-f", "lib/Filelists.mk"], "MDR_SRC_ALL")) == sorted(
        "./" + os.path.relpath(f, ROOT) for f in _build.LIB_SOURCES)
