"""The module as a whole: docstrings, the registry, the worked example of docs/python.md."""
import math
from fractions import Fraction

import numpy as np
import pytest

import aapat


def test_every_function_has_a_docstring():
    import inspect
    for name in dir(aapat):
        obj = getattr(aapat, name)
        if name.startswith("_") or not callable(obj):
            continue
        assert obj.__doc__ and len(obj.__doc__.strip()) > 20, name
    assert "family: the family to search" in aapat.optimize.__doc__
    assert "progress" in aapat.optimize.__doc__


def test_the_registry_lists_what_the_cli_lists():
    reg = aapat.registry()
    assert "mitchell" in [f["name"] for f in reg["filters"]]
    assert {"key": "b", "default": "1/3", "meaning": "B parameter"} in next(
        f for f in reg["filters"] if f["name"] == "mitchell")["parameters"]
    assert "spiral" in [s["name"] for s in reg["scenes"]]


def test_the_worked_example_of_the_docs_runs(tmp_path):
    import os
    import subprocess
    import sys
    script = os.path.join(os.path.dirname(__file__), "..", "examples", "worked_example.py")
    r = subprocess.run([sys.executable, script, str(tmp_path)], capture_output=True, text=True,
                       env={**os.environ, "MPLBACKEND": "Agg"})
    assert r.returncode == 0, r.stderr
    assert "rgss           P(1,1,4)    E2 0.4390" in r.stdout
    assert "optimized: P(1,1,4) from 16 jittered starts, E2 0.3587" in r.stdout
    # docs/python.md shows what it prints, line for line (the figure's line aside).
    doc = open(os.path.join(os.path.dirname(__file__), "..", "..", "docs", "python.md")).read()
    shown = doc.split("It prints:\n\n```\n", 1)[1].split("```", 1)[0]
    printed = "".join(line for line in r.stdout.splitlines(keepends=True)
                      if not line.startswith("(matplotlib"))
    assert printed == shown


def test_import_without_numpy_says_what_to_install(tmp_path):
    """A numpy that cannot be imported (a stand-in package that raises) makes
    `import aapat` fail at once with a message naming what to install."""
    import os
    import subprocess
    import sys
    fake = tmp_path / "numpy"
    fake.mkdir()
    (fake / "__init__.py").write_text("raise ImportError('no numpy here')\n")
    env = {**os.environ, "PYTHONPATH": os.pathsep.join([str(tmp_path)] + sys.path)}
    r = subprocess.run([sys.executable, "-c", "import aapat"], capture_output=True, text=True,
                       env=env)
    assert r.returncode != 0
    assert "aapat needs numpy: install it (Debian: apt-get install python3-numpy" in r.stderr
