#!/usr/bin/env python3
"""check-layers.py fails on a back edge: a tree with one planted include that
reaches up (a layer, and a room of temporal) is refused with a line naming it,
and the same tree without it passes."""
import pathlib
import subprocess
import sys
import tempfile

check = pathlib.Path(__file__).resolve().parent / "check-layers.py"


def run(files):
    with tempfile.TemporaryDirectory() as d:
        root = pathlib.Path(d)
        for name, text in files.items():
            path = root / "src" / "aapat" / name
            path.parent.mkdir(parents=True, exist_ok=True)
            path.write_text(text, encoding="utf-8")
        r = subprocess.run([sys.executable, str(check), str(root)], capture_output=True, text=True)
        return r.returncode, r.stdout


clean = {
    "core/a.h": "#pragma once\n",
    "io/b.h": '#include "aapat/core/a.h"\n',
    "temporal/sequence/s.h": '#include "aapat/core/a.h"\n',
    "temporal/model/m.h": '#include "aapat/temporal/sequence/s.h"\n',
    "temporal/engine/e.h": '#include "aapat/temporal/model/m.h"\n',
    "temporal/search/x.h": '#include "aapat/temporal/engine/e.h"\n',
}
cases = {
    "a room below includes a room above": (
        {"temporal/model/m.cpp": '#include "aapat/temporal/engine/e.h"\n'},
        "temporal's engine is above its model"),
    "the lowest room includes the highest": (
        {"temporal/sequence/s.cpp": '#include "aapat/temporal/search/x.h"\n'},
        "temporal's search is above its sequence"),
    "a layer includes one above it": (
        {"core/a.cpp": '#include "aapat/io/b.h"\n'}, "io is above core"),
    "a file of temporal outside its rooms": (
        {"temporal/loose.h": "#pragma once\n"}, "outside temporal's rooms"),
}
failures = 0
code, out = run(clean)
if code != 0:
    print(f"FAIL the clean tree: exit {code}\n{out}")
    failures += 1
for what, (planted, message) in cases.items():
    code, out = run({**clean, **planted})
    if code != 1 or message not in out:
        print(f"FAIL {what}: exit {code}, expected 1 and '{message}'\n{out}")
        failures += 1
print(f"{1 + len(cases) - failures} passed, {failures} failed")
sys.exit(1 if failures else 0)
