"""One definition, two faces: every command with a Python twin gives the same
keys and values from Python, under the same default objective; and Python is
as strict as the command line about the arrays it is handed."""
import json
import os
import subprocess
import sys

import numpy as np
import pytest

import aapat


def cli_json(aapat_cli, *args):
    doc = json.loads(aapat_cli(*args, "--json"))
    return {k: v for k, v in doc.items() if k not in ("command", "schema")}


def test_eval_defaults_to_the_recommended_objective_on_both_faces(aapat_cli):
    doc = cli_json(aapat_cli, "eval", "msaa-8", "aapat-8")
    assert doc["objective"] == "recommended"
    cli = {row["pattern"]: row["e2"] for row in doc["rows"]}
    py = dict(zip(["msaa-8", "aapat-8"], aapat.eval(["msaa-8", "aapat-8"])))
    assert py == cli
    assert cli["aapat-8"] < cli["msaa-8"]  # the catalog's pattern ranks first under its objective
    papers = cli_json(aapat_cli, "eval", "flipquad", "--objective", "laine-aila")
    assert papers["rows"][0]["e2"] == aapat.eval("flipquad", objective="laine-aila")
    assert round(papers["rows"][0]["e2"], 4) == 0.3643  # Laine-Aila Table 2


def test_perceptual_eval_and_refine_are_the_cli_json(aapat_cli, tmp_path):
    spec = "perceptual:angles=2,patch=16,reference=16"
    cli = cli_json(aapat_cli, "eval", "msaa-4", "rgss", "--objective", spec)
    py = aapat.perceptual_eval(["msaa-4", "rgss"], objective=spec)
    py = {k: v for k, v in py.items() if k not in ("command", "schema")}
    assert py == cli
    refined = aapat.refine("msaa-4", objective=spec, max_tries=10)
    cli = cli_json(aapat_cli, "--quiet", "refine", "msaa-4", "-O", spec, "--max-tries", "10")
    assert {k: v for k, v in refined.items() if k not in ("command", "schema", "refined")} == cli
    assert refined["refined"].name == "msaa-4-perceptual"
    # Weight steps after the compass search: the same document on both faces.
    refined = aapat.refine("msaa-4", objective=spec, max_tries=5, weight_steps=3)
    cli = cli_json(aapat_cli, "--quiet", "refine", "msaa-4", "-O", spec, "--max-tries", "5",
                   "--weight-steps", "3")
    assert {k: v for k, v in refined.items() if k not in ("command", "schema", "refined")} == cli
    assert cli["after"] <= cli["compass_after"] and "weight_steps" in cli
    with pytest.raises(aapat.Error, match="weight_steps"):
        aapat.refine("msaa-4", scenes=["spiral"], weight_steps=2)
    with pytest.raises(aapat.Error, match="ppd"):
        aapat.perceptual_eval("msaa-4", objective="perceptual:ppd=0")
    with pytest.raises(aapat.Error, match="no primitives"):
        aapat.refine("msaa-4", objective="perceptual:edge=0,line=0,thin=0,dot=0")


def test_refine_on_scenes_and_a_lattice_is_the_cli_json(aapat_cli):
    scenes = ["spiral", "checkerboard"]
    py = aapat.refine("rgss", scenes=scenes, size=16, reference_samples=16, api="vulkan",
                      max_tries=8)
    cli = cli_json(aapat_cli, "--quiet", "refine", "rgss", "--scenes", *scenes, "--size", "16",
                   "--reference-samples", "16", "--api", "vulkan", "--max-tries", "8")
    assert {k: v for k, v in py.items() if k not in ("command", "schema", "refined")} == cli
    assert cli["objective"] == "flip over 2 scenes at 16x16 (reference 16 spp mitchell)"
    assert py["refined"].name == "rgss-rendered"
    with pytest.raises(aapat.Error, match="measure"):
        aapat.refine("rgss", scenes=scenes, size=16, measure="psnr")
    with pytest.raises(aapat.Error, match="nosuch"):
        aapat.refine("rgss", api="nosuch", max_tries=2)


def test_eval_report_is_the_cli_json(aapat_cli):
    cli = cli_json(aapat_cli, "eval", "msaa-8", "flipquad", "--optimized-weights")
    py = aapat.eval_report(["msaa-8", "flipquad"], optimized_weights=True)
    py = {k: v for k, v in py.items() if k not in ("command", "schema")}
    assert py == cli


def test_optimize_report_is_the_cli_json(aapat_cli):
    args = ["--family", "P(1,1,3)", "--starts", "3", "--seed", "4"]
    cli = cli_json(aapat_cli, "optimize", *args)
    py = aapat.optimize(family="P(1,1,3)", starts=3, seed=4).report
    py = {k: v for k, v in py.items() if k not in ("command", "schema")}
    assert py.keys() == cli.keys()
    assert py == cli


def test_sequence_eval_row_is_the_cli_row(aapat_cli):
    cli = cli_json(aapat_cli, "sequence", "eval", "aapat-taa-8", "--alpha", "0.2")
    py = aapat.sequence_eval("aapat-taa-8", alpha=0.2)
    assert py.keys() == cli["rows"][0].keys()
    assert py == cli["rows"][0]
    assert py["flicker"] <= py["worst_flicker"]  # the mean, and the largest


def test_sequence_eval_at_a_ratio_is_the_cli_row(aapat_cli):
    """At 1.5, under the model optimize --sequence --ratio searched, the
    catalog's aapat-upscale-1.5 beats Halton(2,3) of its 18 phases on worst
    E2 (0.0963 against 0.1041); Python's row is the CLI's."""
    cli = cli_json(aapat_cli, "sequence", "eval", "aapat-upscale-1.5", "halton:frames=18",
                   "--ratio", "1.5")
    py = aapat.sequence_eval("aapat-upscale-1.5", ratio=1.5)
    assert py == cli["rows"][0]
    assert round(py["worst_e2"], 4) == 0.0963
    assert round(cli["rows"][1]["worst_e2"], 4) == 0.1041


def test_sequence_pan_rows_are_the_cli_rows(aapat_cli):
    """One evaluation on both faces: the same rows, the default velocities too."""
    args = ["aapat-taa-8", "halton:frames=8", "--taa", "ue4", "--acuity", "uniform:step=30"]
    cli = cli_json(aapat_cli, "sequence", "pan", *args)
    py = aapat.sequence_pan(["aapat-taa-8", "halton:frames=8"], taa="ue4",
                            acuity="uniform:step=30")
    assert py == cli["rows"]
    assert [v["velocity"] for v in py[0]["velocities"]][0] == [0.0, 0.0]
    # A setting overridden (of the generic pipeline, which the pan model reads).
    godot = ["aapat-taa-8", "halton:frames=8", "--taa", "godot", "--acuity", "uniform:step=30"]
    cli = cli_json(aapat_cli, "sequence", "pan", *godot, "--taa-set", "resolve=generic",
                   "--taa-set", "history=bilinear", "--velocity", "0.37,0.21")
    py = aapat.sequence_pan(["aapat-taa-8", "halton:frames=8"], taa="godot",
                            settings={"resolve": "generic", "history": "bilinear"},
                            velocities=[(0.37, 0.21)],
                            acuity="uniform:step=30")
    assert py == cli["rows"]
    with pytest.raises(aapat.Error, match="velocity"):
        aapat.sequence_pan(["r2"], taa="fsr2", velocities=[(float("nan"), 0.0)])
    calls = []
    again = aapat.sequence_pan(["aapat-taa-8", "halton:frames=8"], taa="godot",
                               settings={"resolve": "generic", "history": "bilinear"},
                               velocities=[(0.37, 0.21)], acuity="uniform:step=30",
                               progress=lambda done, total, note: calls.append((done, total)))
    assert again == py and sorted(calls) == [(1, 2), (2, 2)]


def test_sequence_pan_over_random_velocities_is_the_cli_comparison(aapat_cli):
    """The same random pans and the same comparison with the first on both faces,
    and the comparison is what the rows say."""
    args = ["halton:frames=4", "r2:frames=4", "--taa", "bevy", "--acuity", "uniform:step=30",
            "--random-velocities", "3", "--max-speed", "0.8", "--seed", "5"]
    cli = cli_json(aapat_cli, "sequence", "pan", *args)
    py = aapat.sequence_pan(["halton:frames=4", "r2:frames=4"], taa="bevy",
                            acuity="uniform:step=30", random_velocities=3, max_speed=0.8, seed=5)
    assert py == cli["rows"]
    velocities = [v["velocity"] for v in py[0]["velocities"]]
    assert len(velocities) == 3 and all(abs(c) <= 0.8 for v in velocities for c in v)
    assert all(round(c, 3) == c for v in velocities for c in v)
    assert "against_first" not in py[0]
    c = py[1]["against_first"]
    changes = [b["mean_e2"] / a["mean_e2"] - 1
               for a, b in zip(py[0]["velocities"], py[1]["velocities"])]
    assert c["sequence"] == py[0]["sequence"] and c["velocities"] == 3
    assert c["lower_at"] == sum(x < 0 for x in changes)
    assert c["mean_change"] == pytest.approx(sum(changes) / 3, rel=1e-12)
    assert (c["lowest_change"], c["highest_change"]) == (min(changes), max(changes))
    with pytest.raises(aapat.Error, match="max_speed"):
        aapat.sequence_pan(["r2"], taa="bevy", random_velocities=2, max_speed=float("nan"))


def assert_same_search(py_result, cli, out):
    """A Python search's dict against the command line's --json and -o file."""
    py = {k: v for k, v in py_result.items() if k not in ("command", "schema")}
    with open(out) as f:
        assert py["result"].to_json() == f.read()
    assert py.keys() == cli.keys()
    for key in cli:
        if key != "result":
            assert py[key] == cli[key], key
    return py


def test_optimize_sequence_at_8_frames_and_8_starts_equals_the_cli(aapat_cli, tmp_path):
    out = str(tmp_path / "seq.json")
    cli = cli_json(aapat_cli, "optimize", "--sequence", "8", "--starts", "8", "-o", out)
    assert_same_search(aapat.optimize_sequence(frames=8, starts=8), cli, out)


def test_optimize_sequence_pan_equals_the_cli(aapat_cli, tmp_path):
    """The search under motion on both faces: the same document and sequence."""
    out = str(tmp_path / "pan.json")
    args = ["--taa", "fsr2", "--ratio", "1.5", "--velocity", "0,0", "--velocity", "0.37,0.21",
            "--step", "0.125", "--min-step", "0.0625", "--acuity", "uniform:step=30"]
    cli = cli_json(aapat_cli, "optimize", "--sequence", "4", *args, "-o", out)
    py = assert_same_search(aapat.optimize_sequence_pan(
        frames=4, taa="fsr2", ratio=1.5, velocities=[(0.0, 0.0), (0.37, 0.21)], step=0.125,
        min_step=0.0625, acuity="uniform:step=30"), cli, out)
    assert py["mean_e2"] <= py["start_mean_e2"]  # never worse than its start
    assert py["from"] == "halton:b1=2,b2=3,frames=4,start=1"


def test_engine_taa_is_the_cli_json(aapat_cli):
    args = ["--taa", "fsr2", "--ratio", "1.5", "--motion", "pan:dx=0.4,dy=0.2", "--size", "24",
            "--frames", "3", "--warmup", "5", "--reference-samples", "4",
            "--taa-set", "resolve=generic", "--taa-set", "history=catmull-rom-9"]
    cli = cli_json(aapat_cli, "animate", "spiral", *args)
    py = aapat.engine_taa("spiral", taa="fsr2", ratio=1.5, motion="pan:dx=0.4,dy=0.2",
                          size=(24, 24), frames=3, warmup=5, reference_samples=4,
                          settings={"resolve": "generic", "history": "catmull-rom-9"})
    assert py.keys() == cli.keys()
    assert py == cli
    assert py["phases"] == 18  # FSR 2's int(8 R^2) at 1.5
    with pytest.raises(aapat.Error, match="ratio"):
        aapat.engine_taa("spiral", ratio=0.5)
    with pytest.raises(aapat.Error, match="unknown TAA setting"):
        aapat.engine_taa("spiral", settings={"colour": 1})


# Every Python function that takes an array, with the array in its place.
ARRAY_CALLS = {
    "eval (n, 2)": lambda a: aapat.eval(a),
    "eval (m, n, 2)": lambda a: aapat.eval(a.reshape(1, *a.shape) if a.ndim == 2 else a),
    "profile": lambda a: aapat.profile(a.reshape(1, *a.shape) if a.ndim == 2 else a),
    "Pattern": lambda a: aapat.Pattern(a),
    "discrepancy": lambda a: aapat.discrepancy(a + 0.5),
    "spectrum": lambda a: aapat.spectrum(a + 0.5, size=8),
    "write_points": lambda a: aapat.write_points("/nonexistent-dir/x.csv", a + 0.5),
    # Spread past the overshoot a filtered image may have (0.25 either side).
    "diff": lambda a: aapat.diff(a * 3 + 0.5, np.full_like(a, 0.5)),
}


def bad_arrays(rng):
    """Arrays a careless caller hands over: NaN, inf, out of range, wrong shape, empty."""
    good = rng.random((4, 2)) - 0.5
    for value in (np.nan, np.inf, -np.inf, 3.0, -3.0, 1e300):
        a = good.copy()
        a[rng.integers(4), rng.integers(2)] = value
        yield a
    yield rng.random((4, 3))
    yield rng.random(5)
    yield np.zeros((0, 2))
    yield rng.random((2, 2, 2, 2))


@pytest.mark.parametrize("name", sorted(ARRAY_CALLS))
def test_every_array_function_refuses_bad_arrays_with_aapat_error(name):
    rng = np.random.default_rng(20261202)
    call = ARRAY_CALLS[name]
    for trial in range(20):
        for a in bad_arrays(rng):
            with pytest.raises(aapat.Error):
                call(a)


def test_discrepancy_of_nan_or_outside_points_is_refused_not_computed():
    with pytest.raises(aapat.Error, match="not finite"):
        aapat.discrepancy(np.array([[0.5, np.nan], [0.2, 0.3]]))
    with pytest.raises(aapat.Error, match="outside the unit square"):
        aapat.discrepancy(np.array([[-3.0, 0.5], [0.2, 0.3]]))
    with pytest.raises(aapat.Error, match="outside the pixel"):
        aapat.eval(np.array([[[5.0, 5.0], [0.0, 0.0]]]))


def test_settings_out_of_range_are_refused():
    with pytest.raises(aapat.Error, match="threads"):
        aapat.eval(np.zeros((1, 2, 2)) + [[0.1, 0.2], [-0.1, -0.2]], threads=65537)
    with pytest.raises(aapat.Error, match="threads"):
        aapat.optimize(family="P(1,1,2)", threads=-5)
    with pytest.raises(aapat.Error, match="max_per_edge"):
        aapat.enumerate(max_per_edge=9)
    with pytest.raises(aapat.Error, match="frequencies"):
        aapat.spectrum_1d(["poisson"], frequencies=0)
    with pytest.raises(aapat.Error, match="max_frequency"):
        aapat.spectrum_1d(["poisson"], max_frequency=-1)
    with pytest.raises(aapat.Error, match="did you mean 'recommended'"):
        aapat.eval("rgss", objective="recomended")
    with pytest.raises(aapat.Error, match="objective"):
        aapat.eval("rgss", objective=3)


def assert_rows_agree(cli_rows, py_rows, extra=()):
    """Every CLI row has its Python twin with the same keys (Python may add the
    objects named in `extra`) and the same values."""
    assert len(cli_rows) == len(py_rows)
    for c, p in zip(cli_rows, py_rows):
        assert set(p) - set(extra) == set(c)
        for key in c:
            assert p[key] == c[key], key


def test_discrepancy_is_the_cli_document(aapat_cli, tmp_path):
    path = str(tmp_path / "h.csv")
    aapat.write_points(path, aapat.generate("halton", 64))
    cli = cli_json(aapat_cli, "discrepancy", path)
    py = aapat.discrepancy(aapat.read_points(path)[0])
    assert py == {k: v for k, v in cli.items() if k != "source"}


def test_enumerate_rows_are_the_cli_rows(aapat_cli):
    cli = cli_json(aapat_cli, "enumerate", "--cost", "1.25", "--optimize", "--starts", "2",
                   "--objective", "laine-aila")
    py = aapat.enumerate(costs=[1.25], optimize=True, starts=2, objective="laine-aila")
    assert_rows_agree(cli["rows"], py, extra=("pattern",))


def test_figure10_rows_are_the_cli_rows(aapat_cli):
    cli = cli_json(aapat_cli, "figure10", "--starts", "2")
    assert cli["objective"] == "laine-aila"  # a paper reproduction: the papers' objective
    py = aapat.figure10(starts=2)
    assert py == cli["rows"]


def test_table3_rows_are_the_cli_rows(aapat_cli):
    args = ["--patterns", "6", "--iterations", "20", "--method", "minimax"]
    cli = cli_json(aapat_cli, "table3", *args)
    assert cli["objective"] == "laine-aila" and cli["method"] == "minimax"
    py = aapat.table3(patterns=6, iterations=20, method="minimax")
    assert py == cli["rows"]
    assert [r["paper"][0] for r in py] == [0.423, 0.346]  # Laine-Aila Table 3, Min column


def test_table2_rows_are_the_cli_rows(aapat_cli):
    cli = cli_json(aapat_cli, "table2", "--size", "12", "--frames", "2", "--no-cache")
    py = aapat.table2(size=12, frames=2)
    assert py == cli["rows"]
    # Hasselgren et al. Table 2, FLIPQUAD's row
    assert py[-1]["paper"] == {"e2": 0.359, "rmse": 3.759, "max_deviation": 76}


def test_hardware_table_rows_are_the_cli_rows(aapat_cli):
    # (the papers' objective: the recommended one's full angle table is slower)
    cli = cli_json(aapat_cli, "hardware-table", "--starts", "1", "--objective", "laine-aila")
    py = aapat.hardware_table(starts=1, objective="laine-aila")
    assert py == cli["rows"]


def test_a_setting_out_of_range_is_named_as_each_face_gives_it(aapat_cli):
    """The library checks the setting once; the command line names its flag,
    Python its keyword."""
    with pytest.raises(aapat.Error, match=r"^max_per_edge 9: expected 0 to 8"):
        aapat.enumerate(max_per_edge=9)
    with pytest.raises(subprocess.CalledProcessError) as refused:
        aapat_cli("enumerate", "--max-per-edge", "9")
    assert "--max-per-edge 9: expected 0 to 8" in refused.value.stderr
    with pytest.raises(aapat.Error, match=r"^patterns 0: expected 1 to"):
        aapat.table3(patterns=0)


def test_the_registry_is_aapat_list(aapat_cli):
    cli = cli_json(aapat_cli, "list")
    py = aapat.registry()
    assert list(py.keys()) == list(cli.keys())  # one list of registries, in one order
    for kind in cli:
        assert py[kind] == cli[kind], kind
    assert [e["name"] for e in py["taa_presets"]] == ["ue4", "fsr2", "godot", "bevy", "bevy-0.16"]


def test_render_generate_and_spectrum_agree_with_the_cli(aapat_cli):
    cli = cli_json(aapat_cli, "render", "circles", "--pattern", "msaa-4", "--size", "24x16",
                   "--reference-samples", "16")
    py = aapat.render("circles", pattern="msaa-4", size=(24, 16), reference=True,
                      reference_samples=16)
    images = ("image", "reference_image")
    assert {k: v for k, v in py.items() if k not in images} == cli
    rows = cli_json(aapat_cli, "generate", "halton", "--n", "16")["rows"]
    assert aapat.generate("halton", 16).tolist() == [[r["x"], r["y"]] for r in rows]
    spec = cli_json(aapat_cli, "spectrum", "jittered", "--n", "64", "--size", "16")
    py = aapat.spectrum("jittered", n=64, size=16)
    assert py["radius"].tolist() == [r["radius"] for r in spec["rows"]]
    assert py["radial_power"].tolist() == [r["power"] for r in spec["rows"]]


def test_the_type_stubs_are_the_modules_signatures():
    """python/aapat-stubs is what pip installs for editors: it must name every
    function with the signature the module has (python/make_stubs.py)."""
    here = os.path.dirname(os.path.abspath(__file__))
    tool = os.path.join(here, "..", "make_stubs.py")
    stubs = os.path.join(here, "..", "aapat-stubs", "__init__.pyi")
    result = subprocess.run([sys.executable, tool, "--check", stubs], capture_output=True,
                            text=True, env={**os.environ, "PYTHONPATH": os.pathsep.join(sys.path)})
    assert result.returncode == 0, result.stdout + result.stderr


def test_spectrum_1d_defaults_are_the_cli_defaults(aapat_cli):
    """Goss & Wu's Figure 8 by default on both faces: 7488 points."""
    cli = cli_json(aapat_cli, "spectrum", "--1d", "poisson", "--frequencies", "32")
    assert cli["points"] == 7488
    py = aapat.spectrum_1d(["poisson"], frequencies=32)
    assert py["poisson"].tolist() == [r["poisson"] for r in cli["rows"]]
    assert py["frequency"].tolist() == [r["frequency"] for r in cli["rows"]]


def test_diff_is_the_cli_document(aapat_cli):
    """aapat.diff on arrays gives `aapat diff --json`'s values for the same
    pixels (the committed zoneplate pair: an aapat rendering against its
    reference), and the reference implementation's mean FLIP."""
    here = os.path.dirname(os.path.abspath(__file__))
    pair = [os.path.join(here, "..", "..", "testdata", "flip", f)
            for f in ("zoneplate-ref.png", "zoneplate-msaa4.png")]
    cli = cli_json(aapat_cli, "diff", *pair)
    assert abs(cli["flip"] - 0.107815) < 1e-5  # NVlabs/flip v1.6 (testdata/flip/README.md)
    ref, test = (aapat.read_image(p) for p in pair)
    assert np.array_equal(ref[..., 0], ref[..., 2])  # a grey file: R = G = B
    py = aapat.diff(ref, test)
    assert py["map"].shape == ref.shape[:2]
    assert aapat.diff(ref[..., 0], test[..., 1])["flip"] == py["flip"]  # grey arrays too
    values = {k: v for k, v in py.items() if k != "map"}
    assert values == {k: v for k, v in cli.items() if k not in ("reference", "test")}


def test_diff_refuses_arrays_over_the_pixel_limit_before_copying_them():
    """An array of more pixels than `aapat diff` reads from a PNG is refused
    by its shape, before it is converted (a broadcast view costs nothing;
    its copy as doubles would be 800 MB)."""
    huge = np.broadcast_to(np.float32(0.5), (6000, 6000, 3))
    with pytest.raises(ValueError, match=r"diff: reference has 6000x6000 pixels; at most 33554432"):
        aapat.diff(huge, huge)


def test_diff_of_renders_arrays_is_renders_own_figures():
    """One quantization rule: aapat.diff of a rendering and its reference
    (arrays, the reference's overshoot past 0 and 1 included) gives render's
    FLIP, RMSE and SSIM to the last digit."""
    r = aapat.render("spiral", pattern="rgss", size=(64, 48), reference=True,
                     reference_samples=64)
    assert r["reference_image"].min() < 0  # the Mitchell reference rings below black
    d = aapat.diff(r["reference_image"], r["image"])
    assert (d["flip"], d["rmse"], d["ssim"]) == (r["flip"], r["rmse"], r["ssim"])
    with pytest.raises(ValueError, match=r"an overshoot of up to 0.25"):
        aapat.diff(r["reference_image"] + 2, r["image"])


def test_snap_and_export_are_the_cli_commands(aapat_cli):
    cli = cli_json(aapat_cli, "snap", "flipquad", "--optimize-weights")
    py = aapat.snap("flipquad", optimize_weights=True)
    assert {k: v for k, v in py.items() if k not in ("result", "command", "schema")} == cli
    assert py["result"].family == "P(4,1+,2)"
    text = aapat_cli("export", "flipquad", "--snap", "--api", "vulkan", "--grid", "2x2")
    assert aapat.export("flipquad", snap=True, api="vulkan", grid=(2, 2)) == text


def test_render_flip_is_aapat_diff_of_its_files(aapat_cli, tmp_path):
    """FLIP means one thing wherever its name appears: the mean FLIP `render`
    reports is `aapat diff` of the image and the reference it writes."""
    image, reference = str(tmp_path / "image.png"), str(tmp_path / "reference.png")
    rendered = cli_json(aapat_cli, "render", "spiral", "--pattern", "rgss", "--size", "40x32",
                        "--reference-samples", "16", "--no-cache", "-o", image,
                        "--reference", reference)
    diffed = cli_json(aapat_cli, "diff", reference, image)
    assert rendered["flip"] == diffed["flip"]
    assert abs(rendered["ssim"] - diffed["ssim"]) < 1e-12


def test_a_mesh_view_renders_in_colour_on_both_faces(aapat_cli, tmp_path):
    """A mesh scene (data/mesh-views, a model of Debian's assimp-testmodels):
    the same document from both faces, an (h, w, 3) image, and figures that
    are `aapat diff`'s of the colour files it writes."""
    here = os.path.dirname(os.path.abspath(__file__))
    view = os.path.join(here, "..", "..", "data", "mesh-views", "box-textured.json")
    image, reference = str(tmp_path / "image.png"), str(tmp_path / "reference.png")
    cli = cli_json(aapat_cli, "render", view, "--pattern", "aapat-4", "--size", "40x32",
                   "--reference-samples", "16", "--no-cache", "-o", image, "--reference",
                   reference)
    py = aapat.render(view, pattern="aapat-4", size=(40, 32), reference=True,
                      reference_samples=16)
    assert py["image"].shape == (32, 40, 3)
    assert {k: v for k, v in py.items() if k not in ("image", "reference_image")} == cli
    assert np.array_equal(np.round(py["image"] * 255), np.round(aapat.read_image(image) * 255))
    diffed = cli_json(aapat_cli, "diff", reference, image)
    assert cli["flip"] == diffed["flip"]
    assert cli["rmse"] == diffed["rmse"]  # both on the 8-bit levels
    assert abs(cli["ssim"] - diffed["ssim"]) < 1e-12


def test_wrong_types_are_aapat_errors():
    """A value of the wrong type is aapat.Error wherever it is found: converted
    inside a function, or refused by the signature (pybind11's TypeError, whose
    message names the signatures taken). aapat.Error is a TypeError and a
    ValueError, so both of Python's idioms catch it."""
    with pytest.raises(aapat.Error, match="not of a type this function takes"):
        aapat.sequence_eval([1, 2])
    with pytest.raises(aapat.Error, match=r"incompatible function arguments(.|\n)*spec: str, n: int"):
        aapat.generate("halton", "ten")
    with pytest.raises(TypeError):
        aapat.Pattern(np.zeros((1, 2)), weights="")
    with pytest.raises(aapat.Error, match="weights: not an array of numbers"):
        aapat.Pattern(np.zeros((1, 2)), weights="")
    assert issubclass(aapat.Error, ValueError) and issubclass(aapat.Error, TypeError)


def test_threads_are_checked_on_every_path():
    """eval checks threads for a named pattern too, where it does not use
    them: the same limit as the command line's --threads."""
    with pytest.raises(aapat.Error, match=r"threads: 65537 is not in \[0, 1024\]"):
        aapat.eval("rgss", threads=65537)


def test_limits_are_one_table_on_every_face(aapat_cli):
    """The library's table of limits: aapat.limits() is `aapat limits --json`,
    and docs/limits.md shows `aapat limits --markdown` between its markers."""
    cli = cli_json(aapat_cli, "limits", "--json")
    assert aapat.limits() == cli["limits"]
    assert len(cli["limits"]) >= 30
    here = os.path.dirname(os.path.abspath(__file__))
    with open(os.path.join(here, "..", "..", "docs", "limits.md")) as f:
        doc = f.read()
    table = doc.split("<!-- the table: aapat limits --markdown -->\n")[1].split(
        "<!-- end of the table -->\n")[0]
    assert table == aapat_cli("limits", "--markdown")


def test_a_value_past_a_limit_is_refused_on_both_faces(aapat_cli):
    """The same limit, checked by the library, on both faces: one past the
    image side, the starts and the reference samples."""
    with pytest.raises(aapat.Error, match="16384"):
        aapat.render("disc", pattern="msaa-4", size=(16385, 1))
    with pytest.raises(aapat.Error, match="1000000"):
        aapat.optimize(family="P(1,1,2)", starts=1_000_001)
    with pytest.raises(aapat.Error, match="reference_samples 65537: expected 1 to 65536"):
        aapat.render("disc", pattern="msaa-4", size=(4, 4), reference=True,
                     reference_samples=65537)
    for args in (["render", "disc", "--pattern", "msaa-4", "--size", "16385x1"],
                 ["optimize", "--family", "P(1,1,2)", "--starts", "1000001"],
                 ["render", "disc", "--pattern", "msaa-4", "--reference-samples", "65537"]):
        with pytest.raises(subprocess.CalledProcessError):
            aapat_cli(*args)


def test_sequence_compare_is_the_cli_study(aapat_cli):
    """The rendered comparison on both faces: the same scenes, renders and
    statistics, and each comparison counts what the rows say."""
    args = ["halton:frames=4", "r2:frames=4", "--taa", "bevy", "--random-scenes", "3",
            "--shapes", "4", "--motion", "random-pan", "--seed", "3", "--size", "16",
            "--frames", "3", "--warmup", "2", "--reference-samples", "4", "--resamples", "100"]
    cli = cli_json(aapat_cli, "sequence", "compare", *args)
    py = aapat.sequence_compare(["halton:frames=4", "r2:frames=4"], taa="bevy", random_scenes=3,
                                shapes=4, motion="random-pan", seed=3, size=(16, 16), frames=3,
                                warmup=2, reference_samples=4, resamples=100)
    for key in ("scenes", "against_first", "sequences", "measures", "motion", "taa_settings"):
        assert py[key] == cli[key], key
    rmse = cli["against_first"][0]["rmse"]
    lower = sum(s["rows"][1]["rmse"] < s["rows"][0]["rmse"] for s in cli["scenes"])
    assert rmse["lower"] == lower and rmse["scenes"] == 3
    assert cli["scenes"][0]["scene"] == "random-shapes:count=4,seed=3"
    with pytest.raises(aapat.Error, match="scenes"):
        aapat.sequence_compare(["r2", "halton"], taa="bevy")
    # A sequence FSR 2 would not run: the same warning on both faces.
    null = ["halton:frames=18", "bevy-halton:frames=18"]
    cli = cli_json(aapat_cli, "sequence", "compare", *null, "--taa", "fsr2", "--ratio", "1.5",
                   "--random-scenes", "1", "--size", "8", "--frames", "2", "--warmup", "2",
                   "--reference-samples", "4")
    py = aapat.sequence_compare(null, taa="fsr2", ratio=1.5, random_scenes=1, size=(8, 8),
                                frames=2, warmup=2, reference_samples=4)
    assert py["warnings"] == cli["warnings"] and "never takes" in cli["warnings"][0]
    animated = aapat.engine_taa("spiral", taa="fsr2", ratio=1.5, sequence="bevy-halton:frames=18",
                                size=(16, 16), frames=2, reference_samples=4)
    assert animated["warnings"] == cli["warnings"]


def test_sequence_compare_at_the_resonances_is_the_cli_study(aapat_cli):
    """At the resonant velocities both faces give the same grid, the same
    worst per scene and the same comparison of the worst."""
    args = ["halton:frames=4", "r2:frames=4", "--taa", "fsr2", "--ratio", "1.5",
            "--random-scenes", "2", "--shapes", "3", "--motion", "resonant", "--size", "10",
            "--frames", "2", "--warmup", "1", "--reference-samples", "1", "--resamples", "50"]
    cli = cli_json(aapat_cli, "sequence", "compare", *args)
    py = aapat.sequence_compare(["halton:frames=4", "r2:frames=4"], taa="fsr2", ratio=1.5,
                                random_scenes=2, shapes=3, motion="resonant", size=(10, 10),
                                frames=2, warmup=1, reference_samples=1, resamples=50)
    for key in ("velocities", "scenes", "against_first", "against_first_worst"):
        assert py[key] == cli[key], key
    assert len(cli["velocities"]) == 38 and [0.5, 1 / 3] in cli["velocities"]
    row = cli["scenes"][0]["rows"][1]
    assert row["worst_velocity"]["flip"] == max(v["flip"] for v in row["per_velocity"])
    worst = cli["against_first_worst"][0]["rmse"]
    lower = sum(s["rows"][1]["worst_velocity"]["rmse"] < s["rows"][0]["worst_velocity"]["rmse"]
                for s in cli["scenes"])
    assert worst["lower"] == lower


def test_sequence_search_is_the_cli_search(aapat_cli, tmp_path):
    """The rendered search on both faces: the same tries, the same sequence."""
    out = str(tmp_path / "s.json")
    args = ["halton:frames=4", "--taa", "bevy", "--random-scenes", "2", "--shapes", "3",
            "--motion", "random-pan", "--size", "12", "--frames", "3", "--warmup", "2",
            "--reference-samples", "4", "--max-tries", "6", "--step", "0.125",
            "--min-step", "0.0625", "--unbiased", "-o", out]
    cli = cli_json(aapat_cli, "sequence", "search", *args)
    py = aapat.sequence_search("halton:frames=4", taa="bevy", random_scenes=2, shapes=3,
                               motion="random-pan", size=(12, 12), frames=3, warmup=2,
                               reference_samples=4, max_tries=6, step=0.125, min_step=0.0625,
                               unbiased=True)
    for key in ("start_value", "value", "tries", "kept", "against", "scenes", "worst",
                "unbiased", "motions"):
        assert py[key] == cli[key], key
    mean = py["result"].offsets.mean(axis=(0, 1))  # unbiased: the frames' mean is (0, 0)
    assert abs(mean[0]) < 1e-12 and abs(mean[1]) < 1e-12
    assert py["result"].to_json() == aapat.sequence(out).to_json()
    assert cli["value"] <= cli["start_value"]
    assert cli["against"] == "bevy-halton:frames=8"  # the preset's own jitter (Bevy 0.17)


def test_study_compare_is_the_cli_comparison(aapat_cli):
    """Patterns compared on both faces: the same measures per scene and the
    same paired comparison against the first."""
    args = ["msaa-4", "rgss", "aapat-4", "--scenes", "spiral", "halfplane", "circles",
            "--size", "24", "--frames", "2", "--reference-samples", "16", "--resamples", "200"]
    cli = cli_json(aapat_cli, "study", "--compare", *args)
    py = aapat.study_compare(["msaa-4", "rgss", "aapat-4"], scenes=["spiral", "halfplane", "circles"],
                             size=24, frames=2, reference_samples=16, resamples=200)
    for key in ("patterns", "against_first", "measures", "scenes", "objectives"):
        assert py[key] == cli[key], key
    flip = cli["against_first"][0]["flip"]
    lower = sum(r < f for r, f in zip((m[4] for m in cli["patterns"][1]["measures"]),
                                      (m[4] for m in cli["patterns"][0]["measures"])))
    assert flip["lower"] == lower and flip["scenes"] == 3 and cli["against_first"][0]["against"] == "msaa-4"


def test_a_huge_argument_is_not_echoed_whole():
    """A 100 KB name in an error message is cut, as the command line cuts it."""
    with pytest.raises(aapat.Error) as e:
        aapat.pattern("x" * 100000)
    assert len(str(e.value)) < 1100 and "more bytes)" in str(e.value)
