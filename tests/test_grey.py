"""Colours reduced to luminance grey (BT.709 Y = 0.2126 R + 0.7152 G + 0.0722 B).

ITU-R BT.709-6, item 3.2; docs/REFERENCES.md §Luminance of a colour. The weights
sum to 1, so a grey colour (g, g, g) has luminance g; the reader must keep
that exactly, or a furnace authored with albedo 0.9 would be traced with
0.8999999999999999 and a reference case would not be the stated one.
"""

import numpy as np
import pytest

from simulator.units import luminance_grey

_W = np.array([0.2126, 0.7152, 0.0722])


@pytest.mark.parametrize("g", [0.0, 0.18, 0.5, 0.8, 0.9, 0.95, 0.99, 1.0, 1e-30, 3.7, 1e6, 0.1 + 0.2])
def test_exact_grey_keeps_its_value(g):
    """(g, g, g) → g bit for bit: exactness is the property asserted (the
    plain dot product gives 0.8999999999999999 for g = 0.9)."""
    assert luminance_grey((g, g, g)) == g


def test_many_greys_and_float32_greys_stay_exact():
    """Every grey of a dense random set, in float64 and float32 (as USD's
    color3f is read), returns its own component; array input is reduced over
    the last axis."""
    rng = np.random.default_rng(7)
    g = rng.uniform(0.0, 1.0, 10_000)
    assert np.array_equal(luminance_grey(np.repeat(g[:, None], 3, axis=1)), g)
    g32 = g.astype(np.float32)
    assert np.array_equal(luminance_grey(np.repeat(g32[:, None], 3, axis=1)), g32.astype(np.float64))


def test_coloured_values_are_the_weighted_sum():
    """Primaries give their weights, and random colours the BT.709 weighted
    sum, within 1e-15 relative of the dot product."""
    assert luminance_grey((1, 0, 0)) == pytest.approx(0.2126, rel=1e-15)
    assert luminance_grey((0, 1, 0)) == pytest.approx(0.7152, rel=1e-15)
    assert luminance_grey((0, 0, 1)) == pytest.approx(0.0722, rel=1e-15)
    rng = np.random.default_rng(3)
    rgb = rng.uniform(0.0, 10.0, (1000, 3))
    np.testing.assert_allclose(luminance_grey(rgb), rgb @ _W, rtol=1e-15, atol=0)


def test_near_grey_stays_within_its_components():
    """A near-grey colour (components within 1e-9 of g) reads within its
    components' range: min ≤ Y ≤ max, so float noise in an authored grey
    never moves it outside what was authored."""
    rng = np.random.default_rng(11)
    g = rng.uniform(0.05, 0.99, (2000, 1))
    rgb = g + rng.uniform(-1e-9, 1e-9, (2000, 3))
    y = luminance_grey(rgb)
    assert np.all(y >= rgb.min(axis=1)) and np.all(y <= rgb.max(axis=1))


def test_one_colour_is_a_float_and_bad_shapes_are_refused():
    """A single colour returns a Python float; a shape without 3 channels is a ValueError."""
    assert type(luminance_grey([0.2, 0.4, 0.6])) is float
    with pytest.raises(ValueError):
        luminance_grey([0.2, 0.4])
