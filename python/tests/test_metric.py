"""The published E2 values of both papers, through aapat.eval: the same
numbers, tables and tolerance (0.001, one unit of the papers' last digit) the
C++ tests pin (src/aapat/generate/catalog_test.cpp)."""
import numpy as np
import pytest

import aapat

LAINE_AILA_TABLE_2 = {"box2x2": 0.698, "rgss": 0.439, "quincunx": 0.518, "flipquad": 0.364,
                      "fliptri": 0.636}
HASSELGREN_TABLE_2 = {"centroid": 1.256, "diagonal-hasselgren": 0.692, "hasselgren-a": 0.554,
                      "hasselgren-b": 0.531, "hasselgren-c": 0.527, "hasselgren-d": 0.497,
                      "hasselgren-e": 0.488, "quincunx-hasselgren": 0.484, "hasselgren-f": 0.359}


@pytest.mark.parametrize("name,e2", sorted({**LAINE_AILA_TABLE_2, **HASSELGREN_TABLE_2}.items()))
def test_published_e2(name, e2):
    assert aapat.eval(name, objective="laine-aila") == pytest.approx(e2, abs=0.001)


def test_a_list_gives_an_array_in_order():
    names = list(LAINE_AILA_TABLE_2)
    np.testing.assert_allclose(aapat.eval(names, objective="laine-aila"),
                               list(LAINE_AILA_TABLE_2.values()), atol=0.001)


def test_rgss_as_an_array_equals_the_catalog_pattern():
    rgss = aapat.pattern("rgss")
    assert aapat.eval(rgss.sets[0]) == aapat.eval("rgss")


def test_the_l2_mean_is_below_the_maximum_and_a_uniform_table_changes_e2():
    papers = aapat.eval("rgss", objective="laine-aila")
    assert aapat.eval("rgss", objective="laine-aila", norm=2) < papers
    assert aapat.eval("rgss", objective="laine-aila", acuity="uniform:step=1") != papers
    # The default is the recommended objective, which the overrides spell out.
    assert aapat.eval("rgss") == aapat.eval("rgss", objective="laine-aila",
                                            acuity="uniform:step=1", norm=2)


def test_the_profile_peaks_at_e2():
    prof = aapat.profile("flipquad", objective="laine-aila")
    assert prof["values"].shape == (4, 4)
    assert prof["values"].max() == pytest.approx(prof["e2"], rel=1e-12)
    assert prof["e2"] == pytest.approx(0.364, abs=0.001)


def test_bad_specs_raise_aapat_error_with_the_library_message():
    with pytest.raises(aapat.Error, match="unknown filter 'nosuch'"):
        aapat.eval("rgss", filter="nosuch")
    with pytest.raises(ValueError, match="filter mitchell: unknown parameter 'q=1'"):
        aapat.eval("rgss", filter="mitchell:q=1")
    with pytest.raises(aapat.Error, match="unknown pattern 'teapot'"):
        aapat.eval("teapot")
