# SPDX-License-Identifier: MIT
# mk/install.mk: installing libmdr on a host, and the checks that a project
# can use it (in make test, seconds each).
#
#   make install PREFIX=/usr/local [DESTDIR=]  headers in PREFIX/include/mdr,
#                  libmdr.a, libmdr.so (soname libmdr.so.0), pkgconfig/mdr.pc
#                  and the CMake package (cmake/mdr: find_package(mdr), the
#                  target mdr::mdr on libmdr.a) in PREFIX/lib
#   make install-check  install into build/, then compile, link and run
#                  examples/cmake-consumer/main.c with
#                  `pkg-config --cflags --libs mdr`, and the consumer project
#                  with find_package(mdr) on that prefix
#   make cmake-check    examples/cmake-consumer with CMake: add_subdirectory
#                  and find_package (after cmake --install) on the host, and
#                  cross-compiled for the Cortex-M4F (cmake/arm-none-eabi.cmake)
#                  and run on QEMU; libmdr's objects free of double helpers
#   make errno-check    building lib/ without -fno-math-errno stops with the
#                  #error of lib/src/mdr_hooks.h (host, Cortex-M4F, RV32IMAFC)
PREFIX ?= /usr/local
DESTDIR ?=
MDR_VERSION := 0.1.0
MDR_SOVERSION := 0
.PHONY: install install-check cmake-check errno-check

$(B)/pic/%.o: lib/src/%.c $(LIB_DEPS)
	@mkdir -p $(@D)
	$(HOSTCC) $(MDR_CFLAGS) $(CFLAGS) -fPIC -c $< -o $@
$(B)/host/libmdr.so: $(addprefix $(B)/pic/,mdr_f32.o mdr_f64.o mdr_q31.o mdr_status.o)
	$(HOSTCC) -shared -Wl,-soname,libmdr.so.$(MDR_SOVERSION) $^ -o $@

install: $(B)/host/libmdr.a $(B)/host/libmdr.so
	install -d $(DESTDIR)$(PREFIX)/include/mdr $(DESTDIR)$(PREFIX)/lib/pkgconfig $(DESTDIR)$(PREFIX)/lib/cmake/mdr
	install -m 644 lib/include/*.h $(DESTDIR)$(PREFIX)/include/mdr/
	install -m 644 $(B)/host/libmdr.a $(DESTDIR)$(PREFIX)/lib/
	install -m 755 $(B)/host/libmdr.so $(DESTDIR)$(PREFIX)/lib/libmdr.so.$(MDR_VERSION)
	ln -sf libmdr.so.$(MDR_VERSION) $(DESTDIR)$(PREFIX)/lib/libmdr.so.$(MDR_SOVERSION)
	ln -sf libmdr.so.$(MDR_SOVERSION) $(DESTDIR)$(PREFIX)/lib/libmdr.so
	sed -e 's|@MDR_PC_PREFIX@|$(PREFIX)|; s|@MDR_PC_LIBDIR@|$${exec_prefix}/lib|; s|@PROJECT_VERSION@|$(MDR_VERSION)|; s|@MDR_PC_DEFS@||' \
	  mk/mdr.pc.in > $(DESTDIR)$(PREFIX)/lib/pkgconfig/mdr.pc
	install -m 644 cmake/mdrConfig.cmake $(DESTDIR)$(PREFIX)/lib/cmake/mdr/
	install -m 644 mk/mdrTargets-make.cmake $(DESTDIR)$(PREFIX)/lib/cmake/mdr/mdrTargets.cmake
	sed -e 's|@MDR_VERSION@|$(MDR_VERSION)|' mk/mdrConfigVersion.cmake.in > $(DESTDIR)$(PREFIX)/lib/cmake/mdr/mdrConfigVersion.cmake

install-check:
	@rm -rf $(B)/install-check && mkdir -p $(B)
	@$(MAKE) --no-print-directory install PREFIX=$(CURDIR)/$(B)/install-check/prefix > $(B)/install-check.log 2>&1 || \
	  { cat $(B)/install-check.log; exit 1; }
	@sh mk/install_check.sh $(CURDIR)/$(B)/install-check "$(HOSTCC)"

cmake-check:
	@sh mk/cmake_check.sh $(CURDIR)/$(B)/cmake-check

errno-check:
	@mkdir -p $(B)
	@set -e; for c in "gcc:host:" "clang:host:" "$(MDR_CM_PREFIX)gcc:cortex-m:$(MDR_CM_FLAGS_m4f)" \
	  "$(MDR_RV_PREFIX)gcc:riscv:$(MDR_RV_FLAGS_rv32imafc)"; do \
	  cc=$${c%%:*}; r=$${c#*:}; port=$${r%%:*}; fl=$${r#*:}; \
	  if $$cc $$fl -std=c99 -ffreestanding -Ilib/include -Iport/$$port -c lib/src/mdr_f32.c -o /dev/null 2> $(B)/errno.log; then \
	    echo "errno-check: $$cc (port/$$port) built lib/ without -fno-math-errno"; exit 1; fi; \
	  grep -q 'needs -fno-math-errno' $(B)/errno.log || { cat $(B)/errno.log; exit 1; }; done; \
	  echo "errno-check: without -fno-math-errno the builtin-sqrt ports stop with the #error (gcc, clang, Cortex-M4F, RV32IMAFC)"
