#!/usr/bin/env python3
"""The number check can fail: a number planted wrong in a copy of the README
(its first marked number, changed in its last digit) makes
check-numbers.py exit 1 naming it, and the README as committed passes.
Usage: test-check-numbers.py AAPAT"""
import pathlib
import re
import subprocess
import sys
import tempfile

aapat = sys.argv[1]
root = pathlib.Path(__file__).resolve().parent.parent
check = root / "scripts" / "check-numbers.py"
readme = (root / "README.md").read_text()
m = re.search(r"(<!-- number: [^>]+ -->)([^<]*?)(\d)(<!-- /number -->)", readme)
if not m:
    sys.exit("test-check-numbers: the README quotes no marked number")
planted_digit = "1" if m.group(3) != "1" else "2"
planted = readme[:m.start()] + m.group(1) + m.group(2) + planted_digit + m.group(4) + readme[m.end():]
with tempfile.TemporaryDirectory() as tmp:
    copy = pathlib.Path(tmp) / "README.md"
    copy.write_text(planted)
    bad = subprocess.run([sys.executable, str(check), aapat, str(copy)], capture_output=True,
                         text=True)
    good = subprocess.run([sys.executable, str(check), aapat, str(root / "README.md")],
                          capture_output=True, text=True)
ok = (bad.returncode == 1 and f"quotes {m.group(2)}{planted_digit}" in bad.stdout
      and good.returncode == 0)
print(f"planted {m.group(2)}{planted_digit} for {m.group(2)}{m.group(3)}: exit {bad.returncode}: "
      f"{bad.stdout.strip()}")
print(f"as committed: exit {good.returncode}: {good.stdout.strip()}")
sys.exit(0 if ok else 1)
