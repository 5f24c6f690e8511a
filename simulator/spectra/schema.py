"""The spectral TOML piece as pydantic models, for a pydantic run config to embed.

Shape only; :func:`resolve` turns a validated piece into
:class:`~simulator.spectra.config.SpectraSettings` (files are resolved
against the config's folder then, with the same one-line errors as
:func:`simulator.spectra.config.load_spectra_settings`).

Usage in a run config model::

    class Output(BaseModel):
        csv: str | None = None
        responses: list[ResponseEntry] = []

    class RunConfig(BaseModel):
        spectra: SpectraTable | None = None
"""

from __future__ import annotations

from pathlib import Path
from typing import Union

from pydantic import BaseModel, ConfigDict

from simulator.spectra.config import SpectraSettings, load_spectra_settings

__all__ = ["CustomResponseEntry", "ResponseEntry", "SpectraTable", "resolve"]


class CustomResponseEntry(BaseModel):
    """``{custom = "diode.csv", name = "diode"}``: a responsivity CSV and its column stem."""

    model_config = ConfigDict(extra="forbid")
    custom: str
    name: str


#: one entry of ``output.responses``: a registry name or a custom table
ResponseEntry = Union[str, CustomResponseEntry]


class SpectraTable(BaseModel):
    """``[spectra]``: ``lights`` is an illuminant name, a temperature (K) or an SPD CSV."""

    model_config = ConfigDict(extra="forbid")
    lights: str | float | None = None


def resolve(responses: list, spectra: SpectraTable | None, config_path) -> SpectraSettings:
    """Validated models → :class:`SpectraSettings` (loads the CSV files)."""
    raw: dict = {"output": {"responses": [r.model_dump() if isinstance(r, BaseModel) else r for r in responses]}}
    if spectra is not None:
        raw["spectra"] = spectra.model_dump(exclude_none=True)
    return load_spectra_settings(raw, Path(config_path))
