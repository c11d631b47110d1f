#!/usr/bin/env python3
"""Same seed, same output on every platform: the library draws its random
numbers through generate/portable_random.h and takes its decisions on
core/portable_math.h where the C libraries round differently, never on the standard library's distributions or
std::shuffle, whose algorithms differ between libstdc++ and libc++ (the
WebAssembly build). Tests may use them: they compare against them."""
import pathlib
import re
import sys

root = pathlib.Path(__file__).resolve().parent.parent
banned = re.compile(r"std::(shuffle|uniform_int_distribution|uniform_real_distribution|"
                    r"normal_distribution|bernoulli_distribution|discrete_distribution|"
                    r"poisson_distribution|exponential_distribution|random_device)\b")
found = []
for folder in ("src/aapat", "web", "python"):
    for path in sorted((root / folder).rglob("*")):
        if path.suffix not in (".cpp", ".h") or path.name.endswith("_test.cpp"):
            continue
        if "node_modules" in path.parts:
            continue
        for number, line in enumerate(path.read_text().splitlines(), 1):
            code = line.split("//", 1)[0]
            if banned.search(code) and "portable" not in path.name:
                found.append(f"{path.relative_to(root)}:{number}: {line.strip()}")
if found:
    print("the standard library's randomness in the library; use generate/portable_random.h:")
    print("\n".join(found))
    sys.exit(1)
print("check-portable: every random draw goes through generate/portable_random.h")
