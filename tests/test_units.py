"""Photometry: luminous efficacies and emission pairs (docs/REFERENCES.md §Photometry)."""

import pytest

from simulator.units import NAMED_EFFICACY, efficacy_from_tables, emission_pair, luminance_grey, luminous_efficacy


@pytest.mark.parametrize("name, published", [("D65", 205.15), ("E", 182.46)])
def test_named_efficacies_equal_the_tables(name, published):
    """K(S) = K_m·∫V·S/∫S (K_m = 683.002 lm/W) over 380–780 nm at 1 nm, trapezoid rule, CIE 1924
    V(λ): the constants a run uses must be what the tables give (to 1e-12),
    and match the published ≈205.15 lm/W (D65) and ≈182.46 lm/W (equal energy)."""
    assert NAMED_EFFICACY[name] == pytest.approx(efficacy_from_tables(name), rel=1e-12)
    assert luminous_efficacy(name) == pytest.approx(published, abs=0.005)


def test_blackbody_efficacy_peaks_near_6600_K():
    """Within 380–780 nm, a blackbody's efficacy rises with temperature up to
    roughly 6,600 K and falls beyond: 3000 K < 6600 K > 20000 K."""
    k3, k66, k20 = (luminous_efficacy(t) for t in (3000.0, 6600.0, 20000.0))
    assert k3 < k66 > k20


def test_emission_pairs_are_twins():
    """Photometric = radiometric × K(S) whichever unit the stage states."""
    w, lm = emission_pair(100.0, "photometric", "D65")
    assert lm == 100.0 and w == pytest.approx(100.0 / 205.152647, rel=1e-6)
    w, lm = emission_pair(2.0, "radiometric", "E")
    assert w == 2.0 and lm == pytest.approx(2.0 * 182.457836, rel=1e-6)
    assert luminance_grey((1.0, 1.0, 1.0)) == pytest.approx(1.0)


def test_km_is_the_si_efficacy_over_v_at_540_THz():
    """K_m = 683.002 lm/W (CIE 018:2019) is K_cd / V(555.016 nm), K_cd = 683 lm/W
    exactly at 540 THz (the SI) and 555.016 nm its wavelength in standard air:
    V linearly interpolated from the CIE 1924 table there gives 683.0016, so
    K_m agrees to its three decimals (±0.0005), and 683 itself does not."""
    import numpy as np

    from simulator.spectra import grid, tables
    from simulator.spectra.sources import K_M_LM_W
    from simulator.units import K_CD, K_M

    km = K_CD / np.interp(555.016, grid.WAVELENGTHS_NM, tables.photopic())
    assert K_CD == 683.0 and K_M == K_M_LM_W == 683.002
    assert abs(km - K_M) <= 0.0005 and abs(km - 683.0) > 0.0015
