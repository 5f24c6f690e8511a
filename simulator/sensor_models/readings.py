"""A run's modelled sensors: their optics twins, and the columns their rows gain.

A sensor that names a model is read twice by the engine: as itself (the
ideal quantity, exactly as without a model: same stream, same bytes) and
as its *optics twin*, a copy appended after every plain sensor whose first
vertex weighs by the model's angular response (``Sensor.optics``;
:mod:`simulator.kernels.optics`). Appending keeps every sensor's random
stream (it is keyed by its index) and the twins run after the plain
sensors' groups, so the ideal readings do not change when a model is
named.

From the twin's reading (W and lm channels, or per-channel responses in a
spectrally traced run) each modelled row gains, beside its ideal columns:

=============================================  ===================================================
column                                          what
=============================================  ===================================================
``model``                                       the model's name
``optics_<q>_<unit>``, ``optics_<q>_stderr_…``  the first channel's calibrated signal through the
                                                head (angular and spectral response), and its Monte
                                                Carlo standard error
``spectral_mismatch_F``                         the mismatch correction factor of the light reaching
                                                the sensor: the true quantity is F × the head's
                                                spectral reading
``device_<q>_<unit>``                           the value the device reports (counts through the
                                                firmware; the optics' signal without electronics)
``device_noise_sd_<unit>``                      the standard deviation of the device's noise in it
``device_counts_<channel>``                     each channel's ADC code
``device_saturated``, ``device_gain``,          the saturation flag and the setting read at
``device_integration_ms``
=============================================  ===================================================

with ``<q>_<unit>`` the model's quantity (``illuminance_lx``,
``irradiance_W_m2``, ``ppfd_umol_m2_s``).
"""

from __future__ import annotations

import dataclasses
import math

import numpy as np

from simulator.sensor_models.electronics import read_device
from simulator.sensor_models.spectral import QUANTITIES, channel_ratio

__all__ = ["TWIN_SUFFIX", "optics_twins", "channel_responses", "model_columns", "add_model_columns", "model_record"]

#: what an optics twin's name adds to its sensor's (plans and records show it)
TWIN_SUFFIX = " (optics)"
#: prefix of a model channel's response name in spectral tracing (no response column is written for it)
RESPONSE_PREFIX = "model:"


def optics_twins(sensors) -> list:
    """One optics twin per sensor that names a model, in sensor order."""
    return [dataclasses.replace(s, name=s.name + TWIN_SUFFIX, optics=s.model.angular, grid=None)
            for s in sensors if getattr(s, "model", None) is not None]


def channel_responses(sensors) -> list:
    """The responses a spectral trace must estimate for the models' channels (each channel's
    responsivity on 380–780 nm: the lanes' range), one per distinct model and channel."""
    from simulator.spectra.grid import trapezoid_weights
    from simulator.spectra.responses import Response
    from simulator.spectra.wide import VISIBLE

    out, seen = [], set()
    for s in sensors:
        m = getattr(s, "model", None)
        if m is None or m.name in seen:
            continue
        seen.add(m.name)
        for ch in m.channels:
            q = np.asarray(ch.responsivity)[VISIBLE] * trapezoid_weights()
            q.setflags(write=False)
            stems = {k: f"{m.name}_{ch.name}" for k in ("irradiance", "radiance", "flux")}
            units = {"irradiance": "W_m2", "radiance": "W_m2_sr", "flux": "W"}
            out.append(Response(f"{RESPONSE_PREFIX}{m.name}:{ch.name}", ch.name, q, stems, units, ch.source))
    return out


def model_columns(model) -> tuple[str, str, str]:
    """``(optics value column, its stderr column, device value column)`` of a model's quantity."""
    q = QUANTITIES[model.quantity]
    return f"optics_{q.stem}_{q.unit}", f"optics_{q.stem}_stderr_{q.unit}", f"device_{q.stem}_{q.unit}"


def _signals_grey(model, w_mean, w_se, spectrum) -> tuple[list[float], float, float]:
    """Channel signals of a grey scene from the twin's radiometric reading (see :mod:`.spectral`)."""
    light = spectrum.on_wide_grid()
    ks = model.calibration_factors()
    per_w = [k * channel_ratio(ch.responsivity, light, spectrum.values) for k, ch in zip(ks, model.channels)]
    return [w_mean * f for f in per_w], w_se * per_w[0], model.mismatch(light)


def add_model_columns(rows_by_name: dict, twins: list, mean, stderr, seed: int, spectrum=None, responses=None,
                      response_mean=None, response_stderr=None, ideal_mean=None, ideal_index=None) -> list[str]:
    """Add the model columns (module table) to the rows of the modelled sensors, in place.

    Parameters
    ----------
    rows_by_name : dict of str to Reading
        The run's rows by sensor name (ideal readings).
    twins : list of Sensor
        The optics twins, in the order of ``mean`` / ``stderr`` (shape (T, 2): W and lm channels).
    seed : int
        The run's seed (the device noise's streams).
    spectrum : Spectrum or None
        A grey scene's one emitter spectrum.
    responses, response_mean, response_stderr :
        A spectral run's response names and the twins' estimates of them, shape (T, R).
    ideal_mean : ndarray, shape (S, R), optional
        A spectral run: the ideal sensors' response estimates (their per-reading mismatch factor);
        ``ideal_index`` maps a sensor name to its row there.

    Returns
    -------
    list of str
        Notes for the run record (one per distinct fact).
    """
    notes: list[str] = []
    for i, twin in enumerate(twins):
        name = twin.name[: -len(TWIN_SUFFIX)]
        row = rows_by_name.get(name)
        if row is None or not row.values or (np.isnan(mean[i, 0]) if np.ndim(mean) == 2 else False):
            continue
        m = twin.model
        col, col_se, dev = model_columns(m)
        q = QUANTITIES[m.quantity]
        if responses is None:
            signals, se0, f = _signals_grey(m, float(mean[i, 0]), float(stderr[i, 0]), spectrum)
        else:
            ks = m.calibration_factors()
            signals, se0 = [], 0.0
            for c, (k, ch) in enumerate(zip(ks, m.channels)):
                j = responses.index(f"{RESPONSE_PREFIX}{m.name}:{ch.name}")
                signals.append(k * float(response_mean[i, j]))
                if c == 0:
                    se0 = k * float(response_stderr[i, j])
            f = _spectral_f(m, ideal_mean, ideal_index, name, responses)
            note = (f"{m.name}: traced spectrally, its channels read 380–780 nm only (the hero wavelengths' "
                    "range): what they see outside it is left out")
            if note not in notes and _outside_visible(m) > 1e-3:
                notes.append(note)
        v = row.values
        v["model"] = m.name
        optics = m.optics_value(signals)
        # a two-channel formula's standard error: the first channel's relative error (the channels'
        # estimates come from the same paths and move together)
        v[col], v[col_se] = optics, (se0 / signals[0] * optics if signals[0] > 0 else 0.0)
        v["spectral_mismatch_F"] = f
        if m.electronics is None:
            v[dev] = signals[0]
            v[f"device_noise_sd_{q.unit}"] = 0.0
            continue
        d = read_device(m.electronics, m.channels, signals, seed, name, twin.gain, twin.integration_ms)
        v[dev] = d.value
        v[f"device_noise_sd_{q.unit}"] = d.noise_sd
        for ch, code in zip(m.channels, d.counts):
            v[f"device_counts_{ch.name}"] = code
        v["device_saturated"] = d.saturated
        v["device_gain"] = d.setting.gain
        v["device_integration_ms"] = d.setting.integration_ms
    return notes


def _outside_visible(model) -> float:
    """The share of the first channel's responsivity (integrated flat) outside 380–780 nm."""
    from simulator.spectra.wide import wide_weights

    s = model.channels[0].responsivity
    tot = float(s @ wide_weights())
    return 1.0 - float(s @ wide_weights(380, 780)) / tot if tot > 0 else 0.0


def _spectral_f(model, ideal_mean, ideal_index, name, responses) -> float:
    """A spectral run's mismatch factor at one sensor: its true quantity (the ideal sensor's estimate of
    the quantity's response) over what the head reports of the same (cosine) light, its channels being
    the ideal sensor's estimates of their responses."""
    if ideal_mean is None or ideal_index is None or name not in ideal_index:
        return math.nan
    resp = {"illuminance": "photopic", "irradiance": "radiometric", "ppfd": "par"}[model.quantity]
    if resp not in responses:
        return math.nan
    r = ideal_index[name]
    ks = model.calibration_factors()
    sig = [k * float(ideal_mean[r, responses.index(f"{RESPONSE_PREFIX}{model.name}:{ch.name}")])
           for k, ch in zip(ks, model.channels)]
    den = model.optics_value(sig)
    return float(ideal_mean[r, responses.index(resp)]) / den if den > 0 else math.nan


def model_record(twins: list, notes: list[str]) -> dict:
    """The run record's ``sensor_models``: each model's indices and which sensors name it."""
    out: dict = {}
    for t in twins:
        m = t.model
        entry = out.setdefault(m.name, {**m.indices(), "file": str(m.path) if m.path else None, "sensors": 0})
        entry["sensors"] += 1
    return {"models": out, "notes": list(notes)} if out else {}
