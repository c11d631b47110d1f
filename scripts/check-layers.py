#!/usr/bin/env python3
"""The library's layering (docs/library.md), enforced: every #include of a
library file, test files included, names a layer at or below its own.
core < work < generate < optimize, analyze < render (which measures its
images with analyze's FLIP) < io < study, temporal < registry (the tables of
every spec and every limit): each layer may include those its CMake target
links, transitively. Inside a layer with rooms (sub-folders), the rooms are
ordered too: temporal's sequence < model < engine < search, each including
only its own room and those before it.

`check-layers.py [ROOT]` checks ROOT/src/aapat (default: this project)."""
import pathlib
import re
import sys

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
    "registry": {"core", "work", "generate", "render", "io", "optimize", "analyze", "study",
                 "temporal"},
}
# The rooms of a layer, lowest first: a file may include its own room and
# the rooms before it.
rooms = {"temporal": ["sequence", "model", "engine", "search"]}
include = re.compile(r'^\s*#\s*include\s*"([^"]+)"', re.M)


def problems_in(root):
    problems = []
    library = root / "src" / "aapat"
    for path in sorted(library.rglob("*")):
        if path.suffix not in (".h", ".cpp"):
            continue
        parts_here = path.relative_to(library).parts
        if len(parts_here) < 2:
            continue
        layer = parts_here[0]
        if layer not in below:
            problems.append(f"{path.relative_to(root)}: {layer} is not a layer of docs/library.md")
            continue
        room = None
        if layer in rooms:
            if len(parts_here) != 3 or parts_here[1] not in rooms[layer]:
                problems.append(f"{path.relative_to(root)}: outside {layer}'s rooms "
                                f"({', '.join(rooms[layer])})")
                continue
            room = parts_here[1]
        for target in include.findall(path.read_text(encoding="utf-8")):
            parts = target.split("/")
            if parts[0] == "aapat" and len(parts) > 2:
                other = parts[1]
                if other != layer and other not in below[layer]:
                    problems.append(f"{path.relative_to(root)}: includes {target} ({other} is "
                                    f"above {layer})")
                elif other == layer and room is not None:
                    order = rooms[layer]
                    there = parts[2] if len(parts) > 3 else None
                    if there not in order:
                        problems.append(f"{path.relative_to(root)}: includes {target} (not in a "
                                        f"room of {layer})")
                    elif order.index(there) > order.index(room):
                        problems.append(f"{path.relative_to(root)}: includes {target} ({layer}'s "
                                        f"{there} is above its {room})")
            elif parts[0] == "cli":
                problems.append(f"{path.relative_to(root)}: includes {target} (the command line)")
            elif parts[0] == "testing" and not path.stem.endswith("_test"):
                problems.append(f"{path.relative_to(root)}: includes {target} (test helpers)")
    return problems


def main():
    root = pathlib.Path(sys.argv[1]) if len(sys.argv) > 1 else \
        pathlib.Path(__file__).resolve().parent.parent
    problems = problems_in(root)
    for p in problems:
        print(p)
    print(f"{0 if problems else 1} passed, {1 if problems else 0} failed")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
