"""The point sets on the Python face (python/bind_points.cpp): generators, discrepancies, spectra."""
import math
from fractions import Fraction

import numpy as np
import pytest

import aapat


def test_generators_are_deterministic_and_in_the_square():
    a = aapat.generate("jittered", 64, seed=9)
    assert a.shape == (64, 2)
    np.testing.assert_array_equal(a, aapat.generate("jittered", 64, seed=9))
    assert ((a >= 0) & (a <= 1)).all()


def test_the_slow_generators_report_hundredths_and_give_the_same_points():
    for spec in ("poisson", "best-candidate", "poisson-maximal"):
        calls = []
        a = aapat.generate(spec, 400, seed=4,
                           progress=lambda done, total, note: calls.append((done, total)))
        np.testing.assert_array_equal(a, aapat.generate(spec, 400, seed=4))
        assert calls and all(total == 100 for _, total in calls), spec
        assert [d for d, _ in calls] == sorted(set(d for d, _ in calls)), spec  # rising
        assert calls[-1][0] >= 95, spec


def test_one_point_has_the_star_discrepancy_of_its_box():
    # One point at (1/2, 1/2): the worst anchored box is [0,1)^2 minus it, 3/4.
    d = aapat.discrepancy(np.array([[0.5, 0.5]]))
    assert d["star_is_exact"] and d["star_exact"] == d["star_upper"] == pytest.approx(0.75)


def test_a_utk_file_gives_the_discrepancy_of_the_same_points_in_csv(tmp_path):
    points = aapat.generate("halton", 200)
    aapat.write_points(str(tmp_path / "h.dat"), points)
    aapat.write_points(str(tmp_path / "h.csv"), points)
    a = aapat.discrepancy(aapat.read_points(str(tmp_path / "h.dat"))[0])
    b = aapat.discrepancy(aapat.read_points(str(tmp_path / "h.csv"))[0])
    assert a == b


def test_the_spectrum_of_white_noise_averages_one():
    s = aapat.spectrum("random", n=256, size=32, realizations=8)
    assert s["power"].shape == (32, 32)
    assert s["radial_power"][4:].mean() == pytest.approx(1.0, abs=0.15)
    one = aapat.spectrum(aapat.generate("random", 256), size=32)
    assert one["realizations"] == 1


def test_the_1d_jittered_spectrum_follows_one_minus_sinc_squared():
    # One uniform point per unit interval: expected power 1 - sinc^2(f) away from 0.
    s = aapat.spectrum_1d(["jittered"], n=8192, seed=4, frequencies=4096, max_frequency=4)
    f, p = s["frequency"], s["jittered"]
    for lo, hi in [(0.2, 0.4), (1.3, 1.7), (3.2, 3.8)]:  # (near whole f the strata line up)
        band = (f >= lo) & (f < hi)
        expected = 1 - np.sinc(f[band]) ** 2
        assert p[band].mean() == pytest.approx(expected.mean(), abs=0.1), (lo, hi)


def test_discrepancy_computes_only_the_measures_asked():
    d = aapat.discrepancy(aapat.generate("halton", 100000), measures="l2-star")
    assert set(d) == {"points", "l2_star"}
    with pytest.raises(aapat.Error, match="measure 'x'"):
        aapat.discrepancy(aapat.generate("halton", 10), measures="x")


def test_discrepancy_every_l2_kind():
    d = aapat.discrepancy(aapat.generate("halton", 1000), measures="all")
    assert {"l2_star", "l2_generalized", "l2_centred", "l2_wrap_around", "l2_unanchored",
            "l2_symmetric", "star_lower", "star_gap", "edge"} <= set(d)
    # One point at the centre: the centred discrepancy is sqrt((13/12)^2 - 1) = 5/12.
    centre = aapat.discrepancy(np.array([[0.5, 0.5]]), measures="l2-centered")
    assert centre["l2_centred"] == pytest.approx(5 / 12, rel=1e-15)


def test_fast_spectrum_within_its_bound_of_the_exact_one():
    points = aapat.generate("poisson", 2000, seed=3)
    fast = aapat.spectrum(points, size=64, method="fast")
    exact = aapat.spectrum(points, size=64)
    assert exact["error_bound"] == 0
    assert 0 < fast["error_bound"] < 1e-6
    assert np.max(np.abs(fast["power"] - exact["power"])) <= fast["error_bound"]
    with pytest.raises(aapat.Error, match="method 'nufft'"):
        aapat.spectrum(points, size=64, method="nufft")


def mixture_squared_exactly(x):
    """Zhou, Fang & Ning's mixture discrepancy squared, MD^2, as
    scipy.stats.qmc writes it, in exact rational arithmetic (x: Fractions)."""
    n = len(x)
    half = Fraction(1, 2)
    single = 0
    for p in x:
        term = 1
        for c in p:
            term *= Fraction(5, 3) - abs(c - half) / 4 - abs(c - half) ** 2 / 4
        single += term
    pairs = 0
    for p in x:
        for q in x:
            term = 1
            for a, b in zip(p, q):
                term *= (Fraction(15, 8) - abs(a - half) / 4 - abs(b - half) / 4
                         - 3 * abs(a - b) / 4 + abs(a - b) ** 2 / 2)
            pairs += term
    return Fraction(19, 12) ** 2 - 2 * single / n + pairs / n ** 2


def test_mixture_discrepancy_is_exact_rational_arithmetic_on_small_sets():
    rng = np.random.default_rng(11)
    for n in (1, 2, 5, 12):
        grid = rng.integers(0, 65, size=(n, 2))  # on a grid of 1/64: ties and centre lines
        exact = mixture_squared_exactly([[Fraction(int(v), 64) for v in p] for p in grid])
        got = aapat.discrepancy(grid / 64.0, measures="l2-mixture")["l2_mixture"]
        assert abs(got ** 2 - float(exact)) <= 1e-13 * float(exact), n


def test_mixture_discrepancy_agrees_with_a_compensated_pairwise_sum():
    """3,000 arbitrary points: the O(N^2) sum in float64, compensated (math.fsum)."""
    x = np.random.default_rng(5).random((3000, 2))
    g = np.abs(x - 0.5)
    single = math.fsum(np.prod(5 / 3 - g / 4 - g * g / 4, axis=1))
    pair = np.ones((len(x), len(x)))
    for k in range(2):
        d = np.abs(x[:, k][:, None] - x[:, k][None, :])
        pair *= 15 / 8 - g[:, k][:, None] / 4 - g[:, k][None, :] / 4 - 3 * d / 4 + d * d / 2
    n = len(x)
    md2 = (19 / 12) ** 2 - 2 * single / n + math.fsum(pair.ravel()) / n ** 2
    got = aapat.discrepancy(x, measures="l2-mixture")["l2_mixture"]
    assert abs(got ** 2 - md2) <= 1e-9 * md2
