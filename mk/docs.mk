# SPDX-License-Identifier: MIT
# mk/docs.mk: the API reference and the checks that keep the sources tidy.
#
#   make headers        write lib/include/*_f32.h, *_f64.h from the templates
#                       lib/include/*_t.h (mk/gen_headers.py; commit them)
#   make headers-check  fail if a generated header is stale (in make test)
#   make docs           Doxygen (Doxyfile) -> build/docs/html; every warning
#                       is an error (in make test)
#   make spdx-check     every source file has its SPDX line (mk/spdx.sh; in
#                       make test)
.PHONY: headers headers-check docs spdx-check
headers:
	/usr/bin/python3 mk/gen_headers.py
headers-check:
	@/usr/bin/python3 mk/gen_headers.py --check
docs: headers-check
	@mkdir -p $(B)/docs
	@doxygen Doxyfile || { cat $(B)/docs/warnings.log; echo "docs: Doxygen warnings (above) are errors"; exit 1; }
	@echo "docs: $(B)/docs/html/index.html, no Doxygen warning"
spdx-check:
	@sh mk/spdx.sh
