"""The grid map's PNG (simulator.io.map_png): cells drawn where they belong,
in the colour of their value, with round ticks."""

from __future__ import annotations

import io

import numpy as np
import pytest

from simulator.io.map_png import MARGINS_PX, NO_READING_RGB, SIZE_PX, VIRIDIS_9, colour_map, map_png, nice_ticks


def test_nice_ticks():
    """Steps of 1, 2, 2.5 or 5 × 10^k, within the range, at most 7."""
    assert nice_ticks(-0.6, 0.6) == pytest.approx([-0.6, -0.4, -0.2, 0.0, 0.2, 0.4, 0.6])
    assert nice_ticks(460.1, 794.4) == pytest.approx([500, 550, 600, 650, 700, 750])
    assert nice_ticks(0.0, 3.0) == pytest.approx([0.0, 0.5, 1.0, 1.5, 2.0, 2.5, 3.0])
    assert nice_ticks(2.0, 2.0) == [2.0]
    for lo, hi in [(-1.5, 1.5), (0.013, 0.0171), (1e3, 7.7e4)]:
        t = nice_ticks(lo, hi)
        assert 2 <= len(t) <= 7 and lo - 1e-12 <= t[0] and t[-1] <= hi + 1e-12


def test_colour_map_ends_and_gaps():
    """u = 0 and 1 give the map's end colours, u = 1/8 its second anchor,
    NaN the no-reading grey; brightness rises with u."""
    c = colour_map(np.array([0.0, 0.125, 1.0, np.nan, -1.0, 2.0]))
    assert np.array_equal(c[0], VIRIDIS_9[0]) and np.array_equal(c[1], VIRIDIS_9[1])
    assert np.array_equal(c[2], VIRIDIS_9[-1]) and tuple(c[3]) == NO_READING_RGB
    assert np.array_equal(c[4], c[0]) and np.array_equal(c[5], c[2])
    luma = colour_map(np.linspace(0, 1, 50)) @ np.array([0.2126, 0.7152, 0.0722])
    assert np.all(np.diff(luma) > 0)


def test_cells_are_drawn_in_place():
    """A 2 × 3 grid whose values rise along each row: the pixel at each
    cell's centre has that cell's colour (row 0 on top), and the picture is
    SIZE_PX with the map inside the margins."""
    from PIL import Image

    v = np.array([[0.0, 1.0, 2.0], [3.0, 4.0, np.nan]])
    png = map_png(v, (3.0, 2.0), ["t"], "x (lx)", "along right (m)", "along up (m)")
    img = np.asarray(Image.open(io.BytesIO(png)).convert("RGB"))
    assert img.shape == (SIZE_PX[1], SIZE_PX[0], 3)
    # the map's pixels: the colour of each cell, found at its centre
    u = v / 4.0
    expected = colour_map(u)
    avail_w = SIZE_PX[0] - MARGINS_PX["left"] - MARGINS_PX["right"]
    avail_h = SIZE_PX[1] - MARGINS_PX["top"] - MARGINS_PX["bottom"]
    scale = min(avail_w / 3.0, avail_h / 2.0)
    pw, ph = round(3.0 * scale), round(2.0 * scale)
    x0 = MARGINS_PX["left"] + (avail_w - pw) // 2
    y0 = MARGINS_PX["top"] + (avail_h - ph) // 2
    for r in range(2):
        for i in range(3):
            px = img[int(y0 + (r + 0.5) * ph / 2), int(x0 + (i + 0.5) * pw / 3)]
            assert np.array_equal(px, expected[r, i]), (r, i, px, expected[r, i])
