"""Modelled candidates: what a real head reads of each light group, and a scenario's readings through it.

A candidate set that names a sensor model (``model = "..."``, docs/sensors.md)
is traced through the model's angular response (the engine's optics hook),
as a run's optics twin is: a light group's reading c_g is that group's true
photometric quantity (radiometric in a radiometric study) through r(ω). What
the head reports depends on the light's spectrum as well, and a study mixes
spectra: daylight through the window, lamps of another colour temperature.

Spectral factors. Channel c of a head calibrated under S_cal (its first
channel reads the true quantity of S_cal at normal incidence, the convention
of ``probesim sensor``) reads, per unit of the quantity of a light of
spectrum S arriving through its optics,

    σ_c(S) = k_c ∫ S s_c dλ / ∫ S q dλ,    k_c = ∫ S_cal q dλ / ∫ S_cal s_c dλ,

s_c over 300–1100 nm, q the quantity's weighting over 380–780 nm
(:meth:`simulator.sensor_models.model.SensorModel.signals_per_true`). For a
one-channel head σ_0(S) = 1/F(S), F the spectral mismatch correction factor
of ISO/CIE 19476 (the true quantity is F times the head's reading). Surfaces
are taken as grey, as a grey run takes them (simulator.sensor_models.spectral),
so a group's light keeps its emitters' spectrum wherever it arrives; a stage
with coloured surfaces is named in a warning. Each light group has one
spectrum (:func:`group_spectra`), so a scenario's channel signal is the
recombination with each group's level scaled by its factor,

    X_c = Σ_g σ_c(S_g) · d_g · c_g,    σ²(X_c) = (σ_c ∘ d)ᵀ C (σ_c ∘ d),

and the head's reading is X_0 (one channel) or its firmware's formula on
the channels' real counts (a two-channel part). The year's recombination
(sky patches, the sun, each lamp group) is :mod:`simulator.study.annual.heads`.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from simulator.errors import UserError

__all__ = ["HeadFactors", "group_spectra", "head_factors", "combine_heads"]

#: the quantity a model must report in a study of these light units (the study reads that channel)
STUDY_QUANTITY = {"photometric": "illuminance", "radiometric": "irradiance"}


@dataclass
class HeadFactors:
    """The modelled candidates of a study and each light group's spectral factors.

    Attributes
    ----------
    index : ndarray of int, shape (n,)
        Candidate indices (study order) that name a model.
    models : list of SensorModel
        Each one's model.
    factors : list of dict
        Each one's σ per group name: an ndarray (C,), one per channel.
    spectra : dict of str to str
        Each group's spectrum, by name (for the record).
    notes : list of str
        Warnings (coloured surfaces or lights, a group's spectrum overriding its lights').
    """

    index: np.ndarray
    models: list
    factors: list
    spectra: dict
    notes: list = field(default_factory=list)

    def record(self, cands) -> dict:
        """For a study's JSON record: per model, its candidate sets, each group's spectrum and F."""
        out: dict = {}
        for i, m, f in zip(self.index, self.models, self.factors):
            e = out.setdefault(m.name, {"sets": [], "file": str(m.path) if m.path else None,
                                        "spectra": dict(self.spectra),
                                        "mismatch_F": {g: _f_of(m, v) for g, v in f.items()}})
            if cands[i].set_name not in e["sets"]:
                e["sets"].append(cands[i].set_name)
        return out


def _f_of(model, sigma: np.ndarray) -> float:
    """F of a light whose channel factors are ``sigma``: the true quantity over what the head reports."""
    v = model.optics_value(list(sigma))
    return 1.0 / v if v > 0 else float("nan")


def group_spectra(study, scene, groups: dict, label: str) -> tuple[dict, list[str]]:
    """Each ``[[group]]``'s emission spectrum as a sensor model reads it.

    A group's ``spectrum`` (an illuminant name, a temperature in kelvin or an SPD ``.csv`` beside the
    study) when given, else its lights' own spectrum as the stage reader gave it (``probesim:spectrum``,
    ``colorTemperature``, else D65 in a photometric study).

    Returns
    -------
    spectra : dict of str to Spectrum
    notes : list of str
        A light with a colour (read at its spectrum's shape) and a group spectrum that overrides one its
        lights state.

    Raises
    ------
    UserError
        A spectrum that cannot be read, or a group whose lights have different spectra and no
        ``spectrum`` of its own: one line naming the key.
    """
    from simulator.spectra.sources import emitter_spectrum

    base = Path(label).parent
    out, notes = {}, []
    for k, g in enumerate(study.group):
        lights = [l for l in scene.lights if l.name in set(groups[g.name])]
        spec = getattr(g, "spectrum", None)
        if spec is not None:
            try:
                s = emitter_spectrum(spec, base)
            except UserError as e:
                raise UserError(f"{label}: group[{k}].spectrum: {e}") from None
            own = sorted({str(l.spectrum) for l in lights if l.spectrum_authored and str(l.spectrum) != str(spec)})
            if own:
                notes.append(f"group {g.name!r}: spectrum {spec} for the sensor models, where its lights state {', '.join(own)}")
        else:
            names = sorted({str(l.spectrum) for l in lights})
            if len(names) > 1:
                raise UserError(f"{label}: group[{k}]: its lights have spectra {', '.join(names)}: a sensor model reads a group "
                                "at one spectrum; give the group's spectrum or split it")  # fmt: skip
            first = lights[0].spectrum if lights else None
            s = emitter_spectrum(first if first is not None else ("D65" if study.light_units == "photometric" else "E"))
        coloured = [l.name for l in lights if np.ptp(np.asarray(l.color, float)) > 0]
        if coloured:
            notes.append(f"group {g.name!r}: {coloured[0]} has a colour; a sensor model reads the group at {s.name}'s shape")
        out[g.name] = s
    return out, notes


def head_factors(study, scene, cands, groups: dict, label: str, extra: dict | None = None) -> HeadFactors | None:
    """The spectral factors of every candidate that names a model, per group (and per ``extra`` light:
    name → Spectrum, the annual sun); None when no candidate names one (the study then runs exactly as
    without this module).

    Raises
    ------
    UserError
        A model that does not report the study's quantity (lux in a photometric study, W/m² in a
        radiometric one), or a group's spectrum (:func:`group_spectra`).
    """
    from simulator.spectra.posthoc import posthoc_refusal

    idx = [i for i, c in enumerate(cands) if getattr(c.sensor, "model", None) is not None]
    if not idx:
        return None
    want = STUDY_QUANTITY[study.light_units]
    for k, spec in enumerate(study.candidates):
        m = next((cands[i].sensor.model for i in idx if cands[i].set_name == spec.name), None)
        if m is not None and m.quantity != want:
            raise UserError(f"{label}: candidates[{k}].model: {m.name!r} reports {m.quantity}; a {study.light_units} study "
                            f"reads {want}")  # fmt: skip
    spectra, notes = group_spectra(study, scene, groups, label)
    spectra.update(extra or {})
    why = posthoc_refusal(scene)
    if why is not None and not why.startswith("emitters have"):
        notes.append(f"sensor models: {why}; a modelled candidate reads each group's light at its emitters' spectrum "
                     "(surfaces taken as grey)")
    wide = {g: s.on_wide_grid() for g, s in spectra.items()}
    models, factors = [], []
    cache: dict = {}
    for i in idx:
        m = cands[i].sensor.model
        if id(m) not in cache:
            cache[id(m)] = {g: np.array(m.signals_per_true(w), float) for g, w in wide.items()}
        models.append(m)
        factors.append(cache[id(m)])
    return HeadFactors(np.asarray(idx, np.int64), models, factors, {g: s.name for g, s in spectra.items()}, notes)


def combine_heads(gr, levels: dict, ids, heads: HeadFactors, ch: int, mean: np.ndarray, stderr: np.ndarray) -> None:
    """A scenario's readings of the modelled sensors of one chunk through their heads, in place.

    ``gr`` the chunk's :class:`~simulator.study.trace.groups.GroupReadings`, ``ids`` its sensors'
    candidate indices, ``mean``/``stderr`` (S, 2) its recombined readings (channel ``ch``, the study's
    quantity, is replaced for the modelled sensors: the head's optics value, and the first channel's
    relative standard error on it)."""
    from simulator.engine.stats import lit_variance
    from simulator.study.trace.groups import level_of

    where = {int(i): k for k, i in enumerate(heads.index)}
    d = np.array([level_of(levels, n) for n in gr.names])
    owner = [n.split("/", 1)[0] for n in gr.names]  # a sky patch's slot belongs to its group
    for row, cid in enumerate(ids):
        k = where.get(int(cid))
        if k is None:
            continue
        model, f = heads.models[k], heads.factors[k]
        sig = np.array([f[g] for g in owner])  # (G, C)
        x, var0 = [], 0.0
        for c in range(sig.shape[1]):
            w = d * sig[:, c]
            x.append(float(w @ gr.mean[:, row, ch]))
            if c == 0:
                var0 = float(lit_variance(w, gr.cov[row, ch]))
        v = model.optics_value(x)
        mean[row, ch] = v
        stderr[row, ch] = np.sqrt(max(var0, 0.0)) / x[0] * v if x[0] > 0 else 0.0
