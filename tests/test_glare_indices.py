"""Glare indices as formulas: the position index, DGP, DGPs, UGR (docs/REFERENCES.md §Glare indices).

No tracing: the formulas of simulator.glare.indices against published values
and against their definitions written out again here.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from simulator.glare import indices as ix


def _direction(sigma_deg: float, tau_deg: float, view=np.array([1.0, 0.0, 0.0]), up=np.array([0.0, 0.0, 1.0])):
    """The unit direction at σ from the view, its projection τ from up (right = view × up)."""
    right = np.cross(view, up)
    s, t = math.radians(sigma_deg), math.radians(tau_deg)
    return math.cos(s) * view + math.sin(s) * (math.cos(t) * up + math.sin(t) * right)


# Luckiesh and Guth's position index for a source straight above the line of sight (T/R = 0), as tabulated
# in the IES Lighting Handbook and CIE 117-1995: H/R → P (docs/REFERENCES.md §Glare indices)
GUTH_TABLE_ABOVE = {0.0: 1.00, 0.1: 1.26, 0.2: 1.53, 0.3: 1.90, 0.4: 2.35, 0.5: 2.86, 0.6: 3.50, 0.7: 4.20, 0.8: 5.00,
                    0.9: 6.00, 1.0: 7.00}  # fmt: skip


@pytest.mark.parametrize("h_over_r,table", sorted(GUTH_TABLE_ABOVE.items()))
def test_position_index_matches_the_published_table(h_over_r, table):
    """Guth's formula (the IES Handbook's fit) at σ = atan(H/R), τ = 0 reproduces the tabulated index within
    3.5%: the fit's own departure from the table it was made from is up to ~3% (1.223 for the table's 1.26
    at H/R 0.1); evaluated through view_angles and position_index, as a source above the line of sight."""
    d = _direction(math.degrees(math.atan(h_over_r)), 0.0)
    p = float(ix.position_index(d, np.array([1.0, 0.0, 0.0]), np.array([0.0, 0.0, 1.0])))
    assert p == pytest.approx(table, rel=0.035)


def test_view_angles_of_constructed_directions():
    """σ and τ come back for directions built from them; below the line of sight is τ > 90°."""
    view, up = np.array([0.0, 1.0, 0.0]), np.array([0.0, 0.0, 1.0])
    for s, t in [(10, 0), (30, 45), (60, 90), (45, 135), (80, 180), (5, 170)]:
        d = _direction(s, t, view, up)
        sigma, tau, below = ix.view_angles(d, view, up)
        assert float(sigma) == pytest.approx(s, abs=1e-9) and float(tau) == pytest.approx(t, abs=1e-9)
        assert bool(below) == (t > 90)


def test_the_two_branches_meet_at_the_horizontal_plane():
    """At τ = 90° Guth's index is exp((35.2 − 28.7001 − 1.22e^−20)·10⁻³σ + 21·10⁻⁵σ²) and the lower one
    exp(6.49·10⁻³σ + 21·10⁻⁵σ²) (β = σ there): they differ by e^(10⁻⁵σ) − 1, 6·10⁻⁴ at σ = 60°."""
    for s in (5.0, 20.0, 40.0, 60.0):
        a = float(ix.position_index_guth(s, 90.0))
        b = float(ix.position_index_below(s, 90.0))
        assert a / b == pytest.approx(math.exp(9.9e-6 * s), rel=1e-6)
        assert b == pytest.approx(math.exp(6.49e-3 * s + 21e-5 * s * s), rel=1e-12)


def test_position_index_on_the_line_of_sight_and_its_cap():
    """P = 1 on the line of sight; far off it P is at most 16 (evalglare's cap); below the line of sight the
    lower form β = atan(tan σ·√(1 + 0.3225·cos²τ)) applies: straight below at σ = 30°, β = atan(1.15·tan 30°)."""
    view, up = np.array([1.0, 0.0, 0.0]), np.array([0.0, 0.0, 1.0])
    assert float(ix.position_index(view, view, up)) == pytest.approx(1.0, abs=1e-12)
    assert float(ix.position_index(_direction(85, 0), view, up)) == 16.0
    beta = math.degrees(math.atan(math.tan(math.radians(30)) * math.sqrt(1.3225)))
    expect = math.exp(6.49e-3 * beta + 21e-5 * beta**2)
    assert float(ix.position_index(_direction(30, 180), view, up)) == pytest.approx(expect, rel=1e-12)


def test_dgp_dgps_ugr_formulas():
    """DGP = 5.87e-5·E_v + 0.092·log10(1 + G/E_v^1.87) + 0.159 (evalglare's constants), capped at 1;
    low-light factor e^(0.024E − 4)/(1 + e^(0.024E − 4)) below 1000 lx; DGPs = 6.22e-5·E_v + 0.184;
    UGR = 8·log10(0.25·G/L_b), 0 without a source."""
    ev, g = 2000.0, 5.0e6
    expect = 5.87e-5 * ev + 0.092 * math.log10(1 + g / ev**1.87) + 0.159
    assert ix.dgp(ev, g) == pytest.approx(expect, rel=1e-14)
    assert ix.dgp(3e5, g) == 1.0 and ix.dgp(3e5, g, capped=False) > 1.0
    ev = 400.0
    f = math.exp(0.024 * ev - 4) / (1 + math.exp(0.024 * ev - 4))
    assert ix.dgp(ev, g, low_light=True) == pytest.approx(f * ix.dgp(ev, g), rel=1e-14)
    assert ix.low_light_factor(1000.0) == 1.0
    assert ix.dgps(1500.0) == pytest.approx(6.22e-5 * 1500 + 0.184, rel=1e-14)
    assert ix.ugr(50.0, 4.0e5) == pytest.approx(8 * math.log10(0.25 / 50.0 * 4.0e5), rel=1e-14)
    assert ix.ugr(50.0, 0.0) == 0.0 and math.isnan(ix.ugr(0.0, 1.0))
