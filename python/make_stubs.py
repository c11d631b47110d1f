#!/usr/bin/env python3
"""Writes the type stubs of the `aapat` module (python/aapat-stubs/__init__.pyi)
from the signatures pybind11 gives every function, method and property, so
that editors complete names and show signatures. Run with the built module on
PYTHONPATH: `make_stubs.py OUT.pyi`; `make_stubs.py --check FILE` exits 1 when
FILE is not what the module gives (the test suite runs it)."""
import inspect
import re
import sys

import aapat

SIMPLE_DEFAULT = re.compile(r"^(None|True|False|-?[0-9.e+-]+|inf|'[^']*'|\[\])$")


def clean_type(t):
    t = t.strip()
    t = re.sub(r"numpy\.ndarray\[[^\]]*\]", "numpy.ndarray", t)
    t = t.replace("aapat.", "")
    t = re.sub(r"\bobject\b", "Any", t)
    for old, new in (("List[", "list["), ("Dict[", "dict["), ("Tuple[", "tuple["),
                     ("Callable[", "Callable[")):
        t = t.replace(old, new)
    return t


def split_args(text):
    """Top-level comma split of a pybind11 argument list."""
    parts, depth, cur, quote = [], 0, "", None
    for ch in text:
        if quote:
            cur += ch
            if ch == quote:
                quote = None
            continue
        if ch in "'\"":
            quote = ch
        elif ch in "([{":
            depth += 1
        elif ch in ")]}":
            depth -= 1
        if ch == "," and depth == 0:
            parts.append(cur.strip())
            cur = ""
        else:
            cur += ch
    if cur.strip():
        parts.append(cur.strip())
    return parts


def stub_signature(name, sig_line):
    m = re.match(r"^\w+\((.*)\) -> (.*)$", sig_line)
    if not m:
        return f"def {name}(*args: Any, **kwargs: Any) -> Any: ..."
    args = []
    for a in split_args(m.group(1)):
        if a in ("*", "self"):
            args.append(a)
            continue
        if a.startswith("self:"):
            args.append("self")
            continue
        default = None
        if " = " in a:
            a, default = a.split(" = ", 1)
            default = default if SIMPLE_DEFAULT.match(default) else "..."
            if default == "inf":
                default = "..."
        arg_name, _, arg_type = a.partition(":")
        text = f"{arg_name.strip()}: {clean_type(arg_type)}" if arg_type else arg_name.strip()
        args.append(text + (f" = {default}" if default is not None else ""))
    return f"def {name}({', '.join(args)}) -> {clean_type(m.group(2))}: ..."


def first_line(doc):
    return (doc or "").strip().splitlines()[0] if doc else ""


def stubs():
    out = ['"""Type stubs of aapat (written by python/make_stubs.py from the module)."""',
           "from typing import Any, Callable", "", "import numpy", "",
           "__version__: str", "", "class Error(ValueError, TypeError): ...", ""]
    for name, obj in sorted(vars(aapat).items()):
        if name.startswith("_") or name == "Error":
            continue
        if inspect.isclass(obj):
            out.append(f"class {name}:")
            body = []
            for attr, value in sorted(vars(obj).items()):
                if attr.startswith("_") and attr not in ("__init__", "__call__"):
                    continue
                if isinstance(value, property):
                    ret = re.search(r"-> (.*)$", first_line(value.fget.__doc__))
                    body.append(f"    @property\n    def {attr}(self) -> "
                                f"{clean_type(ret.group(1)) if ret else 'Any'}: ...")
                elif callable(value) or isinstance(value, staticmethod):
                    doc = first_line(getattr(value, "__doc__", ""))
                    if doc.startswith("Overloaded"):
                        doc = ""
                    if not re.match(r"^\w+\(", doc):
                        continue  # no signature: a class Python does not construct
                    static = "self" not in doc.split("->")[0]
                    line = stub_signature(attr, doc)
                    body.append(("    @staticmethod\n" if static and attr != "__init__" else "")
                                + "    " + line)
            out.extend(body or ["    ..."])
            out.append("")
        elif callable(obj):
            out.append(stub_signature(name, first_line(obj.__doc__)))
    return "\n".join(out) + "\n"


if __name__ == "__main__":
    text = stubs()
    if sys.argv[1] == "--check":
        with open(sys.argv[2]) as f:
            if f.read() != text:
                print(f"{sys.argv[2]} is not what the module gives: rerun python/make_stubs.py")
                sys.exit(1)
        print("stubs up to date")
    else:
        with open(sys.argv[1], "w") as f:
            f.write(text)
