# SPDX-License-Identifier: MIT
# mk/ref.mk: the GSL reference vectors (make ref-check) and the quadrature
# tables (make tables).
#
.PHONY: ref-check tables
$(B)/host/mdr_refgen: ref/mdr_refgen.c $(REF_SRC) ref/mdr_ref.h
	@mkdir -p $(@D)
	$(HOSTCC) $(TEST_CFLAGS) -O2 $< $(REF_SRC) $(GSL_LIBS) -o $@
$(B)/host/vecdiff: ref/vecdiff.c
	$(HOSTCC) $(TEST_CFLAGS) -O2 $< -lm -o $@

ref-check: $(B)/host/mdr_refgen $(B)/host/vecdiff
	@mkdir -p $(B)/ref
	./$(B)/host/mdr_refgen critical > $(B)/ref/critical.csv & \
	./$(B)/host/mdr_refgen curves > $(B)/ref/curves.csv; wait
	./$(B)/host/vecdiff ref/vectors/critical.csv $(B)/ref/critical.csv
	./$(B)/host/vecdiff ref/vectors/curves.csv $(B)/ref/curves.csv

$(B)/host/gen_tables: ref/gen_tables.c
	@mkdir -p $(@D)
	$(HOSTCC) -O2 $< $(GSL_LIBS) -o $@
tables: $(B)/host/gen_tables
	./$(B)/host/gen_tables > lib/src/math/mdr_tables.h
