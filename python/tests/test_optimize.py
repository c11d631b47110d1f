"""The optimizer and the enumeration from Python: the CLI's result for the
same seed, progress reported, the published optimum reached."""
import json
import os
import threading

import pytest

import aapat


def test_optimize_from_python_equals_the_cli_file(aapat_cli, tmp_path):
    out = str(tmp_path / "cli.json")
    aapat_cli("optimize", "--family", "P(1,1,4)", "--starts", "4", "--seed", "3", "-o", out)
    with open(out) as f:
        cli = f.read()
    py = aapat.optimize(family="P(1,1,4)", starts=4, seed=3)
    assert py.pattern.to_json() == cli
    assert json.loads(cli)["provenance"]["e2"] == f"{py.e2:.6f}"


def test_polishing_a_pattern_equals_the_cli(aapat_cli, tmp_path):
    out = str(tmp_path / "polished.json")
    aapat_cli("optimize", "flipquad", "--starts", "2", "-o", out)
    with open(out) as f:
        assert aapat.optimize(pattern="flipquad", starts=2).pattern.to_json() == f.read()


def test_the_best_p114_reaches_laine_aila_table_2_and_reports_progress():
    calls = []
    r = aapat.optimize(family="P(1,1,4)", starts=16, seed=1, objective="laine-aila",
                       progress=lambda done, total, note: calls.append((done, total)))
    assert r.e2 == pytest.approx(0.359, abs=0.001)
    assert calls and calls[-1] == (16, 16)
    assert len(r.starts["final_e2"]) == 16
    assert r.starts["final_e2"].min() == r.e2


def test_the_gil_is_released_while_it_runs():
    ticks = []
    stop = threading.Event()

    def count():
        while not stop.is_set():
            ticks.append(1)
            stop.wait(0.001)

    t = threading.Thread(target=count)
    t.start()
    aapat.optimize(family="P(4,4,4)", starts=4, seed=2, threads=1)  # ~0.2 s
    stop.set()
    t.join()
    assert len(ticks) > 5  # the other thread ran during the optimization


def test_a_progress_callback_that_raises_stops_the_run():
    def boom(done, total, note):
        raise KeyboardInterrupt("stop")

    with pytest.raises(KeyboardInterrupt):
        aapat.optimize(family="P(1,1,4)", starts=4, progress=boom)


def test_bad_settings_name_the_problem():
    with pytest.raises(aapat.Error, match=r"give either a family \(a search\) or a pattern"):
        aapat.optimize()
    with pytest.raises(aapat.Error, match="family: 'Q' is not of the form"):
        aapat.optimize(family="Q")
    with pytest.raises(aapat.Error, match="known methods are descent"):
        aapat.optimize(family="P(1,1,4)", method="newton")


def test_the_enumeration_counts_hasselgren_configurations():
    rows = aapat.enumerate(costs=[1.25, 1.5])
    by_n = {}
    for r in rows:
        by_n[r["n"]] = by_n.get(r["n"], 0) + 1
    cli_like = aapat.enumerate(costs=[1.25], optimize=True, starts=2, objective="laine-aila")
    assert all(r["e2"] is not None and r["pattern"].family == "P(4,1+,1.25)" for r in cli_like)
    assert by_n[1.25] == len(cli_like)
    assert sorted(r["e2"] for r in cli_like) == [r["e2"] for r in cli_like]
