#!/usr/bin/env python3
"""The library's layering (docs/library.md), enforced: every #include of a
library file, test files included, names a layer at or below its own.
core < work < generate < optimize, analyze < render (which measures its
images with analyze's FLIP) < io < study, temporal < limits (the table of
every limit): each layer may include those its CMake target
links, transitively."""
import pathlib
import re
import sys

root = pathlib.Path(__file__).resolve().parent.parent
below = {
    "core": set(),
    "work": {"core"},
    "generate": {"core", "work"},
    "optimize": {"core", "work", "generate"},
    "analyze": {"core", "generate"},
    "render": {"core", "work", "generate", "analyze"},
    "io": {"core", "work", "generate", "render", "analyze"},
    "study": {"core", "work", "generate", "render", "io", "optimize", "analyze"},
    "temporal": {"core", "work", "generate", "render", "io", "optimize", "analyze"},
    "limits": {"core", "work", "generate", "render", "io", "optimize", "analyze", "study",
               "temporal"},
}
include = re.compile(r'^\s*#\s*include\s*"([^"]+)"', re.M)
problems = []
for path in sorted((root / "src" / "aapat").glob("*/*")):
    if path.suffix not in (".h", ".cpp"):
        continue
    layer = path.parent.name
    for target in include.findall(path.read_text(encoding="utf-8")):
        parts = target.split("/")
        if parts[0] == "aapat" and len(parts) > 2:
            other = parts[1]
            if other != layer and other not in below[layer]:
                problems.append(f"{path.relative_to(root)}: includes {target} ({other} is above "
                                f"{layer})")
        elif parts[0] == "cli":
            problems.append(f"{path.relative_to(root)}: includes {target} (the command line)")
        elif parts[0] == "testing" and not path.stem.endswith("_test"):
            problems.append(f"{path.relative_to(root)}: includes {target} (test helpers)")
for p in problems:
    print(p)
print(f"{0 if problems else 1} passed, {1 if problems else 0} failed")
sys.exit(1 if problems else 0)
