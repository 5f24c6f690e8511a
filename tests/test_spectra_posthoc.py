"""Post-hoc responses of grey scenes: the greenhouse bench's PPFD from one radiometric channel.

Everything in stages/greenhouse.usda is grey and the six LED bars share one
SPD, so every reading's spectrum is the SPD times a geometry factor and
``PPFD = E · µmol/J`` is exact (simulator.spectra.posthoc). The synthetic LED
(stages/spectra/grow_led_spd.csv) gives 4.648 µmol/J (PAR), 4.890 (ePAR),
197.65 lm/W and 143.12 melanopic-EDI lux per W/m².
"""

from __future__ import annotations

import copy
from dataclasses import replace
import csv
from pathlib import Path

import numpy as np
import OpenEXR
import pytest

from simulator.config.loader import apply_overrides, load_config
from simulator.io.maps import grid_outputs
from simulator.io.results import COLUMNS, Reading, extra_columns, write_outputs
from simulator.pipeline import run
from simulator.scene.model import Geometry, Light, LightKind, Scene, Sensor, SensorKind
from simulator.spectra import grid, responses as R, sources, tables
from simulator.spectra.config import load_spectra_settings
from simulator.spectra.posthoc import apply_posthoc, posthoc_refusal, response_channels, rgb_per_luminance
from simulator.spectra.reduce import posthoc_ratio
from simulator.spectra.transport import choose_transport
from simulator.units import K_M, NAMED_EFFICACY

ROOT = Path(__file__).resolve().parents[1]
LED = ROOT / "stages" / "spectra" / "grow_led_spd.csv"


#: the CSV header of a fixed-budget run of irradiance sensors only (``[output] csv_columns = "kinds"``,
#: docs/DESIGN.md §The CSV's columns, per kind): no column another kind fills, no ``target_met``
IRRADIANCE_COLUMNS = ("sensor", "kind", "x", "y", "z", "dx", "dy", "dz", "irradiance_W_m2", "irradiance_stderr_W_m2",
                      "illuminance_lx", "illuminance_stderr_lx", "samples", "seconds", "method")


@pytest.fixture(scope="module")
def greenhouse(tmp_path_factory):
    out = tmp_path_factory.mktemp("greenhouse")
    # the greenhouse traced without its responses: these tests add them to the bare rows
    cfg = replace(apply_overrides(load_config(ROOT / "configs" / "greenhouse.toml"), samples=128, csv=out / "gh.csv"), spectra=None)
    return cfg, run(cfg, log=lambda *a: None), out


def _v_csv(tmp_path: Path) -> Path:
    p = tmp_path / "v_diode.csv"
    rows = "\n".join(f"{w:g},{K_M * v!r}" for w, v in zip(grid.WAVELENGTHS_NM, tables.photopic()))
    p.write_text("wavelength_nm,responsivity_lm_W\n" + rows + "\n")
    return p


def _settings(tmp_path: Path, lights: bool):
    raw = {"output": {"responses": ["par", "epar", "melanopic_edi", {"custom": str(_v_csv(tmp_path)), "name": "vdiode"}]}}
    if lights:
        raw["spectra"] = {"lights": str(LED)}
    return load_spectra_settings(raw, tmp_path / "run.toml")


def test_a_grey_run_writes_the_standard_columns_only(greenhouse):
    """No responses asked for: the CSV has exactly the standard columns (a grey
    run's CSV is what it was), one channel traced."""
    cfg, res, _ = greenhouse
    assert extra_columns(res.rows) == []
    with open(res.csv_path, newline="") as f:
        assert tuple(next(csv.reader(f))) == IRRADIANCE_COLUMNS
    assert choose_transport(res.scene)[:2] == ("grey", 1)


def test_custom_v_responsivity_reproduces_the_lux_column(greenhouse, tmp_path):
    """A responsivity of K_m·V(λ) lm/W (K_m = 683.002) reads the engine's own illuminance
    column (spectrum as the stage was read: equal energy), cell by cell, to
    1e-6: the engine carries its two channels in float32 (ulp 6e-8), the
    responses are float64 products of the radiometric one."""
    cfg, res, _ = greenhouse
    rows = copy.deepcopy(res.rows)
    s = _settings(tmp_path, lights=False)
    done = apply_posthoc(rows, res.scene, cfg.light_units, sources.emitter_spectrum(cfg.radiometric_spectrum), s.responses)
    assert not done.notes
    for r in rows:
        assert r.values["vdiode_lm_m2"] == pytest.approx(r.values["illuminance_lx"], rel=1e-6)
        assert r.values["vdiode_stderr_lm_m2"] == pytest.approx(r.values["illuminance_stderr_lx"], rel=1e-6)


def test_ppfd_of_the_bench_from_one_channel(greenhouse, tmp_path):
    """With the LED's SPD declared, each cell's PPFD and its stderr are the
    radiometric reading's × µmol/J (4.648); lux are recomputed as E × 197.65
    lm/W (noted, since the stage reader assumed equal energy) and the V(λ)
    diode reads them; melanopic EDI = E × 143.12."""
    cfg, res, _ = greenhouse
    rows = copy.deepcopy(res.rows)
    s = _settings(tmp_path, lights=True)
    done = apply_posthoc(rows, res.scene, cfg.light_units, s.lights, s.responses)
    assert done.notes and "photometric columns recomputed" in done.notes[0]
    assert done.ratios["par"] == pytest.approx(4.648, abs=5e-4)
    assert s.lights.efficacy_lm_W == pytest.approx(197.65, abs=5e-3)
    assert done.columns[:2] == ["ppfd_umol_m2_s", "ppfd_stderr_umol_m2_s"]
    for before, after in zip(res.rows, rows):
        e, e_se = before.values["irradiance_W_m2"], before.values["irradiance_stderr_W_m2"]
        v = after.values
        assert v["irradiance_W_m2"] == e
        assert v["ppfd_umol_m2_s"] == pytest.approx(e * done.ratios["par"], rel=1e-12)
        assert v["ppfd_stderr_umol_m2_s"] == pytest.approx(e_se * done.ratios["par"], rel=1e-12)
        assert v["illuminance_lx"] == pytest.approx(e * s.lights.efficacy_lm_W, rel=1e-12)
        assert v["vdiode_lm_m2"] == pytest.approx(v["illuminance_lx"], rel=1e-9)
        assert v["melanopic_edi_lx"] == pytest.approx(e * 143.12, rel=1e-4)


def test_the_ppfd_map_and_csv_columns(greenhouse, tmp_path):
    """Written out: the CSV gains the response columns after the standard
    ones; the bench EXR carries ppfd_umol_m2_s (as the CSV, in float32) and the
    PPFD uniformity (min/mean) in its header; a PPFD PNG is written."""
    cfg, res, _ = greenhouse
    rows = copy.deepcopy(res.rows)
    s = _settings(tmp_path, lights=True)
    apply_posthoc(rows, res.scene, cfg.light_units, s.lights, s.responses)
    out = tmp_path / "gh.csv"
    maps = grid_outputs(out, cfg.grids, rows, {"seed": 1}, response_channels(s.responses))
    write_outputs(out, rows, {}, maps)
    with open(out, newline="") as f:
        table = list(csv.DictReader(f))
        header = list(table[0])
    assert tuple(header[:len(COLUMNS)]) == COLUMNS and "ppfd_umol_m2_s" in header[len(COLUMNS):]
    ppfd = np.array([float(r["ppfd_umol_m2_s"]) for r in table])
    exr = OpenEXR.File(str(tmp_path / "gh.bench.exr"), separate_channels=True)
    img = exr.channels()["ppfd_umol_m2_s"].pixels
    g = cfg.grids[0]
    assert img.shape == (g.ny, g.nx)
    assert np.allclose(np.sort(img.ravel()), np.sort(ppfd), rtol=1e-6)
    head = exr.header()
    assert float(head["probesim:par_uniformity"]) == pytest.approx(ppfd.min() / ppfd.mean(), rel=1e-6)
    assert (tmp_path / "gh.bench.par.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


def test_spectral_sum_over_lights_equals_the_post_hoc_value():
    """The exactness claim, spectrally: a grey reading is Σ_l G_l L_l(λ) with
    λ-independent geometry factors; summing the lights' spectral radiances
    (each its stated watts × the shared shape) and applying a response gives
    the radiometric reading × posthoc_ratio, for any G and any stated values."""
    s = sources.spd_csv(LED)
    rng = np.random.default_rng(2)
    g, watts = rng.random(6), 100 * rng.random(6)
    spectral = sum(gi * sources.spectral_emission(w, "radiometric", s) for gi, w in zip(g, watts))
    e = float(g @ watts)
    for name in ("par", "epar", "photopic", "melanopic_edi", "scotopic", "s_cone"):
        assert R.response(name).of(spectral) == pytest.approx(e * posthoc_ratio(R.response(name), s.values), rel=1e-12)


def _scene(pairs, warnings=()):
    lights = [Light(f"/L{i}", LightKind.POINT, np.zeros(3), np.eye(3), p) for i, p in enumerate(pairs)]
    return Scene(Geometry(), lights, [], warnings=list(warnings))


def _row(lx, lx_se):
    s = Sensor("s", SensorKind.IRRADIANCE, np.zeros(3), np.array([0, 0, 1.0]))
    return Reading(s, {"irradiance_W_m2": lx / NAMED_EFFICACY["D65"], "irradiance_stderr_W_m2": lx_se / NAMED_EFFICACY["D65"],
                       "illuminance_lx": lx, "illuminance_stderr_lx": lx_se}, 1, 0.0, "light", None)


def test_photometric_runs_scale_from_the_stated_lux():
    """light_units photometric (D65): PPFD = lx / K(D65) × µmol/J(D65), with no
    rewrite (the stage reader's twin was D65 already)."""
    k = NAMED_EFFICACY["D65"]  # the stage reader's K(D65)
    scene = _scene([(1.0, k), (2.0, 2 * k)])
    rows = [_row(500.0, 5.0)]
    done = apply_posthoc(rows, scene, "photometric", sources.cie_illuminant("D65"), [R.response("par")])
    assert not done.notes
    ratio = posthoc_ratio(R.response("par"), sources.cie_illuminant("D65").values)
    assert rows[0].values["ppfd_umol_m2_s"] == pytest.approx(500.0 / k * ratio, rel=1e-12)
    assert rows[0].values["ppfd_stderr_umol_m2_s"] == pytest.approx(5.0 / k * ratio, rel=1e-12)


def test_scenes_the_post_hoc_path_refuses():
    """A coloured scene needs spectral transport and lights of different
    spectra need per-emitter values: both are refused with the reason, and the
    transport choice says which."""
    coloured = _scene([(1.0, 205.0)], ["coloured albedo/emission/light colour reduced to luminance grey: /World/Red"])
    why = posthoc_refusal(coloured)
    assert "/World/Red" in why and "colour can change a reading" in why
    mode, channels, reason = choose_transport(coloured)
    assert (mode, channels) == ("spectral", 4) and "hero" in reason
    mixed = _scene([(1.0, 205.15), (1.0, 163.1)])
    assert "2 different spectra" in posthoc_refusal(mixed)
    mode, channels, reason = choose_transport(mixed, n_responses=5)
    assert (mode, channels) == ("per-emitter", 4) and "hero" in reason
    with pytest.raises(ValueError, match="different spectra"):
        apply_posthoc([_row(1.0, 0.1)], mixed, "photometric", sources.cie_illuminant("D65"), [R.response("par")])
    assert posthoc_refusal(_scene([(1.0, 205.15), (3.0, 3 * 205.15)])) is None


def test_probe_rgb_of_a_grey_scene_is_the_emitters_chromaticity():
    """RGB per unit luminance: D65 is sRGB's white, (1, 1, 1) to 1e-3; the
    LED (blue + red peaks) is magenta-ish (R and B above G); BT.709 luminance
    of the result is 1 (Y = 1 by construction) to 1e-3."""
    from simulator.units import luminance_grey

    assert np.allclose(rgb_per_luminance(sources.cie_illuminant("D65")), 1.0, atol=1e-3)
    led = rgb_per_luminance(sources.spd_csv(LED))
    assert led[0] > led[1] and led[2] > led[1]
    assert luminance_grey(led) == pytest.approx(1.0, abs=1e-3)


def test_run_hooks(greenhouse, tmp_path):
    """What a run calls: nothing asked → nothing done; asked → the declared
    spectrum, or the stage reader's own; a coloured scene, or lights sharing
    a spectrum the run does not name, stop the run with one line."""
    from simulator.errors import UserError
    from simulator.spectra.config import SpectraSettings
    from simulator.spectra.posthoc import finish_run, run_spectrum

    cfg, res, _ = greenhouse
    assert run_spectrum(SpectraSettings(), res.scene, cfg.light_units, "E") is None
    assert finish_run(res.rows, res.scene, cfg.light_units, None, SpectraSettings()) == (None, [])
    s = _settings(tmp_path, lights=True)
    assert run_spectrum(s, res.scene, cfg.light_units, "E").name == "grow_led_spd.csv"
    bare = _settings(tmp_path, lights=False)
    assert run_spectrum(bare, res.scene, cfg.light_units, "E").name == "E"
    with pytest.raises(UserError, match="not the run's D65"):
        run_spectrum(bare, res.scene, cfg.light_units, "D65")
    coloured = _scene([(1.0, 205.0)], ["coloured albedo/emission/light colour reduced to luminance grey: /World/Red"])
    with pytest.raises(UserError, match="cannot be computed from one channel: coloured"):
        run_spectrum(s, coloured, "photometric", "E")
    rows = copy.deepcopy(res.rows)
    record, channels = finish_run(rows, res.scene, cfg.light_units, s.lights, s)
    assert record["spectrum"] == "grow_led_spd.csv" and record["responses"][0] == "par"
    assert [c["name"] for c in channels] == ["par", "epar", "melanopic_edi", "vdiode"]
    assert "ppfd_umol_m2_s" in rows[0].values


def test_probe_patch_and_radiance_rows_get_their_own_columns():
    """A probe's scalar irradiance gives scalar_ppfd (its fluence rate), a
    patch its PPF in µmol/s, a radiance meter its photon radiance; the base
    columns the kinds already have are the CSV's own names."""
    k = NAMED_EFFICACY["E"]
    scene = _scene([(1.0, k)])
    probe = Reading(Sensor("p", SensorKind.PROBE, np.zeros(3), np.zeros(3)),
                    {"scalar_irradiance_W_m2": 2.0, "scalar_irradiance_stderr_W_m2": 0.1,
                     "scalar_illuminance_lx": 2.0 * k, "scalar_illuminance_stderr_lx": 0.1 * k}, 1, 0.0, "path", None)
    patch = Reading(Sensor("f", SensorKind.PATCH, np.zeros(3), np.array([0, 0, 1.0])),
                    {"irradiance_W_m2": 1.0, "irradiance_stderr_W_m2": 0.0, "illuminance_lx": k, "illuminance_stderr_lx": 0.0,
                     "flux_W": 3.0, "flux_stderr_W": 0.0, "luminous_flux_lm": 3 * k, "luminous_flux_stderr_lm": 0.0},
                    1, 0.0, "path", None)
    meter = Reading(Sensor("m", SensorKind.RADIANCE, np.zeros(3), np.array([0, 0, 1.0])),
                    {"radiance_W_m2_sr": 5.0, "radiance_stderr_W_m2_sr": 0.5, "luminance_cd_m2": 5 * k,
                     "luminance_stderr_cd_m2": 0.5 * k}, 1, 0.0, "path", None)
    done = apply_posthoc([probe, patch, meter], scene, "radiometric", sources.equal_energy(), [R.response("par")])
    ratio = done.ratios["par"]
    assert probe.values["scalar_ppfd_umol_m2_s"] == pytest.approx(2.0 * ratio)
    assert probe.values["scalar_ppfd_stderr_umol_m2_s"] == pytest.approx(0.1 * ratio)
    assert patch.values["ppf_umol_s"] == pytest.approx(3.0 * ratio) and patch.values["ppfd_umol_m2_s"] == pytest.approx(ratio)
    assert meter.values["par_photon_radiance_umol_m2_s_sr"] == pytest.approx(5.0 * ratio)
    assert "scalar_ppfd_umol_m2_s" in done.columns and "ppf_stderr_umol_s" in done.columns
