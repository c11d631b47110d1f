"""Sequences from Python: the CLI's numbers and files, numpy offsets, errors."""
import json

import numpy as np
import pytest

import aapat


def test_halton_offsets_are_the_upscalers():
    s = aapat.sequence("halton:frames=4")
    assert s.period == 4
    assert s.offsets.shape == (4, 1, 2)
    # Halton(2,3) from index 1, minus 1/2: (0, -1/6), (-1/4, 1/6), ...
    assert s.offsets[0, 0] == pytest.approx([0.0, 1 / 3 - 0.5])
    assert s.offsets[1, 0] == pytest.approx([-0.25, 2 / 3 - 0.5])


def test_eval_equals_the_cli(aapat_cli):
    cli = json.loads(aapat_cli("sequence", "eval", "aapat-taa-8", "--alpha", "0.1", "--json"))
    row = cli["rows"][0]
    py = aapat.sequence_eval("aapat-taa-8", alpha=0.1)
    assert py["worst_e2"] == row["worst_e2"]
    assert py["flicker"] == row["flicker"]
    assert np.array_equal(py["cut_curve"], np.array(row["cut_curve"]))


def test_optimize_equals_the_cli_file(aapat_cli, tmp_path):
    out = str(tmp_path / "seq.json")
    aapat_cli("optimize", "--sequence", "4", "--starts", "3", "--flicker-weight", "2", "-o", out)
    r = aapat.optimize_sequence(frames=4, starts=3, flicker_weight=2)
    with open(out) as f:
        assert r["result"].to_json() == f.read()
    assert r["j"] <= r["halton_j"]


def test_optimize_reports_each_start_and_a_raising_callback_stops_it():
    calls = []
    r = aapat.optimize_sequence(frames=4, starts=3,
                                progress=lambda done, total, note: calls.append((done, total, note)))
    assert [c[:2] for c in calls] == [(1, 3), (2, 3), (3, 3)]
    assert calls[-1][2] == f"best J {r['j']:.5f}"

    def boom(done, total, note):
        raise KeyboardInterrupt("stop")

    with pytest.raises(KeyboardInterrupt):
        aapat.optimize_sequence(frames=4, starts=3, progress=boom)


@pytest.mark.parametrize("key,distance", [
    ("jitter_bound", lambda j: np.abs(j).max(axis=1)),
    ("jitter_radius", lambda j: np.hypot(j[:, 0], j[:, 1]))])
def test_a_jitter_bound_or_radius_is_the_cli_s(aapat_cli, tmp_path, key, distance):
    out = str(tmp_path / "bounded.json")
    aapat_cli("optimize", "--sequence", "4", "--starts", "2", "--" + key.replace("_", "-"), "0.3",
              "-o", out)
    r = aapat.optimize_sequence(frames=4, starts=2, **{key: 0.3})
    with open(out) as f:
        assert r["result"].to_json() == f.read()
    assert r[key] == 0.3
    assert distance(np.array(json.loads(r["result"].to_json())["jitter"])).max() <= 0.3
    with pytest.raises(aapat.Error, match=key + " 0.8"):
        aapat.optimize_sequence(frames=4, starts=1, **{key: 0.8})


def test_no_radius_by_default_and_none_with_a_ratio():
    assert aapat.optimize_sequence(frames=4, starts=1)["jitter_radius"] is None
    with pytest.raises(aapat.Error, match="jitter_radius"):
        aapat.optimize_sequence(frames=18, starts=1, ratio=1.5, jitter_radius=0.3)


def test_bad_settings_raise_aapat_error():
    with pytest.raises(aapat.Error, match="alpha"):
        aapat.sequence_eval("halton:frames=4", alpha=0)
    with pytest.raises(aapat.Error, match="unknown sequence"):
        aapat.sequence("nothing")
