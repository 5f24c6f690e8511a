"""Lights whose only spectrum is their ``colorTemperature``, in grey scenes with responses asked for.

UsdLux: with ``enableColorTemperature`` a light's colour is a blackbody at
``colorTemperature``. In a grey scene whose lights all share one such
temperature the readings' spectrum is that blackbody's shape, so every
response is the radiometric reading times ``∫ q·B_T / ∫ B_T`` (exact from
one channel, simulator.spectra.posthoc). The reference here is Planck's law
in closed form with CIE 015's c₂ = 1.4388e-2 m·K, integrated by the test
itself: PAR = ∫₄₀₀⁷⁰⁰ B_T(λ)·λ/(h c N_A) dλ · 1e6 / ∫₃₈₀⁷⁸⁰ B_T dλ µmol/J.
Lights of different temperatures give different efficacies: the run takes
the per-emitter path (traced, responses estimated per sample).
"""

from __future__ import annotations


import numpy as np
import pytest

from simulator.config.loader import load_config
from simulator.pipeline import run

C2_M_K = 1.4388e-2  # CIE 015:2018, second radiation constant
H_J_S, C_M_S, NA = 6.62607015e-34, 299792458.0, 6.02214076e23  # SI 2019 exact constants


def _planck_shape(t_k: float, lam_nm: np.ndarray) -> np.ndarray:
    lam = lam_nm * 1e-9
    return lam**-5 / np.expm1(C2_M_K / (lam * t_k))  # c1 cancels in every ratio


def _par_umol_per_J(t_k: float) -> float:
    """PAR photon response per radiometric watt (380–780 nm) of a blackbody, by a 0.01 nm trapezoid."""
    lam = np.linspace(380.0, 780.0, 40001)
    band = np.linspace(400.0, 700.0, 30001)
    photons = _planck_shape(t_k, band) * band * 1e-9 / (H_J_S * C_M_S * NA) * 1e6
    return float(np.trapezoid(photons, band) / np.trapezoid(_planck_shape(t_k, lam), lam))


def _stage(tmp_path, temps):
    lights = "".join(f'''
def DistantLight "Sun{k}"
{{
    float inputs:intensity = {1000.0 * (k + 1)}
    float inputs:angle = 0
    bool inputs:enableColorTemperature = 1
    float inputs:colorTemperature = {t}
}}
''' for k, t in enumerate(temps))
    (tmp_path / "s.usda").write_text(f'''#usda 1.0
(
    metersPerUnit = 1
    upAxis = "Z"
)
def Mesh "Floor"
{{
    int[] faceVertexCounts = [4]
    int[] faceVertexIndices = [0, 1, 2, 3]
    point3f[] points = [(-5, -5, 0), (5, -5, 0), (5, 5, 0), (-5, 5, 0)]
    color3f[] primvars:displayColor = [(0.5, 0.5, 0.5)]
}}
{lights}''')
    (tmp_path / "c.toml").write_text('''stage = "s.usda"
[simulation]
samples = 256
seed = 1
[[sensor]]
name = "up"
kind = "irradiance"
position = [0, 0, 1]
normal = [0, 0, 1]
[output]
csv = "out.csv"
responses = ["par"]
''')
    return load_config(tmp_path / "c.toml")


@pytest.mark.parametrize("temperature_K", [2700.0, 6500.0])
def test_one_colour_temperature_grey_scene_is_exact_from_one_channel(tmp_path, temperature_K):
    """Two lights at one temperature: no refusal; PPFD / irradiance is the blackbody's PAR ratio to
    1e-5 (the 1 nm reduction grid's quadrature against a 0.01 nm one), and the run is grey."""
    out = run(_stage(tmp_path, [temperature_K, temperature_K]), log=lambda *a: None)
    row = out.rows[0].values
    assert out.record["spectra"]["path"].startswith("post-hoc")
    assert row["irradiance_W_m2"] > 0
    ratio = row["ppfd_umol_m2_s"] / row["irradiance_W_m2"]
    truth = _par_umol_per_J(temperature_K)
    assert abs(ratio - truth) <= 1e-5 * truth, (ratio, truth)
    assert row["ppfd_stderr_umol_m2_s"] == pytest.approx(row["irradiance_stderr_W_m2"] * ratio, rel=1e-9, abs=1e-12)


def test_two_colour_temperatures_take_the_per_emitter_path(tmp_path):
    """2700 K and 6500 K lights: efficacies differ, so the run is not post hoc but traced per emitter;
    the delta suns' PPFD, E1·PAR(2700 K) + E2·PAR(6500 K) with E_i each sun's irradiance, is read within
    4 standard errors."""
    cfg = _stage(tmp_path, [2700.0, 6500.0])
    out = run(cfg, log=lambda *a: None)
    assert out.record["plan"]["transport"] == "per-emitter"
    row = out.rows[0].values
    e_w = [l.emission[0] for l in out.scene.lights]  # normal irradiance of each delta sun, W/m²
    truth = sum(e * _par_umol_per_J(t) for e, t in zip(e_w, (2700.0, 6500.0)))
    se = row["ppfd_stderr_umol_m2_s"]
    assert abs(row["ppfd_umol_m2_s"] - truth) <= 4 * se + 1e-6 * truth, (row["ppfd_umol_m2_s"], truth, se)
