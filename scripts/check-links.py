#!/usr/bin/env python3
"""Every relative link in README.md and docs/*.md, and every project path that
`aapat list` cites (docs/..., data/...), exists inside the repository; no
document points outside it (../). Usage: check-links.py AAPAT_BINARY."""
import pathlib
import re
import subprocess
import sys

root = pathlib.Path(__file__).resolve().parent.parent
link = re.compile(r"!?\[[^\]]*\]\(([^)\s]+)\)")
cited = re.compile(r"\b((?:docs|data|scripts|examples|python)/[\w./-]*\w)")
problems = []

for doc in [root / "README.md", *sorted((root / "docs").glob("*.md"))]:
    text = doc.read_text(encoding="utf-8")
    for target in link.findall(text):
        if re.match(r"^[a-z]+:", target) or target.startswith("#"):
            continue
        path = target.split("#")[0]
        resolved = (doc.parent / path).resolve()
        if not resolved.is_relative_to(root):
            problems.append(f"{doc.relative_to(root)}: link {target} leaves the repository")
        elif not resolved.exists():
            problems.append(f"{doc.relative_to(root)}: link {target} does not exist")
    for target in re.findall(r"\.\./shared/[\w./-]+", text):
        problems.append(f"{doc.relative_to(root)}: {target} is outside the repository")

if len(sys.argv) > 1:
    listing = subprocess.run([sys.argv[1], "list"], check=True, capture_output=True,
                             text=True).stdout
    for target in sorted(set(cited.findall(listing))):
        if not (root / target).exists():
            problems.append(f"aapat list: cites {target}, which does not exist")

for p in problems:
    print(p)
print(f"{0 if problems else 1} passed, {1 if problems else 0} failed")
sys.exit(1 if problems else 0)
