"""Random bad values and types for every function, method and constructor of
the module: each call either returns or raises aapat.Error (a ValueError and a
TypeError), never another exception, and never crashes the interpreter. Each
function has a cheap valid call; a case replaces one of its arguments (or adds
one) with a value drawn from what a careless or hostile caller hands over."""
import math
import os

import numpy as np
import pytest

import aapat

CASES_PER_FUNCTION = 24


class Opaque:
    """An object of no type the module knows."""


def bad_values(rng, tmp):
    fifo = os.path.join(tmp, "fifo")
    if not os.path.exists(fifo):
        os.mkfifo(fifo)
    values = [
        None, True, -1, 0, -2**31, 2**63, 2**64, 2**70, -2**64,
        math.nan, math.inf, -math.inf, -1e300, 1e300, 1e-320,
        "", "x", "nan", "a" * 5000, "\u00e9\u4e2d", "box:radius=nan", "P(9,9,9)", "msaa-4:x=1",
        fifo, "/dev/zero", "/", os.path.join(tmp, "missing", "file.json"),
        [], [1, 2], ["x"], [[math.nan, 0]], {}, {"x": 1}, {"gamma": "x"}, (1,), (1, 2, 3),
        (2**40, 2**40), (-1, 8), (0, 0), Opaque(), b"\xff\xfe",
        np.array([]), np.zeros((0, 2)), np.full((3, 2), math.nan), np.zeros((2, 3, 4, 5)),
        np.array(["a", "b"]), np.ones((4, 2)) * 7, np.zeros((2, 2), dtype=np.complex128),
    ]
    return values[int(rng.integers(len(values)))]


@pytest.fixture(scope="module")
def files(tmp_path_factory):
    tmp = tmp_path_factory.mktemp("bad")
    pattern = aapat.pattern("msaa-4")
    pattern_file = str(tmp / "p.json")
    pattern.save(pattern_file)
    points_file = str(tmp / "p.csv")
    aapat.write_points(points_file, aapat.generate("halton", 16))
    return {"tmp": str(tmp), "pattern": pattern_file, "points": points_file}


def calls(files):
    """name -> (function, positional arguments, keyword arguments): a valid, cheap call."""
    tmp = files["tmp"]
    p = aapat.pattern("msaa-4")
    seq = aapat.sequence("halton:frames=4")
    img = np.full((8, 8, 3), 0.5)
    return {
        "acuity": (aapat.acuity, ["uniform:step=10"], {}),
        "AcuityTable": (aapat.AcuityTable, ["uniform:step=10"], {}),
        "filter": (aapat.filter, ["box"], {}),
        "Filter": (aapat.Filter, ["tent"], {}),
        "Filter.__call__": (aapat.filter("tent").__call__, [np.linspace(-1, 1, 5)], {}),
        "diff": (aapat.diff, [img, img * 0.9], {"ppd": 67.0}),
        "snap": (aapat.snap, ["flipquad"], {"lattice": 16, "optimize_weights": False}),
        "export": (aapat.export, ["msaa-4"], {"api": "vulkan", "snap": True, "grid": (2, 2)}),
        "discrepancy": (aapat.discrepancy, [aapat.generate("halton", 32)], {"measures": "l2-star"}),
        "engine_taa": (aapat.engine_taa, ["checkerboard"],
                       {"size": (16, 16), "frames": 2, "warmup": 0, "reference_samples": 4,
                        "taa": "fsr2", "ratio": 1.0, "settings": {}}),
        "enumerate": (aapat.enumerate, [], {"max_per_edge": 1, "costs": [1.0]}),
        "eval": (aapat.eval, ["msaa-4"], {"threads": 1, "norm": 2}),
        "eval_report": (aapat.eval_report, [p], {"optimized_weights": False}),
        "figure10": (aapat.figure10, [], {"starts": 1, "seed": 1}),
        "generate": (aapat.generate, ["halton", 16], {"seed": 1}),
        "hardware_table": (aapat.hardware_table, [], {"starts": 1, "seed": 1,
                                                       "acuity": "uniform:step=30"}),
        "load_pattern": (aapat.load_pattern, [files["pattern"]], {}),
        "optimize": (aapat.optimize, [], {"family": "P(1,1,2)", "starts": 1, "iterations": 5,
                                           "lattice": 0, "threads": 1, "time_limit": 0.0}),
        "optimize_sequence": (aapat.optimize_sequence, [],
                              {"frames": 2, "starts": 1, "iterations": 5, "alpha": 0.5}),
        "optimize_sequence_pan": (aapat.optimize_sequence_pan, [],
                                  {"frames": 2, "taa": "fsr2", "ratio": 1.0, "settings": {},
                                   "velocities": [(0.3, 0.2)], "step": 0.25, "min_step": 0.25,
                                   "jitter_bound": 0.5, "acuity": "uniform:step=30"}),
        "pattern": (aapat.pattern, ["msaa-4"], {}),
        "Pattern": (aapat.Pattern, [np.array([[0.1, 0.2], [-0.3, 0.1]])], {"name": "two"}),
        "Pattern.from_json": (aapat.Pattern.from_json, [p.to_json()], {}),
        "Pattern.save": (p.save, [os.path.join(tmp, "saved.json")], {}),
        "profile": (aapat.profile, ["msaa-4"], {"acuity": "uniform:step=10"}),
        "read_points": (aapat.read_points, [files["points"]], {"format": ""}),
        "registry": (aapat.registry, [], {}),
        "limits": (aapat.limits, [], {}),
        "render": (aapat.render, ["disc"], {"pattern": "msaa-4", "size": (8, 8), "samples": 4,
                                            "reference_samples": 4}),
        "save_pattern": (aapat.save_pattern, [p, os.path.join(tmp, "s.json")], {}),
        "sequence": (aapat.sequence, ["halton:frames=4"], {}),
        "Sequence.save": (seq.save, [os.path.join(tmp, "q.json")], {}),
        "sequence_eval": (aapat.sequence_eval, [seq], {"alpha": 0.2, "window": 0, "ratio": 1.0}),
        "sequence_pan": (aapat.sequence_pan, [["halton:frames=4"]],
                         {"taa": "godot", "ratio": 1.0,
                          "settings": {"resolve": "generic", "history": "bilinear"},
                          "velocities": [(0.3, 0.2)],
                          "acuity": "uniform:step=30"}),
        "sequence_compare": (aapat.sequence_compare, [["halton:frames=4", "r2:frames=4"]],
                             {"taa": "bevy", "random_scenes": 2, "shapes": 3, "size": (8, 8),
                              "frames": 2, "warmup": 1, "reference_samples": 4,
                              "resamples": 20}),
        "sequence_search": (aapat.sequence_search, ["halton:frames=2"],
                            {"taa": "bevy", "random_scenes": 1, "shapes": 2, "size": (8, 8),
                             "frames": 2, "warmup": 1, "reference_samples": 4, "max_tries": 2}),
        "perceptual_eval": (aapat.perceptual_eval, [["msaa-4", "rgss"]],
                            {"objective": "perceptual:angles=1,patch=16,reference=16"}),
        "refine": (aapat.refine, ["msaa-4"],
                   {"objective": "perceptual:angles=1,patch=16,reference=16", "max_tries": 3}),
        "study_compare": (aapat.study_compare, [["msaa-4", "rgss"]],
                          {"scenes": ["halfplane"], "size": 8, "frames": 1,
                           "reference_samples": 4, "resamples": 20}),
        "spectrum": (aapat.spectrum, ["halton"], {"n": 16, "size": 8}),
        "spectrum_1d": (aapat.spectrum_1d, [["jittered"]], {"n": 16, "frequencies": 16}),
        "table2": (aapat.table2, [], {"size": 8, "frames": 1}),
        "table3": (aapat.table3, [], {"patterns": 1, "iterations": 1}),
        "write_points": (aapat.write_points, [os.path.join(tmp, "w.csv"),
                                              aapat.generate("halton", 4)], {}),
    }


def every_public_callable():
    """The module's functions and the public methods of its classes."""
    names = set()
    for name, value in vars(aapat).items():
        if name.startswith("_") or name == "Error":
            continue
        if isinstance(value, type):
            names.add(name)
            for attr, member in vars(value).items():
                if (attr == "__call__" or not attr.startswith("_")) and (
                        callable(member) or isinstance(member, staticmethod)):
                    names.add(f"{name}.{attr}")
        elif callable(value):
            names.add(name)
    return names


def test_every_callable_has_a_bad_argument_case(files):
    """A function added to the module without a case here fails this test."""
    covered = set(calls(files))
    # Classes that Python does not construct, and methods without arguments
    # (to_json, read-only results) take nothing to corrupt.
    no_arguments = {"OptimizeResult", "Sequence", "Pattern.to_json", "Sequence.to_json",
                    "read_image"}
    missing = every_public_callable() - covered - no_arguments
    assert not missing, f"no bad-argument case for {sorted(missing)}"


@pytest.mark.parametrize("name", sorted(
    ["acuity", "AcuityTable", "filter", "Filter", "Filter.__call__", "diff", "discrepancy",
     "engine_taa", "enumerate", "eval", "eval_report", "export", "figure10", "generate", "hardware_table",
     "load_pattern", "optimize", "perceptual_eval", "refine", "optimize_sequence", "optimize_sequence_pan", "pattern", "Pattern", "Pattern.from_json",
     "Pattern.save", "profile", "read_points", "registry", "limits", "render", "save_pattern", "sequence",
     "Sequence.save", "sequence_compare", "sequence_eval", "sequence_pan", "sequence_search", "snap", "spectrum", "study_compare", "spectrum_1d", "table2", "table3",
     "write_points"]))
def test_random_bad_arguments_raise_only_aapat_error(name, files, monkeypatch):
    # A bad value may be a valid relative path ("nan"): whatever a case
    # writes lands in the test's folder, not where pytest was started.
    monkeypatch.chdir(files["tmp"])
    function, args, kwargs = calls(files)[name]
    function(*args, **kwargs)  # the valid call runs
    rng = np.random.default_rng(sum(map(ord, name)))  # the same cases on every run
    for case in range(CASES_PER_FUNCTION):
        a, k = list(args), dict(kwargs)
        value = bad_values(rng, files["tmp"])
        slots = len(a) + len(k)
        pick = int(rng.integers(slots + 2))
        if pick < len(a):
            a[pick] = value
        elif pick < slots:
            k[list(k)[pick - len(a)]] = value
        elif pick == slots:
            a.append(value)  # one positional argument too many
        else:
            k["no_such_keyword"] = value
        try:
            function(*a, **k)
        except aapat.Error:
            pass
        except Exception as e:  # noqa: BLE001 - the point of the test
            pytest.fail(f"{name} case {case} ({a!r:.200}, {k!r:.200}) raised "
                        f"{type(e).__name__}: {e}")
