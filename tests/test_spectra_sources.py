"""Emission spectra: Planck's law, CIE illuminants, light colours, SPD files, and their scale."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from simulator.errors import UserError
from simulator.spectra import grid, sources, tables
from simulator.units import K_M, emission_pair, luminance_grey

ROOT = Path(__file__).resolve().parents[1]


@pytest.mark.parametrize("t", [1500.0, 3000.0, 6500.0, 20000.0])
def test_blackbody_has_colour_sciences_shape(t):
    """A colour temperature here and colour-science's ``sd_blackbody`` (both
    with CIE 15's c₂ = 1.4388e-2 m K) have the same shape on the grid to 1e-7:
    the efficacies the engine uses for ``colorTemperature`` come from the latter."""
    import colour

    ours = sources.blackbody(t).values
    theirs = np.asarray(colour.sd_blackbody(t, colour.SpectralShape(380, 780, 1)).values, float)
    ratio = ours / theirs
    assert np.ptp(ratio) <= 1e-7 * ratio.mean()


def test_blackbody_integral_matches_stefan_boltzmann_beyond_the_grid():
    """Planck integrated over 50 nm – 1 mm (log-spaced trapezoid) is σT⁴/π to
    1e-4: the formula's constants are right, not only its shape."""
    from scipy import constants as sc

    wl = np.geomspace(50.0, 1e6, 200001)
    b = sources.planck_W_m2_sr_nm(3000.0, wl)
    assert np.trapezoid(b, wl) == pytest.approx(sc.sigma * 3000.0**4 / np.pi, rel=1e-4)


@pytest.mark.parametrize("units, spec", [("photometric", "D65"), ("radiometric", "E"), ("photometric", 3000.0),
                                         ("radiometric", "D65")])
def test_spectral_emission_integrates_to_the_engine_pair(units, spec):
    """The spectral density of a stated value has exactly the (radiometric,
    photometric) pair :func:`simulator.units.emission_pair` gives: ∫ S dλ and
    K_m ∫ V S dλ (K_m = 683.002 lm/W), to 1e-9 (UsdLux: the blackbody colour is luminance-normalised,
    so in photometric units a colour temperature changes only the spectrum)."""
    s = sources.emitter_spectrum(spec)
    density = sources.spectral_emission(250.0, units, s)
    w, lm = emission_pair(250.0, units, spec)
    assert grid.integrate(density) == pytest.approx(w, rel=1e-9)
    assert K_M * grid.integrate(density * tables.photopic()) == pytest.approx(lm, rel=1e-9)


def test_light_colour_modulates_its_white_spectrum():
    """White (1, 1, 1) on D65 is D65; grey (c, c, c) is c × the base exactly;
    a coloured light's luminance is the BT.709 luminance of its colour × the
    white's, to the uplift's round trip (1e-3)."""
    d65 = sources.cie_illuminant("D65")
    assert np.allclose(sources.colour_emission((1, 1, 1), d65).values, d65.values, rtol=1e-12, atol=0)
    assert np.allclose(sources.colour_emission((0.3, 0.3, 0.3), d65).values, 0.3 * d65.values, rtol=1e-12, atol=0)
    for rgb in [(1, 0, 0), (0, 1, 0), (0, 0, 1), (0.9, 0.5, 0.1)]:
        ratio = sources.colour_emission(rgb, d65).photometric / d65.photometric
        assert ratio == pytest.approx(luminance_grey(rgb), abs=1e-3)
    with pytest.raises(UserError):
        sources.colour_emission((1, -0.1, 0), d65)


@pytest.mark.parametrize("spec, name", [("D65", "D65"), ("A", "A"), ("FL2", "FL2"), ("LED-B3", "LED-B3"),
                                        ("3000K", "blackbody 3000 K"), ("blackbody:2700", "blackbody 2700 K"),
                                        (5000, "blackbody 5000 K"), ("E", "E")])
def test_emitter_spectrum_names(spec, name):
    """Every way a config or stage can name a spectrum gives a non-negative,
    non-zero shape on the grid."""
    s = sources.emitter_spectrum(spec)
    assert s.name == name and s.values.shape == grid.WAVELENGTHS_NM.shape
    assert s.values.min() >= 0 and s.radiometric > 0


def test_unknown_illuminant_suggests_the_nearest():
    with pytest.raises(UserError, match="unknown illuminant 'D66'.*'D65'"):
        sources.emitter_spectrum("D66")
    with pytest.raises(UserError, match="positive number of kelvin"):
        sources.emitter_spectrum(-5)


def test_spd_file_is_read_relative_and_noted_when_short(tmp_path):
    """A CSV path is relative to the base folder; a file that stops short of
    380–780 nm is 0 beyond its range, with a note; negative values are refused."""
    s = sources.emitter_spectrum("spectra/grow_led_spd.csv", ROOT / "stages")
    assert s.name == "grow_led_spd.csv" and not s.notes
    (tmp_path / "short.csv").write_text("wavelength_nm,relative_spd\n450,1\n650,1\n")
    short = sources.spd_csv(tmp_path / "short.csv")
    assert short.notes and short.values[grid.WAVELENGTHS_NM < 450].max() == 0.0
    # 1 from 450 to 650 nm, ramping to 0 over the 1 nm grid steps either side: 200 + 2 × 0.5
    assert grid.integrate(short.values) == pytest.approx(201.0, rel=1e-12)
    (tmp_path / "neg.csv").write_text("wavelength_nm,relative_spd\n450,1\n650,-1\n")
    with pytest.raises(UserError, match=r"neg\.csv:3: relative_spd -1 is negative"):
        sources.spd_csv(tmp_path / "neg.csv")
    (tmp_path / "col.csv").write_text("wavelength_nm,watts\n450,1\n650,1\n")
    with pytest.raises(UserError, match=r"col\.csv:1: SPD column 'watts'"):
        sources.spd_csv(tmp_path / "col.csv")


def test_spreadsheet_exports_are_read(tmp_path):
    """Quoted cells, a byte-order mark and trailing empty cells (a spreadsheet's
    CSV export) read like the plain file."""
    p = tmp_path / "export.csv"
    p.write_bytes('\ufeff"wavelength_nm","relative_spd",,\n380,1,,\n780,3,,\n'.encode("utf-8"))
    s = sources.spd_csv(p)
    assert grid.integrate(s.values) == pytest.approx(800.0, rel=1e-12)
