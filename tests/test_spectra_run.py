"""Runs with ``output.responses`` and ``[spectra]``: the config keys, the columns they add, the refusals.

stages/point.usda is grey with one light (a 100 cd point at 3 m), so every
response is exact post hoc from the one traced channel
(simulator.spectra.posthoc); stages/quickstart.usda has a coloured rug, so
it is traced with hero wavelengths and every response estimated per sample.
"""

from __future__ import annotations

import csv
from pathlib import Path

import numpy as np
import pytest

from simulator.commands.cli import main
from simulator.config.loader import load_config
from simulator.errors import UserError
from simulator.io.results import COLUMNS  # noqa: F401
from simulator.pipeline import run
from simulator.spectra import grid, sources, tables
from simulator.spectra.reduce import posthoc_ratio
from simulator.spectra.responses import response
from simulator.units import K_M

ROOT = Path(__file__).resolve().parents[1]

_SENSORS = """
[simulation]
samples = 64
seed = 1

[[sensor]]
name = "below"
kind = "irradiance"
position = [0, 0, 0]
normal = [0, 0, 1]

[[sensor]]
name = "offset"
kind = "irradiance"
position = [1.5, 1.0, 0]
normal = [0, 0, 1]
"""


#: the CSV header of a fixed-budget run of irradiance sensors only (``[output] csv_columns = "kinds"``,
#: docs/DESIGN.md §The CSV's columns, per kind): no column another kind fills, no ``target_met``
IRRADIANCE_COLUMNS = ("sensor", "kind", "x", "y", "z", "dx", "dy", "dz", "irradiance_W_m2", "irradiance_stderr_W_m2",
                      "illuminance_lx", "illuminance_stderr_lx", "samples", "seconds", "method")


def _config(tmp_path: Path, stage: str = "point.usda", units: str = "photometric", output: str = "", spectra: str = "") -> Path:
    p = tmp_path / "run.toml"
    text = f'stage = "{(ROOT / "stages" / stage).as_posix()}"\nlight_units = "{units}"\n{spectra}\n{_SENSORS}\n'
    text += f'[output]\ncsv = "out/run.csv"\n{output}\n'
    p.write_text(text)
    return p


def _table(path: Path) -> list[dict]:
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def _v_diode(tmp_path: Path) -> Path:
    """A responsivity CSV of K_m·V(λ) lm/W (K_m = 683.002) on the spectral grid."""
    p = tmp_path / "v_diode.csv"
    rows = "\n".join(f"{w:g},{K_M * v!r}" for w, v in zip(grid.WAVELENGTHS_NM, tables.photopic()))
    p.write_text("wavelength_nm,responsivity_lm_W\n" + rows + "\n")
    return p


def test_par_and_melanopic_columns_on_a_grey_stage(tmp_path):
    """``responses = ["par", "melanopic_edi"]`` on the grey point stage (lux
    stated, D65 assumed): each row gains ppfd_umol_m2_s and melanopic_edi_lx
    with their stderr columns, after the standard columns; each is the lux
    reading / K(D65) × the response's ratio for D65 (µmol/J, melanopic lx per
    W/m²), to 1e-9 relative (the CSV's 9 significant digits); the run record
    says which responses and which spectrum."""
    cfg = load_config(_config(tmp_path, output='responses = ["par", "melanopic_edi"]'))
    out = run(cfg, log=lambda *a: None)
    table = _table(out.csv_path)
    header = list(table[0])
    assert tuple(header[:len(IRRADIANCE_COLUMNS)]) == IRRADIANCE_COLUMNS
    assert header[len(IRRADIANCE_COLUMNS):] == ["ppfd_umol_m2_s", "ppfd_stderr_umol_m2_s", "melanopic_edi_lx", "melanopic_edi_stderr_lx"]
    d65 = sources.emitter_spectrum("D65")
    for name, col in (("par", "ppfd_umol_m2_s"), ("melanopic_edi", "melanopic_edi_lx")):
        ratio = posthoc_ratio(response(name), d65.values)
        for r in table:
            assert float(r[col]) == pytest.approx(float(r["illuminance_lx"]) / d65.efficacy_lm_W * ratio, rel=1e-8)
    # E = 100 cd / 9 m² below the point light; melanopic EDI of D65 equals its lux (CIE S 026 §3.8)
    below = table[0]
    assert float(below["illuminance_lx"]) == pytest.approx(100.0 / 9.0, rel=1e-6)
    assert float(below["melanopic_edi_lx"]) == pytest.approx(100.0 / 9.0, rel=2e-3)
    assert out.record["spectra"]["responses"] == ["par", "melanopic_edi"]
    assert out.record["spectra"]["spectrum"] == "D65"
    assert out.record["plan"]["transport"] == "grey"


def test_a_683_v_responsivity_reproduces_the_lux_column(tmp_path):
    """A custom responsivity of K_m·V(λ) lm/W in a radiometric run (equal-energy
    spectrum) reads the engine's own illuminance column and its stderr, row
    by row, to 1e-6 relative: the engine carries its lux twin in float32
    (ulp 6e-8, summed over samples), the custom column is a float64 product
    of the radiometric reading."""
    entry = f'responses = [{{ custom = "{_v_diode(tmp_path).as_posix()}", name = "vdiode" }}]'
    cfg = load_config(_config(tmp_path, units="radiometric", output=entry))
    table = _table(run(cfg, log=lambda *a: None).csv_path)
    assert "vdiode_lm_m2" in table[0] and "vdiode_stderr_lm_m2" in table[0]
    for r in table:
        assert float(r["vdiode_lm_m2"]) == pytest.approx(float(r["illuminance_lx"]), rel=1e-6)
        if float(r["illuminance_stderr_lx"]) > 0:
            assert float(r["vdiode_stderr_lm_m2"]) == pytest.approx(float(r["illuminance_stderr_lx"]), rel=1e-6)


def test_a_run_without_responses_writes_the_standard_columns(tmp_path):
    """No ``responses``: the header is exactly the standard columns and the
    record has no "spectra" entry."""
    out = run(load_config(_config(tmp_path)), log=lambda *a: None)
    with open(out.csv_path, newline="") as f:
        assert tuple(next(csv.reader(f))) == IRRADIANCE_COLUMNS
    assert "spectra" not in out.record


def test_a_coloured_stage_with_responses_is_traced_spectrally(tmp_path):
    """quickstart.usda's rug is coloured: the run traces hero wavelengths and
    its PPFD columns come from the same samples as its lux (one estimate per
    sample, so each has its own stderr); the record names the transport and
    why."""
    cfg = load_config(_config(tmp_path, stage="quickstart.usda", output='responses = ["par"]'))
    out = run(cfg, log=lambda *a: None)
    rows = _table(out.csv_path)
    assert [r["sensor"] for r in rows[:2]] == ["below", "offset"]  # then the stage's own sensors
    for r in rows[:2]:
        lux, ppfd = float(r["illuminance_lx"]), float(r["ppfd_umol_m2_s"])
        assert lux > 0 and ppfd > 0 and float(r["ppfd_stderr_umol_m2_s"]) > 0
        # D65 light off a mostly grey room: PPFD per lux near D65's 0.01802 µmol s⁻¹ lm⁻¹ (within 10 %)
        assert 0.9 * 0.01802 < ppfd / lux < 1.1 * 0.01802
    spectra = out.record["spectra"]
    assert spectra["path"] == "hero wavelengths (spectral transport)" and "/World/Furniture/Rug" in spectra["reason"]
    assert spectra["estimated"] == ["radiometric", "photopic", "par"] and spectra["responses"] == ["par"]
    assert out.record["plan"]["transport"] == "spectral" and out.record["plan"]["channels"] == 4


def test_the_plan_names_the_transport(tmp_path, capsys):
    """``probesim plan``: grey (one channel) for the point stage, spectral (4
    hero wavelengths traced, because of the rug's colour) for the coloured quickstart."""
    assert main(["plan", str(_config(tmp_path))]) == 0
    assert "transport grey, channels: 1" in capsys.readouterr().out
    assert main(["plan", str(_config(tmp_path, stage="quickstart.usda"))]) == 0
    line = capsys.readouterr().out.strip().splitlines()[-1]
    assert "transport spectral, channels: 4" in line and "hero wavelengths" in line and "Rug" in line


@pytest.mark.parametrize(
    "output, spectra, key, what",
    [
        ('responses = ["par", "melanopc"]', "", "output.responses[1]", "unknown response 'melanopc'"),
        ('responses = "par"', "", "output.responses", "expected an array"),
        ('responses = [{ custom = "nope.csv" }]', "", "output.responses[0].name", "required"),
        ("", '[spectra]\nlight = "D65"', "spectra.light", "unknown key"),
        ("", '[spectra]\nlights = "nope.csv"', "spectra.lights", ""),
        ("colour = 1", "", "output.colour", ""),
    ],
)
def test_bad_spectral_keys_are_one_line_errors(tmp_path, capsys, output, spectra, key, what):
    """A wrong response name, shape, custom table, ``[spectra]`` key or file:
    one line naming the config file and the key, exit 2, nothing written;
    unknown ``[output]`` keys stay errors."""
    cfg = _config(tmp_path, output=output, spectra=spectra)
    with pytest.raises(UserError) as e:
        load_config(cfg)
    msg = str(e.value)
    assert "\n" not in msg and str(cfg) in msg and key in msg and what in msg
    assert main(["run", str(cfg), "-q"]) == 2
    assert capsys.readouterr().err.count("\n") == 1
    assert not (tmp_path / "out").exists()


def test_greenhouse_ppfd_columns_and_map(tmp_path):
    """configs/greenhouse.toml (its responses enabled, the LED's SPD named):
    PPFD, ePPFD and melanopic EDI columns with stderr; PPFD = E × 4.648 µmol/J
    (the LED's, simulator.spectra.posthoc) to 1e-8; the bench EXR carries the
    PPFD channel, the PNG is written; the uniformity is ~0.54 (min/mean, as
    measured at 1024 samples, here 64: within 0.03)."""
    from simulator.config.loader import apply_overrides

    cfg = apply_overrides(load_config(ROOT / "configs" / "greenhouse.toml"), samples=64, csv=tmp_path / "gh.csv")
    out = run(cfg, log=lambda *a: None)
    table = _table(out.csv_path)
    for c in ("ppfd_umol_m2_s", "ppfd_stderr_umol_m2_s", "eppfd_umol_m2_s", "melanopic_edi_lx", "melanopic_edi_stderr_lx"):
        assert c in table[0]
    par = out.record["spectra"]["per_radiometric_W"]["par"]
    assert par == pytest.approx(4.648, abs=5e-4)
    e = np.array([float(r["irradiance_W_m2"]) for r in table])
    ppfd = np.array([float(r["ppfd_umol_m2_s"]) for r in table])
    assert np.allclose(ppfd, e * par, rtol=1e-8)
    assert ppfd.min() / ppfd.mean() == pytest.approx(0.54, abs=0.03)
    import OpenEXR

    exr = OpenEXR.File(str(tmp_path / "gh.bench.exr"), separate_channels=True)
    assert "ppfd_umol_m2_s" in exr.channels()
    assert float(exr.header()["probesim:par_uniformity"]) == pytest.approx(ppfd.min() / ppfd.mean(), rel=1e-6)
    assert (tmp_path / "gh.bench.par.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


def test_a_probe_of_a_grey_scene_writes_its_emitters_colour(tmp_path):
    """With ``[spectra] lights = "A"`` on the grey greenhouse (radiometric
    units) every radiance has illuminant A's chromaticity, so the probe's
    lat-long EXR carries R, G, B = the stated radiance (W m⁻² sr⁻¹) × the
    linear sRGB of A per unit luminance (rgb_per_luminance: warm, R > G > B),
    whose BT.709 Y is the stated radiance again (to 2e-4: the Y weights
    0.2126, 0.7152, 0.0722 are the sRGB matrix's row rounded to 4 decimals),
    and names the colour in its header."""
    import OpenEXR

    from simulator.spectra.posthoc import rgb_per_luminance
    from simulator.units import luminance_grey

    cfg = _config(tmp_path, stage="greenhouse.usda", units="radiometric", spectra='[spectra]\nlights = "A"')
    cfg.write_text(cfg.read_text().replace("[output]", '[[sensor]]\nname = "ball"\nkind = "probe"\n'
                                                      'position = [0, 0, 0.5]\nresolution = [8, 4]\n\n[output]'))
    out = run(load_config(cfg), log=lambda *a: None)
    exr = OpenEXR.File(str(tmp_path / "out" / "run.ball.exr"), separate_channels=True)
    ch = {k: v.pixels.astype(float) for k, v in exr.channels().items()}
    rgb = rgb_per_luminance(sources.emitter_spectrum("A"))
    assert rgb[0] > rgb[1] > rgb[2]
    lit = ch["L_W_m2_sr"] > 0
    assert lit.any()
    for k, c in enumerate("RGB"):
        assert np.allclose(ch[c][lit] / ch["L_W_m2_sr"][lit], rgb[k], rtol=1e-6)
    y = luminance_grey(np.stack([ch["R"], ch["G"], ch["B"]], axis=-1))
    assert np.allclose(y, ch["L_W_m2_sr"], rtol=2e-4, atol=0)
    assert "illuminant" not in exr.header()["probesim:rgb"] and " A " in exr.header()["probesim:rgb"]
    assert out.record["spectra"]["spectrum"] == "A"
