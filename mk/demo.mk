# SPDX-License-Identifier: MIT
# mk/demo.mk: make demo-check (in make test) runs make demo into
# $(B)/demo-check and checks what a user gets: both PNGs written by gnuplot,
# and the four states they mark (jump-in and pull-off of each substrate's
# cycle) present in afm_marks.csv.
.PHONY: demo-check
demo-check: $(B)/host/afm_demo $(B)/host/mdr
	@rm -rf $(B)/demo-check
	@$(MAKE) --no-print-directory demo B=$(B) DEMO_DIR=$(B)/demo-check > $(B)/demo-check.log 2>&1 || \
	  { cat $(B)/demo-check.log; echo "demo-check: make demo failed"; exit 1; }
	@for f in afm_fd.png afm_cycle.png; do \
	  head -c 8 $(B)/demo-check/$$f | od -An -c | grep -q 'P   N   G' || \
	    { echo "demo-check: $(B)/demo-check/$$f is not a PNG"; exit 1; }; done
	@for m in PDMS,jump-in PDMS,pull-off polystyrene,jump-in polystyrene,pull-off \
	  "PDMS,fixed-load pull-off" "polystyrene,fixed-load pull-off"; do \
	  grep -q "^$$m," $(B)/demo-check/afm_marks.csv || \
	    { echo "demo-check: no '$$m' in afm_marks.csv"; exit 1; }; done
	@echo "demo-check: make demo wrote afm_fd.png and afm_cycle.png with the jump-in and pull-off marks"
