"""Sensor responses: PAR photon flux per watt, CIE S 026 α-opic EDIs, scotopic K′m, custom responsivity CSVs.

PAR photon flux per radiometric watt (µmol/J), checked below against
independent integrals:

* blackbody 3000 K: 3.1798 per W in 380–780 nm, 4.9787 per W in 400–700 nm, 0.40287 per total W;
* blackbody 5000 K: 3.5782, 4.6434, 1.4681;
* CIE D65: 3.6966 per W in 380–780 nm, 4.5285 per W in 400–700 nm.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
from scipy import constants as sc
from scipy.integrate import quad

from simulator.errors import UserError
from simulator.spectra import grid, responses as R, sources, tables
from simulator.units import K_CD, K_M, NAMED_EFFICACY

LED_SPD = Path(__file__).resolve().parents[1] / "stages" / "spectra" / "grow_led_spd.csv"


def _planck(lam_nm: float, t: float) -> float:
    """Planck spectral radiance per nm from scipy's CODATA constants (written independently of sources.py)."""
    lam = lam_nm * 1e-9
    return 2 * sc.h * sc.c**2 / lam**5 / np.expm1(sc.h * sc.c / (lam * sc.k * t)) * 1e-9


def _photons_umol(lam_nm: float) -> float:
    """µmol of photons per joule at λ: λ / (h c N_A) · 1e6."""
    return lam_nm * 1e-9 / (sc.h * sc.c * sc.N_A) * 1e6


@pytest.mark.parametrize("t, per_w, per_par_w, per_total_w", [
    (3000.0, 3.1798, 4.9787, 0.40287),
    (5000.0, 3.5782, 4.6434, 1.4681),
])  # fmt: skip
def test_ppfd_per_watt_of_a_blackbody_matches_the_integral(t, per_w, per_par_w, per_total_w):
    """PPFD per watt of a Planckian radiator, three ways (µmol/J):

    ``∫_400^700 B_λ λ/(h c N_A) dλ · 1e6`` over ``∫_380^780 B_λ dλ`` (probesim's
    radiometric W), over ``∫_400^700 B_λ dλ`` (PAR watts) and over
    ``σ T⁴ / π`` (all wavelengths, Stefan–Boltzmann). The reference is
    adaptive quadrature (scipy ``quad``) of Planck's law written from scipy's
    CODATA constants; the response is the 1 nm trapezoid rule: they agree to
    1e-5. 3000 K: 3.1798, 4.9787, 0.40287 µmol/J; 5000 K: 3.5782, 4.6434,
    1.4681 µmol/J. A *colour temperature* (CIE 15's c₂ = 1.4388e-2 m K, what
    ``colorTemperature`` uses) gives the same per-W figures to 1e-5."""
    par = R.response("par")
    b = sources.planck_W_m2_sr_nm(t, grid.WAVELENGTHS_NM)
    photons = quad(lambda x: _planck(x, t) * _photons_umol(x), 400, 700, epsabs=0, epsrel=1e-12)[0]
    w_all = quad(lambda x: _planck(x, t), 380, 780, epsabs=0, epsrel=1e-12)[0]
    w_par = quad(lambda x: _planck(x, t), 400, 700, epsabs=0, epsrel=1e-12)[0]
    total = sc.sigma * t**4 / np.pi
    assert par.of(b) / grid.integrate(b) == pytest.approx(photons / w_all, rel=1e-5)
    assert par.of(b) / grid.integrate(b, 400, 700) == pytest.approx(photons / w_par, rel=1e-5)
    assert par.of(b) / total == pytest.approx(photons / total, rel=1e-5)
    assert photons / w_all == pytest.approx(per_w, abs=5e-5)
    assert photons / w_par == pytest.approx(per_par_w, abs=5e-5)
    assert photons / total == pytest.approx(per_total_w, abs=5e-5)
    ct = sources.blackbody(t).values
    assert par.of(ct) / grid.integrate(ct) == pytest.approx(photons / w_all, rel=1e-5)


def test_ppfd_per_watt_of_d65_matches_the_5_nm_table():
    """D65: 3.6966 µmol/J per radiometric W (380–780 nm), 4.5285 per PAR watt.

    Independent integral: the trapezoid rule on colour-science's CIE D65
    table at its own 5 nm steps, ``Σ D65 λ/(h c N_A)`` over 400–700 nm; the
    response integrates D65 interpolated to 1 nm. Agreement 1e-5."""
    import colour

    d65 = colour.SDS_ILLUMINANTS["D65"]
    wl = np.arange(380.0, 781.0, 5.0)
    v = np.asarray(d65[wl], float)
    inside = (wl >= 400) & (wl <= 700)
    photons = np.trapezoid(v[inside] * _photons_umol(wl[inside]), wl[inside])
    watts = np.trapezoid(v, wl)
    s = sources.cie_illuminant("D65").values
    par = R.response("par")
    assert par.of(s) / grid.integrate(s) == pytest.approx(photons / watts, rel=1e-5)
    assert photons / watts == pytest.approx(3.6966, abs=5e-5)
    assert par.of(s) / grid.integrate(s, 400, 700) == pytest.approx(4.5285, abs=5e-5)


def test_epar_counts_400_to_750_nm():
    """ePAR adds the photons of 700–750 nm: for a flat spectrum the difference
    is ``∫_700^750 λ dλ / (h c N_A) · 1e6`` per W/nm, in closed form."""
    e = np.ones_like(grid.WAVELENGTHS_NM)
    extra = (750**2 - 700**2) / 2 * 1e-9 / (sc.h * sc.c * sc.N_A) * 1e6
    assert R.response("epar").of(e) - R.response("par").of(e) == pytest.approx(extra, rel=1e-9)


@pytest.mark.parametrize("alpha, published_mW_lm", [
    ("s_cone", 0.8173), ("m_cone", 1.4558), ("l_cone", 1.6289), ("rhodopic", 1.4497), ("melanopic", 1.3262),
])  # fmt: skip
def test_d65_elrs_match_cie_s026_table_2(alpha, published_mW_lm):
    """K_α,v^D65 = ∫ s_α D65 / (K_m ∫ V D65), K_m = 683.002 lm/W,, computed from the tables, equals
    CIE S 026:2018 Table 2 to its 4 decimals (half a unit: 5e-5 mW/lm)."""
    assert 1e3 * R.d65_elr_W_lm(alpha) == pytest.approx(published_mW_lm, abs=5e-5)


@pytest.mark.parametrize("alpha", R.ALPHA_OPIC)
def test_edi_under_d65_equals_the_illuminance(alpha):
    """CIE S 026's definition: the α-opic equivalent daylight (D65) illuminance
    of D65 light is its illuminance, at any level (here 1234 × the table)."""
    e = 1234.0 * sources.cie_illuminant("D65").values
    assert R.response(f"{alpha}_edi").of(e) == pytest.approx(R.response("photopic").of(e), rel=1e-12)


def test_melanopic_edi_differs_from_lux_away_from_d65():
    """Under illuminant A (2856 K) the melanopic DER, EDI/lux, is well below 1
    (warm light): it is ``K_mel(A)/K_mel(D65)``, here computed both ways."""
    a = sources.cie_illuminant("A").values
    der = R.response("melanopic_edi").of(a) / R.response("photopic").of(a)
    k_a = R.response("melanopic").of(a) / R.response("photopic").of(a)
    assert der == pytest.approx(k_a / R.d65_elr_W_lm("melanopic"), rel=1e-12)
    assert 0.3 < der < 0.6


def test_photopic_response_equals_the_engine_twin():
    """The photopic response per radiometric W of D65 and of E is the efficacy
    the engine's photometric twin uses (simulator.units), to 1e-12."""
    for name in ("D65", "E"):
        s = sources.emitter_spectrum(name).values
        assert R.response("photopic").of(s) / grid.integrate(s) == pytest.approx(NAMED_EFFICACY[name], rel=1e-12)


def test_scotopic_constant_is_km_over_v_prime_at_540_THz():
    """K′_m = 1700.06 lm/W (CIE) is K_m / V′(555.016 nm): V′ linearly
    interpolated from the CIE 1951 table at 555.016 nm gives 1700.06 ± 0.01;
    the older 1699 lm/W is K_m / V′(555 nm)."""
    vp = tables.scotopic()
    assert K_CD / np.interp(555.016, grid.WAVELENGTHS_NM, vp) == pytest.approx(R.K_PRIME_M_LM_W, abs=0.01)
    assert K_CD / np.interp(555.0, grid.WAVELENGTHS_NM, vp) == pytest.approx(1699.0, abs=0.01)


def _write(path, header, rows):
    path.write_text("# a datasheet\n" + header + "\n" + "\n".join(f"{a},{b}" for a, b in rows) + "\n")
    return path


def test_custom_responsivity_equal_to_v_reproduces_photopic(tmp_path):
    """A responsivity CSV of K_m·V(λ) lm/W (absolute, K_m = 683.002) at 1 nm reads exactly the
    photopic value of any spectrum (D65, a blackbody, the greenhouse LED); a
    *relative* V(λ) (any scale) reads the photopic value / K_m."""
    v = tables.photopic()
    wl = grid.WAVELENGTHS_NM
    absolute = R.custom_response(_write(tmp_path / "v.csv", "wavelength_nm,responsivity_lm_W", zip(wl, K_M * v)), "vdiode")
    relative = R.custom_response(_write(tmp_path / "r.csv", "wavelength_nm,responsivity", zip(wl, 5 * v)), "vrel")
    assert absolute.columns("irradiance") == ("vdiode_lm_m2", "vdiode_stderr_lm_m2")
    assert relative.columns("flux") == ("vrel_W", "vrel_stderr_W")
    for s in (sources.cie_illuminant("D65"), sources.blackbody(3000), sources.spd_csv(LED_SPD)):
        ph = R.response("photopic").of(s.values)
        assert absolute.of(s.values) == pytest.approx(ph, rel=1e-9)
        assert relative.of(s.values) == pytest.approx(ph / K_M, rel=1e-4)  # V's table peak is 1 at 555 nm to 1e-4


@pytest.mark.parametrize("header, rows, fragment", [
    ("wavelength_nm,responsivity_A_W", [(400, 0.1), (390, 0.2)], ":4: wavelength 390 nm is not above the previous (400 nm)"),
    ("wavelength_nm,responsivity_A_W", [(400, 0.1), (410, -0.2)], ":4: responsivity_A_W -0.2 is negative"),
    ("wavelength_nm,responsivity_A_W", [(400, 0.1), (410, "x")], ":4: not a number"),
    ("wavelength_nm,current", [(400, 0.1), (410, 0.2)], ":2: responsivity column 'current': expected"),
    ("nm,responsivity", [(400, 0.1), (410, 0.2)], ":2: responsivity header must be 'wavelength_nm,<column>'"),
    ("wavelength_nm,responsivity", [(0.4, 0.1), (0.41, 0.2)], ":3: wavelength 0.4 nm is outside"),
    ("wavelength_nm,responsivity", [(900, 0.1), (1000, 0.2)], "outside 380–780 nm"),
    ("wavelength_nm,responsivity", [(400, 0.0), (410, 0.0)], "zero everywhere"),
    ("wavelength_nm,responsivity", [(400, 0.1)], "at least 2 rows"),
])  # fmt: skip
def test_bad_responsivity_files_are_one_line_errors(tmp_path, header, rows, fragment):
    """Every problem with a responsivity file is one UserError line naming the
    file (and the line, where there is one)."""
    p = _write(tmp_path / "diode.csv", header, rows)
    with pytest.raises(UserError) as e:
        R.custom_response(p, "diode")
    msg = str(e.value)
    assert "\n" not in msg and str(p) in msg and fragment in msg


def test_custom_names_are_checked(tmp_path):
    """A custom response needs a column-safe name that is not a built-in one; a
    missing file is named."""
    p = _write(tmp_path / "d.csv", "wavelength_nm,responsivity", [(400, 1), (700, 1)])
    for bad in ("Diode", "par", "2x", "a b", "irradiance", "flux"):  # the last two would overwrite CSV columns
        with pytest.raises(UserError):
            R.custom_response(p, bad)
    with pytest.raises(UserError, match="no such file"):
        R.custom_response(tmp_path / "missing.csv", "diode")
    r = R.custom_response(_write(tmp_path / "short.csv", "wavelength_nm,responsivity", [(400, 1), (700, 1)]), "short")
    assert r.notes and "400–700 nm" in r.notes[0]
