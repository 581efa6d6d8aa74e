# SPDX-License-Identifier: MIT
# mk/python.mk: the Python package in python/ (cffi in API mode over the
# library's sources; docs/python.md).
#
#   make python        build the extension in place (python/mdr/); then
#                      PYTHONPATH=python /usr/bin/python3 -c 'import mdr'
#   make python-test   the pytest suite python/tests (in make test); a run
#                      that collects no test fails (pytest's exit status 5)
#   make python-bench  python/bench.py: c.eq over 1e6 radii against a Python
#                      loop of scalar calls, Engine.run against the C step;
#                      the tables go into docs/python.md
#   make python-clean  remove the extension and its build (also by make clean)
#
# Always the system Python (Debian's python3-cffi, -numpy, -pytest,
# -matplotlib, -setuptools, -dev), never a python3 found first on PATH.
PYTHON := /usr/bin/python3

# setup.py rebuilds the extension when a source or header is newer than it
# (python/setup.py, DEPENDS) and says so otherwise
.PHONY: python python-test python-bench python-clean
python:
	cd python && $(PYTHON) setup.py -q build_ext --inplace --build-temp ../$(B)/python --build-lib ../$(B)/python/lib

# (two workers where pytest-xdist is installed, mk/packages.txt: the
# suite's 34 s in 17; each worker's worst errors printed merged, conftest.py)
PYTEST_J := $(if $(shell $(PYTHON) -c 'import xdist' 2>/dev/null && echo yes),-n 2)
python-test: python $(B)/host/mdr
	@cd python && MDR_CLI=$(CURDIR)/$(B)/host/mdr MPLBACKEND=Agg $(PYTHON) -m pytest -q -W error $(PYTEST_J) tests; rc=$$?; \
	  if [ $$rc -eq 5 ]; then echo "python-test: pytest collected no tests"; exit 1; fi; exit $$rc

python-bench: python
	cd python && $(PYTHON) bench.py --readme ../docs/python.md
	@echo "python-bench: docs/python.md's Python figures updated"

python-clean:
	rm -rf python/mdr/_mdr_cffi*.so $(B)/python
clean: python-clean

# lint: the package's C (python/src) like the CLI's, clang-tidy and cppcheck
PY_INC := -Ilib/include -Iport/host -Iexamples -Ipython/src
LINT_CFG_py := -std=c99 $(PY_INC)
$(eval $(call lint_rule,py:python/src/mdr_py.c))
$(call lint_stamp,py:python/src/mdr_py.c): $(wildcard python/src/*.h python/src/*.inc) examples/mdr_host.h examples/mdr_host_t.h examples/tip_csv.h
$(B)/lint/cppcheck-py.stamp: $(wildcard python/src/*.c python/src/*.h python/src/*.inc) .cppcheck-suppressions $(LIB_DEPS) $(wildcard examples/*.h)
	@mkdir -p $(@D)
	$(CPPCHECK) $(PY_INC) python/src/mdr_py.c
	@echo "cppcheck python/src: clean" && touch $@
lint: $(B)/lint/cppcheck-py.stamp $(call lint_stamp,py:python/src/mdr_py.c)
