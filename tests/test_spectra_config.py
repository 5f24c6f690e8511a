"""The spectral TOML piece: ``output.responses`` and ``[spectra] lights``, loaded with one-line errors."""

from __future__ import annotations

import tomllib
from pathlib import Path

import pytest

from simulator.errors import UserError
from simulator.spectra.config import load_spectra_settings
from simulator.spectra.schema import CustomResponseEntry, SpectraTable, resolve

ROOT = Path(__file__).resolve().parents[1]


def _load(tmp_path: Path, text: str):
    cfg = tmp_path / "run.toml"
    cfg.write_text(text)
    return load_spectra_settings(tomllib.loads(text), cfg)


def test_the_proposed_toml_loads(tmp_path):
    """Names, a custom responsivity (relative to the config) and a declared
    SPD load into responses in config order and a spectrum."""
    (tmp_path / "diode.csv").write_text("wavelength_nm,responsivity_A_W\n400,0.1\n700,0.4\n")
    s = _load(tmp_path, f'''
        [output]
        responses = ["photopic", "par", "melanopic_edi", {{ custom = "diode.csv", name = "diode" }}]
        [spectra]
        lights = "{(ROOT / 'stages' / 'spectra' / 'grow_led_spd.csv').as_posix()}"
        ''')
    assert [r.name for r in s.responses] == ["photopic", "par", "melanopic_edi", "diode"]
    assert s.responses[3].columns("irradiance") == ("diode_A_m2", "diode_stderr_A_m2")
    assert s.lights.name == "grow_led_spd.csv" and s.wanted
    assert s.raw["responses"] == ["photopic", "par", "melanopic_edi", "diode"]


def test_nothing_asked_for_is_empty(tmp_path):
    s = _load(tmp_path, '[output]\ncsv = "a.csv"\n')
    assert s.responses == () and s.lights is None and not s.wanted


@pytest.mark.parametrize("text, fragment", [
    ('[output]\nresponses = ["melanopc"]', "output.responses[0]: unknown response 'melanopc' (did you mean 'melanopic'?"),
    ('[output]\nresponses = "par"', "output.responses: expected an array"),
    ('[output]\nresponses = ["par", "par"]', "output.responses[1]: response 'par' is already output.responses[0]"),
    ('[output]\nresponses = [3]', "output.responses[0]: expected a response name or a table"),
    ('[output]\nresponses = [{ custom = "nope.csv", name = "d" }]', "output.responses[0]: "),
    ('[output]\nresponses = [{ custom = "d.csv" }]', "output.responses[0].name: required"),
    ('[output]\nresponses = [{ custom = "d.csv", name = "d", scale = 2 }]', "output.responses[0].scale: unknown key"),
    ('[spectra]\nlight = "D65"', "spectra.light: unknown key (did you mean 'lights'?"),
    ('[spectra]\nlights = "D66"', "spectra.lights: unknown illuminant 'D66'"),
    ('[spectra]\nlights = true', "spectra.lights: expected an illuminant name"),
    ('spectra = 3', "spectra: expected a table"),
])  # fmt: skip
def test_mistakes_are_one_line_errors(tmp_path, text, fragment):
    """Each mistake is one UserError line naming the config file and the key."""
    with pytest.raises(UserError) as e:
        _load(tmp_path, text)
    msg = str(e.value)
    assert "\n" not in msg and msg.startswith(str(tmp_path / "run.toml")) and fragment in msg


def test_missing_custom_file_is_named(tmp_path):
    with pytest.raises(UserError, match=r"output\.responses\[0\]: .*nope\.csv: no such file"):
        _load(tmp_path, '[output]\nresponses = [{ custom = "nope.csv", name = "d" }]')


def test_pydantic_schema_resolves_to_the_same_settings(tmp_path):
    """The pydantic models validate the shape (extra keys refused) and
    resolve to what the plain loader gives."""
    import pydantic

    (tmp_path / "diode.csv").write_text("wavelength_nm,responsivity\n400,1\n700,2\n")
    s = resolve(["par", CustomResponseEntry(custom="diode.csv", name="diode")], SpectraTable(lights="3000K"),
                tmp_path / "run.toml")
    assert [r.name for r in s.responses] == ["par", "diode"] and s.lights.name == "blackbody 3000 K"
    with pytest.raises(pydantic.ValidationError):
        CustomResponseEntry(custom="d.csv", name="d", scale=2)
