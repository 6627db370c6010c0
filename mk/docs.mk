# mk/docs.mk - the documentation's links (included by the Makefile).
#   make check-links   every relative link and image of README.md and docs/*.md
#                      names an existing file, and every #anchor a heading of its
#                      page (scripts/check_links.py, python3 alone; part of
#                      make check and make check-quick)
.PHONY: check-links

check-links:
	@python3 scripts/check_links.py

check: check-links
check-quick: check-links
