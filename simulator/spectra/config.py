"""How a run names its responses and its emitters' spectrum: the TOML piece and its loader.

Proposed TOML (keys the run config passes here)::

    [output]
    csv = "out.csv"
    # every reading is also reported as these (radiometric and photopic
    # columns are always written); a table names a responsivity CSV
    responses = ["par", "melanopic_edi", "scotopic",
                 { custom = "diode.csv", name = "diode" }]

    [spectra]
    # spectral shape of every light that names no probesim:spectrum (default: D65
    # for photometric light units, radiometric_spectrum otherwise): a CIE
    # illuminant ("D65", "A", "FL2", "LED-B3"), a temperature (3000 or
    # "3000K"), or an SPD CSV relative to this config
    lights = "../stages/spectra/grow_led_spd.csv"

Paths are relative to the config file's folder. Every problem is one
:class:`UserError` line naming the config file and key, e.g.
``configs/g.toml: output.responses[1]: unknown response 'melanopc' (did you mean 'melanopic'?)``.
:mod:`simulator.spectra.schema` has the same shape as pydantic models.
"""

from __future__ import annotations

import difflib
from dataclasses import dataclass, field
from pathlib import Path

from simulator.errors import UserError

__all__ = ["RESPONSES_KEY", "SPECTRA_KEY", "SPECTRA_KEYS", "SpectraSettings", "load_spectra_settings", "parse_responses"]

#: key of the responses list inside ``[output]``
RESPONSES_KEY = "responses"
#: top-level table of spectral settings
SPECTRA_KEY = "spectra"
#: keys allowed in ``[spectra]``
SPECTRA_KEYS = ("lights",)
_CUSTOM_KEYS = ("custom", "name")


@dataclass(frozen=True)
class SpectraSettings:
    """A run's spectral settings.

    Attributes
    ----------
    responses : tuple of Response
        Requested responses, in the config's order, without duplicates.
    lights : Spectrum or None
        Declared spectrum of the lights (``[spectra] lights``); None: the
        stage reader's own (D65, ``radiometric_spectrum`` or blackbodies).
    raw : dict
        What the config said, for the run record.
    """

    responses: tuple = ()
    lights: object | None = None
    raw: dict = field(default_factory=dict)

    @property
    def wanted(self) -> bool:
        """True when anything beyond the standard columns was asked for."""
        return bool(self.responses) or self.lights is not None


def _fail(label: str, key: str, message: str) -> UserError:
    return UserError(": ".join(p for p in (label, key, " ".join(str(message).split())) if p))


def parse_responses(value, base_dir: Path, label: str = "", key: str = "output.responses") -> tuple:
    """Responses from the TOML value of ``output.responses``.

    Parameters
    ----------
    value : list
        Strings (registry names, :data:`simulator.spectra.responses.NAMES`)
        and tables ``{custom = "file.csv", name = "stem"}``.
    base_dir : Path
        The config's folder (custom files are relative to it).
    label : str
        The config file, for messages.
    key : str
        The key path, for messages.

    Returns
    -------
    tuple of Response
    """
    from simulator.spectra.responses import NAMES, custom_response, response

    if not isinstance(value, list):
        raise _fail(label, key, f"expected an array of response names, got {type(value).__name__}")
    out = []
    seen: dict[str, str] = {}
    for i, entry in enumerate(value):
        where = f"{key}[{i}]"
        if isinstance(entry, str):
            if entry not in NAMES:
                hint = difflib.get_close_matches(entry, NAMES, n=1)
                did = f"did you mean {hint[0]!r}? " if hint else ""
                raise _fail(label, where, f"unknown response {entry!r} ({did}expected one of: {', '.join(NAMES)}, "
                                          "or a table {custom = \"file.csv\", name = \"stem\"})")
            r = response(entry)
        elif isinstance(entry, dict):
            for k in entry:
                if k not in _CUSTOM_KEYS:
                    raise _fail(label, f"{where}.{k}", f"unknown key (expected one of: {', '.join(_CUSTOM_KEYS)})")
            for k in _CUSTOM_KEYS:
                if not isinstance(entry.get(k), str):
                    raise _fail(label, f"{where}.{k}", "required, a string")
            path = Path(entry["custom"])
            if not path.is_absolute():
                path = base_dir / path
            try:
                r = custom_response(path, entry["name"])
            except UserError as e:
                raise _fail(label, where, str(e)) from None
        else:
            raise _fail(label, where, f"expected a response name or a table, got {type(entry).__name__}")
        if r.name in seen:
            raise _fail(label, where, f"response {r.name!r} is already {seen[r.name]}")
        seen[r.name] = where
        out.append(r)
    return tuple(out)


def load_spectra_settings(raw: dict, config_path) -> SpectraSettings:
    """The spectral settings of a parsed run config (see module docstring).

    Parameters
    ----------
    raw : dict
        The whole parsed TOML (``tomllib.load``).
    config_path : path
        The config file: its folder resolves relative paths; its name labels messages.

    Returns
    -------
    SpectraSettings
        Empty when the config has neither key.
    """
    from simulator.spectra.sources import emitter_spectrum

    cfg = Path(config_path)
    label, base = str(config_path), cfg.parent
    output = raw.get("output", {})
    responses = ()
    if isinstance(output, dict) and RESPONSES_KEY in output:
        responses = parse_responses(output[RESPONSES_KEY], base, label)
    lights = None
    table = raw.get(SPECTRA_KEY)
    if table is not None:
        if not isinstance(table, dict):
            raise _fail(label, SPECTRA_KEY, "expected a table")
        for k in table:
            if k not in SPECTRA_KEYS:
                hint = difflib.get_close_matches(k, SPECTRA_KEYS, n=1)
                did = f"did you mean {hint[0]!r}? " if hint else ""
                raise _fail(label, f"{SPECTRA_KEY}.{k}", f"unknown key ({did}expected one of: {', '.join(SPECTRA_KEYS)})")
        if "lights" in table:
            spec = table["lights"]
            if isinstance(spec, bool) or not isinstance(spec, (str, int, float)):
                raise _fail(label, "spectra.lights", "expected an illuminant name, a temperature or a .csv file")
            try:
                lights = emitter_spectrum(spec, base)
            except UserError as e:
                raise _fail(label, "spectra.lights", str(e)) from None
    rec = {}
    if responses:
        rec["responses"] = [r.name for r in responses]
    if table is not None:
        rec["spectra"] = dict(table)
    return SpectraSettings(responses, lights, rec)
