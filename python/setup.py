# SPDX-License-Identifier: MIT
"""Build and install the Python package mdr over libmdr (cffi, API mode).

    make python                                   # in place (python/mdr/)
    pip install --no-build-isolation ./python     # from the repository root

Needs the repository around python/ (the library's sources and headers),
a C compiler, and the Debian packages python3-cffi, python3-numpy,
python3-setuptools, python3-dev (see the README, "Python").
"""
import os
import sys

import glob

from setuptools import setup
from setuptools.command.build_ext import build_ext

try:  # setuptools >= 69
    from setuptools.modified import newer_group
except ImportError:
    from setuptools.dep_util import newer_group

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "mdr"))
import _build  # noqa: E402  (python/mdr/_build.py: declarations, sources, flags)

sys.path.pop(0)

if not os.path.isfile(os.path.join(_build.ROOT, "lib", "include", "mdr.h")):
    sys.exit("mdr: build from a libmdr checkout (lib/ not found beside python/ in %s)" % _build.ROOT)


# everything the extension is compiled from (a change rebuilds it)
DEPENDS = sorted(
    _build.LIB_SOURCES
    + _build.HELPER_SOURCES
    + [os.path.join(_build.ROOT, "lib", "src", "mdr_float.inc")]
    + [f for d in _build.INCLUDE_DIRS for f in glob.glob(os.path.join(d, "*.h"))]
    + [f for f in glob.glob(os.path.join(_build.PKG, "src", "*.inc"))]
    + glob.glob(os.path.join(_build.ROOT, "lib", "src", "*.h"))
    + glob.glob(os.path.join(_build.ROOT, "lib", "src", "*", "*.h"))
    + glob.glob(os.path.join(_build.ROOT, "lib", "src", "*", "*.inc"))
    + [os.path.abspath(__file__), os.path.join(_build.HERE, "_build.py")]
)


# the library's symbols stay inside the extension (only PyInit is exported)
HIDDEN = ["-fvisibility=hidden"]


class BuildExt(build_ext):
    """Compiles libmdr's sources with the library's flags (lib/Filelists.mk)
    and the package's C loops with its warning flags, and links them into
    the cffi extension."""

    def build_extension(self, ext):
        ext.depends = list(ext.depends or []) + DEPENDS
        if not self.force and not newer_group(list(ext.sources) + ext.depends,
                                              self.get_ext_fullpath(ext.name), "newer"):
            return super().build_extension(ext)  # up to date: setuptools says so and skips
        tmp = os.path.join(self.build_temp, "mdr-objects")
        inc = _build.INCLUDE_DIRS
        objs = self.compiler.compile(_build.LIB_SOURCES, output_dir=tmp, include_dirs=inc,
                                     extra_postargs=_build.LIB_CFLAGS + _build.WARN + HIDDEN)
        objs += self.compiler.compile(_build.HELPER_SOURCES, output_dir=tmp, include_dirs=inc,
                                      extra_postargs=_build.HELPER_CFLAGS + HIDDEN)
        ext.extra_objects = objs + list(ext.extra_objects or [])
        return super().build_extension(ext)


setup(
    name="mdr",
    version="0.1",
    description="Adhesive (JKR-type) contact mechanics by the Method of Dimensionality Reduction (libmdr)",
    packages=["mdr"],
    python_requires=">=3.7",
    install_requires=["cffi>=1.12", "numpy"],
    extras_require={"plot": ["matplotlib"]},
    cffi_modules=["mdr/_build.py:ffibuilder"],
    cmdclass={"build_ext": BuildExt},
    zip_safe=False,
)
