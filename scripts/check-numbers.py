#!/usr/bin/env python3
"""Every number the README and docs/ quote in prose through a marker is the
number the command prints today:

    <!-- number: eval rgss --objective laine-aila --json | rows.0.e2 | .4f -->0.4390<!-- /number -->

runs `aapat eval rgss --objective laine-aila --json`, takes rows[0].e2,
formats it with Python's format spec .4f and compares it with the text
between the markers (each command runs once, however often it is quoted).
A command's whole output shown in a code block is checked the same way:

    <!-- output: export flipquad --snap --api d3d12-tier2 -->
    ```hlsl
    ...exactly what the command prints...
    ```
    <!-- /output -->

Usage: check-numbers.py AAPAT [--write] [FILE...] (default: README.md and
docs/**/*.md). Exits 1 naming every number or output that differs, with the
command; --write rewrites the outputs (not the numbers, which prose
surrounds) to what the commands print."""
import json
import pathlib
import re
import shlex
import subprocess
import sys

MARKER = re.compile(r"<!-- number: (.+?) \| ([^|]+?) \| ([^|]+?) -->(.*?)<!-- /number -->", re.S)
OUTPUT = re.compile(r"(<!-- output: (.+?) -->\n```[a-z]*\n)(.*?)(```\n<!-- /output -->)", re.S)


def value_at(doc, path):
    for key in path.split("."):
        doc = doc[int(key)] if isinstance(doc, list) else doc[key]
    return doc


def main():
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    aapat = sys.argv[1]
    write = "--write" in sys.argv[2:]
    root = pathlib.Path(__file__).resolve().parent.parent
    files = [pathlib.Path(f) for f in sys.argv[2:] if f != "--write"] or (
        [root / "README.md"] + sorted((root / "docs").rglob("*.md")))
    outputs, wrong, checked = {}, [], 0
    for path in files:
        text = path.read_text()
        for m in MARKER.finditer(text):
            command, key, spec, quoted = m.group(1).strip(), m.group(2).strip(), m.group(3).strip(), m.group(4)
            if command not in outputs:
                run = subprocess.run([aapat] + shlex.split(command), capture_output=True, text=True,
                                     cwd=root)
                if run.returncode != 0:
                    wrong.append(f"{path.name}: `aapat {command}` failed: {run.stderr.strip()}")
                    outputs[command] = None
                    continue
                outputs[command] = json.loads(run.stdout)
            if outputs[command] is None:
                continue
            try:
                now = format(value_at(outputs[command], key), spec)
            except (KeyError, IndexError, ValueError, TypeError) as e:
                wrong.append(f"{path.name}: `aapat {command}` has no {key} ({e})")
                continue
            checked += 1
            if now != quoted:
                line = text.count("\n", 0, m.start()) + 1
                wrong.append(f"{path.name}:{line}: quotes {quoted} where `aapat {command}` gives "
                             f"{key} = {now}")
        shown = {}
        for m in OUTPUT.finditer(text):
            command = m.group(2).strip()
            run = subprocess.run([aapat] + shlex.split(command), capture_output=True, text=True,
                                 cwd=root)
            if run.returncode != 0:
                wrong.append(f"{path.name}: `aapat {command}` failed: {run.stderr.strip()}")
                continue
            checked += 1
            shown[m.group(0)] = m.group(1) + run.stdout + m.group(4)
            if run.stdout != m.group(3) and not write:
                line = text.count("\n", 0, m.start()) + 1
                wrong.append(f"{path.name}:{line}: the output shown is not what `aapat {command}` "
                             "prints (scripts/check-numbers.py AAPAT --write rewrites it)")
        if write and shown:
            for old, new in shown.items():
                text = text.replace(old, new)
            path.write_text(text)
    if wrong:
        print("\n".join(wrong))
        sys.exit(1)
    print(f"check-numbers: {checked} quoted numbers and outputs, each what its command prints")


if __name__ == "__main__":
    main()
