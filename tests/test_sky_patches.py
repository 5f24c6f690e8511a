"""Tregenza's sky patches and the CIE skies as patch luminances (simulator.study.inputs.sky_patches)."""

import math

import numpy as np
import pytest

from simulator.study.inputs import sky_patches as sp


def test_patch_counts_and_solid_angles():
    """145 patches: 30, 30, 24, 24, 18, 12, 6 in the 12° bands and the cap (Tregenza 1987).
    Each patch's solid angle (2π/n)(sin a₁ − sin a₀) sums to the hemisphere's 2π, and its
    projected solid angle (π/n)(sin²a₁ − sin²a₀) to π (a horizontal receiver under a sky of
    radiance 1 reads π); both to 1e-12."""
    assert sp.BAND_COUNTS == (30, 30, 24, 24, 18, 12, 6, 1)
    assert sp.N_PATCHES == 145
    omega = np.array([sp.patch_solid_angle(p) for p in range(145)])
    proj = np.array([sp.patch_projected_solid_angle(p) for p in range(145)])
    assert abs(omega.sum() - 2 * math.pi) < 1e-12
    assert abs(proj.sum() - math.pi) < 1e-12
    # the cap: 2π(1 − sin 84°)
    assert abs(omega[144] - 2 * math.pi * (1 - math.sin(math.radians(84)))) < 1e-12


def test_patch_index_round_trip():
    """Each patch's centre direction maps back to that patch; directions drawn uniformly on the
    hemisphere land in each patch in proportion to its solid angle (chi-square, 144 dof, below
    the 0.999 quantile 206); below the horizon is the ground slot 145."""
    for p in range(145):
        assert int(sp.patch_index(sp.patch_direction(p))) == p
    rng = np.random.default_rng(3)
    n = 400_000
    z = rng.random(n)
    phi = 2 * math.pi * rng.random(n)
    r = np.sqrt(1 - z**2)
    d = np.stack([r * np.cos(phi), r * np.sin(phi), z], axis=-1)
    counts = np.bincount(sp.patch_index(d), minlength=146)
    assert counts[145] == 0
    expect = n * np.array([sp.patch_solid_angle(p) for p in range(145)]) / (2 * math.pi)
    chi2 = float(np.sum((counts[:145] - expect) ** 2 / expect))
    assert chi2 < 206.0
    assert int(sp.patch_index(np.array([0.3, 0.2, -0.1]))) == sp.GROUND


def test_patch_azimuth_convention():
    """Patch 0 is centred on north (+Y) and azimuth runs toward east (+X), as the study's sun
    (simulator.study.inputs.sun): in the horizon band of 30 patches 12° wide, a direction at azimuth 12°
    (north-north-east) is patch 1, one at −12° (west of north) the band's last, 29, and due east
    (90°, +X) is patch 90/12 = 7.5 → the boundary; at 93° it is patch 8."""
    a = math.radians(12.0)
    assert int(sp.patch_index(np.array([math.sin(a), math.cos(a), 0.05]))) == 1
    a = math.radians(-12.0)  # west of north: the band's last patch
    assert int(sp.patch_index(np.array([math.sin(a), math.cos(a), 0.05]))) == 29
    a = math.radians(93.0)
    assert int(sp.patch_index(np.array([math.sin(a), math.cos(a), 0.05]))) == 8


def test_overcast_zenith_horizon_ratio():
    """The traditional CIE overcast sky L ∝ (1 + 2 sin γ)/3 is 3 times brighter at the zenith than
    at the horizon (exactly); the ISO 15469 type 1 sky, φ(0)/φ(90°) = 1 + 4e^{−0.7} = 2.986, within 0.5%."""
    zen, hor = np.array([0.0, 0.0, 1.0]), np.array([1.0, 0.0, 1e-12])
    assert abs(sp.overcast_luminance(zen) / sp.overcast_luminance(hor) - 3.0) < 1e-9
    r1 = sp.general_sky_luminance(1, zen, None) / sp.general_sky_luminance(1, np.array([1.0, 0.0, 1e-6]), None)
    assert abs(r1 - (1 + 4 * math.exp(-0.7))) < 1e-9
    assert abs(r1 / 3.0 - 1.0) < 0.005


def test_overcast_weights_horizontal_illuminance():
    """A horizontal receiver under the overcast sky reads 7π L_z/9
    (docs/REFERENCES.md §CIE standard overcast sky). The cosine-weighted integral over each patch
    (the same midpoint cells) sums to it to 1e-4 (the midpoint rule's error on the quadratic
    cosθ·(1 + 2cosθ), 12 cells a side: 3e-5); the 145-patch sky, each patch at its mean
    luminance, gives Σ L̄_p ∫_p cosθ dω, 0.42% low (the sky is piecewise constant over 12° bands,
    where L and cosθ both rise with altitude): asserted between 0.2% and 0.6% low, so the patch
    sky's discretisation is known, not hidden."""
    rel = sp.patch_means(sp.overcast_luminance)
    proj = np.array([sp.patch_projected_solid_angle(p) for p in range(145)])
    exact = 7 * math.pi / 9
    weighted = sp.patch_means(lambda d: sp.overcast_luminance(d) * d[..., 2])
    omega = np.array([sp.patch_solid_angle(p) for p in range(145)])
    assert abs(float(weighted @ omega) / exact - 1.0) < 1e-4
    low = 1.0 - float(rel @ proj) / exact
    assert 0.002 < low < 0.006


def test_clear_sky_brightest_near_sun():
    """CIE type 12 (clear sky): the patch around the sun is the brightest of its band and
    brighter than the zenith; the sky is 1 at the zenith relative to itself."""
    sun = np.array([math.sin(math.radians(200)) * math.cos(math.radians(40)),
                    math.cos(math.radians(200)) * math.cos(math.radians(40)), math.sin(math.radians(40))])
    w = sp.sky_weights(12, sun)
    p_sun = int(sp.patch_index(sun))
    band = [p for p in range(145) if sp._band_of(p) == sp._band_of(p_sun)]
    assert p_sun == band[int(np.argmax(w[band]))]
    assert w[p_sun] > w[144]
    assert abs(float(sp.general_sky_luminance(12, np.array([0.0, 0.0, 1.0]), sun)) - 1.0) < 1e-12
    with pytest.raises(ValueError):
        sp.general_sky_luminance(12, np.array([0.0, 0.0, 1.0]), None)


def test_sky_weights_scale():
    """Weights are scaled so Σ d_p ∫_p cosθ dω = π (as much horizontal light as the uniform dome):
    the uniform sky's weights are all 1."""
    assert np.allclose(sp.sky_weights("uniform", None), 1.0, atol=1e-12)
    proj = np.array([sp.patch_projected_solid_angle(p) for p in range(145)])
    assert abs(float(sp.sky_weights("overcast", None) @ proj) - math.pi) < 1e-12
