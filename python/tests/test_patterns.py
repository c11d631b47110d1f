"""Patterns and point sets cross into numpy and back exactly, and the
vectorized evaluation equals one-by-one evaluation."""
import numpy as np
import pytest

import aapat


def random_pattern_array(rng, n):
    return rng.random((n, 2)) - 0.5


def test_a_pattern_round_trips_through_numpy_exactly():
    rng = np.random.default_rng(7)
    xy = random_pattern_array(rng, 6)
    w = rng.random(6) + 0.1
    w /= w.sum()  # a pattern's weights sum to 1
    p = aapat.Pattern(xy, w, name="mine")
    np.testing.assert_array_equal(p.sets[0], xy)
    np.testing.assert_array_equal(p.weights[0], w)
    again = aapat.Pattern(p.sets[0], p.weights[0], name="again")
    np.testing.assert_array_equal(again.sets[0], xy)
    assert p.family == "P(1,1,6)"


def test_a_pattern_round_trips_through_its_json_and_both_files(tmp_path):
    p = aapat.pattern("hasselgren-f")
    back = aapat.Pattern.from_json(p.to_json())
    for a, b in zip(p.sets, back.sets):
        np.testing.assert_array_equal(a, b)
    path = str(tmp_path / "f.json")
    p.save(path)
    assert aapat.load_pattern(path).to_json() == p.to_json()
    rgss = aapat.pattern("rgss")
    xyw = str(tmp_path / "rgss.xyw")
    aapat.save_pattern(rgss, xyw)
    np.testing.assert_array_equal(aapat.load_pattern(xyw).sets[0], rgss.sets[0])


def test_vectorized_eval_equals_one_by_one():
    rng = np.random.default_rng(3)
    xy = rng.random((200, 4, 2)) - 0.5
    w = rng.random((200, 4)) + 0.5
    w /= w.sum(axis=1, keepdims=True)
    batch = aapat.eval(xy, weights=w)
    single = [aapat.eval(aapat.Pattern(xy[i], w[i])) for i in range(200)]
    np.testing.assert_array_equal(batch, single)
    assert batch.shape == (200,)


def test_bad_arrays_are_refused():
    with pytest.raises(aapat.Error, match=r"\(m, n, 2\)"):
        aapat.eval(np.zeros((3, 4, 3)))
    with pytest.raises(aapat.Error, match="sample 0 x = nan is not finite"):
        aapat.eval(np.full((1, 2, 2), np.nan))
    with pytest.raises(aapat.Error, match="weights must be"):
        aapat.eval(np.zeros((2, 4, 2)), weights=np.ones(3))


def test_point_sets_round_trip_through_every_format(tmp_path):
    points = aapat.generate("best-candidate", 128, seed=5)
    for ext in ["csv", "dat", "bin", "psa"]:
        path = str(tmp_path / f"p.{ext}")
        aapat.write_points(path, points)
        np.testing.assert_array_equal(aapat.read_points(path)[0], points)
    path = str(tmp_path / "p.f32")
    aapat.write_points(path, points)
    np.testing.assert_array_equal(aapat.read_points(path)[0], points.astype(np.float32))
    safari = str(tmp_path / "s.csv")
    aapat.write_points(safari, points, format="safari")
    np.testing.assert_array_equal(aapat.read_points(safari, format="safari")[0], points)
    sets = [aapat.generate("jittered", 16, seed=s) for s in range(3)]
    aapat.write_points(str(tmp_path / "many.dat"), sets)
    back = aapat.read_points(str(tmp_path / "many.dat"))
    assert len(back) == 3
    for a, b in zip(sets, back):
        np.testing.assert_array_equal(a, b)


def test_the_vectorized_profile_matches_each_patterns_profile():
    xy = np.random.default_rng(5).random((30, 3, 2)) - 0.5
    batch = aapat.profile(xy, objective="laine-aila", acuity="uniform:step=10")  # the maximum
    assert batch["values"].shape == (30, 18)
    np.testing.assert_array_equal(batch["values"].max(axis=1), batch["e2"])
    one = aapat.profile(aapat.Pattern(xy[7]), objective="laine-aila", acuity="uniform:step=10")
    np.testing.assert_allclose(one["values"][0], batch["values"][7], rtol=1e-12)


def test_arrays_of_the_wrong_shape_are_named_with_their_shape():
    with pytest.raises(aapat.Error, match=r"expected an \(n, 2\) array of x, y, not shape \(3, 3\)"):
        aapat.Pattern(np.zeros((3, 3)))
    with pytest.raises(aapat.Error, match="no point set given"):
        aapat.spectrum([], size=16)
