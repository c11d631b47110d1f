#!/usr/bin/env python3
"""Tests beside their concept (docs/library.md, "Tests beside their concept"):
every library source src/aapat/.../x.cpp has x_test.cpp beside it, or is
listed with its reason in docs/library.md's table between the markers; and a
listed source exists and has no test file of its name (else the row is
stale)."""
import pathlib
import re
import sys

root = pathlib.Path(__file__).resolve().parent.parent
library = root / "src" / "aapat"
doc = (root / "docs" / "library.md").read_text(encoding="utf-8")
begin, end = "<!-- sources-without-a-test-file: begin -->", "<!-- sources-without-a-test-file: end -->"
if begin not in doc or end not in doc:
    print("docs/library.md: the table of sources without a test file is missing its markers")
    print("0 passed, 1 failed")
    sys.exit(1)
table = doc[doc.index(begin):doc.index(end)]
listed = set()
for row in table.splitlines():
    if row.startswith("| `"):
        first_cell = row.split(" | ")[0]
        listed.update(re.findall(r"`([^`]+\.cpp)`", first_cell))
problems = []
sources = sorted(p for p in library.rglob("*.cpp") if not p.name.endswith("_test.cpp"))
for source in sources:
    rel = source.relative_to(library).as_posix()
    has_test = source.with_name(source.stem + "_test.cpp").exists()
    if not has_test and rel not in listed:
        problems.append(f"src/aapat/{rel}: no {source.stem}_test.cpp beside it and no row in "
                        "docs/library.md saying where it is tested")
    if has_test and rel in listed:
        problems.append(f"src/aapat/{rel}: has {source.stem}_test.cpp, but docs/library.md still "
                        "lists it as without one")
for rel in sorted(listed):
    if not (library / rel).exists():
        problems.append(f"docs/library.md lists src/aapat/{rel}, which does not exist")
for p in problems:
    print(p)
print(f"{0 if problems else 1} passed, {1 if problems else 0} failed")
sys.exit(1 if problems else 0)
