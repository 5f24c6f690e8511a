"""Responses of a spectrally traced run: tables for the engine, response columns for the rows.

When the plan's transport is not ``grey`` (:mod:`simulator.spectra.transport`)
the engine traces 4 hero wavelengths per sample (:mod:`simulator.spectra.hero`)
and estimates every response per sample, so the value and stderr of each
response column come from the same samples (wavelength noise included), and
the radiometric and photometric columns are that estimate's radiometric and
photopic responses. Readings the plan answers in closed form (``analytic``,
``exact``: light straight from emitters, no reflection) are not traced: their
responses are ``Σ_l E_l · (q · S_l)``, which needs one emitter spectrum (the
radiometric reading × the ratio); with several, the run estimates them by
direct-light sampling (:func:`simulator.pipeline.run_plan`).
"""

from __future__ import annotations

import numpy as np

from simulator.spectra.posthoc import BASE_COLUMNS

__all__ = ["run_hero_tables", "closed_form_responses", "add_traced_columns", "traced_record", "traced_warning"]

#: the stage reader's summary warning when it reduced a colour to grey (simulator.scene.usd.materials)
_COLOURED = "coloured albedo/emission/light colour reduced to luminance grey: "


def traced_warning(warning: str) -> str:
    """A stage warning as it reads in a spectrally traced run: the reader's grey reduction of colours
    no longer applies to albedos, emissiveColor and light colours, which the kernels trace spectrally."""
    if not warning.startswith(_COLOURED):
        return warning
    return ("coloured albedo, emissiveColor or light color traced with hero wavelengths (texture colours "
            "still read as luminance grey): " + warning[len(_COLOURED):])


def run_hero_tables(cfg, scene, extra=()):
    """The hero tables of a run (:func:`simulator.spectra.hero.hero_tables`): the config's responses (and
    ``extra``: the sensor models' channels, which write no column of their own), ``[spectra] lights`` if
    declared, the stage reader's default spectrum otherwise."""
    from simulator.spectra.hero import hero_tables

    settings = cfg.spectra
    default = "D65" if cfg.light_units == "photometric" else cfg.radiometric_spectrum
    responses = (() if settings is None else tuple(settings.responses)) + tuple(extra)
    declared = None if settings is None else settings.lights
    return hero_tables(scene, cfg.light_units, default, responses, declared)


def writes_columns(r) -> bool:
    """Whether response ``r`` has columns of its own: not radiometric or photopic (the CSV's own), nor a
    sensor model's channel (:func:`simulator.sensor_models.readings.channel_responses`)."""
    return r.name not in ("radiometric", "photopic") and not r.name.startswith("model:")


def closed_form_responses(tables, mean: np.ndarray) -> np.ndarray | None:
    """Responses (S, R) of closed-form readings ``mean`` (S, 2), or None when emitters differ in spectrum.

    A closed-form reading is light straight from emitters; with one shared
    shape S (per radiometric unit, ``tables.emission``) every response is
    ``mean[:, 0] · (q_r · S)``.
    """
    rows = np.asarray(tables.emission, float)
    rows = rows[np.any(rows > 0, axis=1)]
    if len(rows) == 0:
        return np.zeros((len(mean), len(tables.responses)))
    if np.max(np.abs(rows - rows[0])) > 1e-9 * np.max(np.abs(rows[0])):
        return None
    ratio = np.array([float(np.asarray(r.q, float) @ rows[0]) for r in tables.responses])
    return np.asarray(mean, float)[:, :1] * ratio[None, :]


def _quantity_of(column: str) -> str | None:
    return next((q for q, cols in BASE_COLUMNS.items() if cols[0] == column), None)


def add_traced_columns(rows, tables, mean: np.ndarray, stderr: np.ndarray) -> list[str]:
    """Add every non-base response's columns to the rows of plain sensors (in place).

    Parameters
    ----------
    rows : list of simulator.io.results.Reading
        One per sensor, in the order of ``mean``; each kind's column groups
        (``SensorKindSpec.columns``) say which quantities it reports, and a
        group with ``factor = "area"`` (a patch's flux) scales by its area.
    tables : HeroTables
    mean, stderr : ndarray, shape (S, R)
        Per sensor and response (NaN: not available, left empty).

    Returns
    -------
    list of str
        The columns added, value and stderr, in order.
    """
    added: dict[str, None] = {}
    for i, row in enumerate(rows):
        for group in row.sensor.spec.columns:
            quantity = _quantity_of(group.columns[0])
            if quantity is None:
                continue
            factor = row.sensor.size[0] * row.sensor.size[1] if group.factor == "area" else 1.0
            for j, r in enumerate(tables.responses):
                if not writes_columns(r):
                    continue
                col, col_se = r.columns(quantity)
                added[col] = added[col_se] = None
                if np.isfinite(mean[i, j]) and row.values:
                    row.values[col], row.values[col_se] = float(mean[i, j] * factor), float(stderr[i, j] * factor)
    return list(added)


def traced_record(tables, columns: list[str], mode: str, reason: str) -> dict:
    """What the run record says about spectral transport."""
    return {"path": f"hero wavelengths ({mode} transport)", "reason": reason,
            "estimated": [r.name for r in tables.responses], "columns": list(columns),
            "reflectance_rows": int(tables.reflectance.shape[0]),
            "measured_reflectances": list(getattr(tables, "measured", [])), "notes": list(tables.notes)}
