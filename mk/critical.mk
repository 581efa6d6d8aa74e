# SPDX-License-Identifier: MIT
# Issue 16: critical states you can trust everywhere.
#   crit-sweep     mdr_critical against closed forms worked out in long
#                  double (host_tests/crit_sweep.c), f32 and f64; run by
#                  make stress (STRESS=short in make test, STRESS=long dense)
#   test_critical  the cmocka suite of the critical search, sampled profiles
#                  (MDR_PROFILE_TABLE) and their error paths (in TESTS and
#                  SAN_TESTS)
$(B)/host/crit_sweep: host_tests/crit_sweep.c host_tests/fl.h $(B)/host/libmdr.a
	$(HOSTCC) $(TEST_CFLAGS) -O2 $< $(B)/host/libmdr.a -lm -o $@
.PHONY: crit-sweep
crit-sweep: $(B)/host/crit_sweep
	./$(B)/host/crit_sweep $(STRESS)
stress: crit-sweep

# test_critical is built by the suite rules of mk/tests.mk
