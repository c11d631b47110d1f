"""Rendering on the Python face (python/bind_render.cpp): images as arrays and their figures."""
import math
from fractions import Fraction

import numpy as np
import pytest

import aapat


def test_render_gives_an_image_array_and_the_error_figures():
    r = aapat.render("disc", pattern="rgss", size=(48, 32), reference=True, reference_samples=64)
    assert r["image"].shape == (32, 48)
    assert 0 <= r["image"].min() and r["image"].max() <= 1
    assert r["rmse"] > 0 and r["max_deviation"] >= 1
    assert r["reference_image"].shape == (32, 48)
    assert r["reference"] == "64 jittered samples per pixel, mitchell:b=1/3,c=1/3"
    with pytest.raises(aapat.Error, match="give either a pattern or a per-pixel generator"):
        aapat.render("disc")


def test_render_textured_multisampled_and_adaptive():
    flat = aapat.render("checkerboard", pattern="rgss", size=(32, 32))
    textured = aapat.render("checkerboard", pattern="rgss", size=(32, 32), texture="checker")
    # The 8 x 8 checker repeating every 8 squares is the checkerboard itself.
    assert np.array_equal(flat["image"], textured["image"])
    multi = aapat.render("checkerboard", pattern="rgss", size=(32, 32), texture="checker",
                         options={"mode": "multisample", "texture-filter": "trilinear"})
    assert 0.5 < multi["lookups_per_pixel"] <= 1
    assert not np.array_equal(multi["image"], flat["image"])
    refined = aapat.render("spiral", generator="jittered", samples=4, filter="box", size=(32, 32),
                           options={"adaptive": "contrast", "threshold": 0.1})
    assert refined["refinement_map"].shape == (32, 32)
    assert refined["adaptive"]["evaluations"] == refined["refinement_map"].sum()
    with pytest.raises(aapat.Error, match="unknown texture filter .cubic."):
        aapat.render("checkerboard", pattern="rgss", options={"texture-filter": "cubic"})
