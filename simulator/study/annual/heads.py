"""Modelled candidates over a year: their hourly signal by light group, and their device in the control.

A candidate set naming a sensor model is traced through the model's angular
response (:mod:`simulator.study.inputs.heads`): its daylight coefficients,
its direct sun (:func:`simulator.study.annual.sunlight.direct_sun`, E_n·r(θ, φ)·V)
and its lamp readings are true lux through r(ω). What the head reports of
them depends on each light's spectrum.

Spectra. The sky's patches take the sky group's spectrum; the sun (its exact
direct light, and its interreflected light from the patches around it or
from its traced bins) that of the group holding the stage's DistantLight,
else the DistantLight's own, else D65; each lamp group its own; the
ground slot, of luminance ρ(E_dh + E_n sin h)/π, the hour's blend: a share
E_dh/(E_dh + E_n sin h) of sky and the rest of sun. Channel c's hourly
signal is year.py's recombination with every level scaled by its light's
factor σ_c (:mod:`simulator.study.inputs.heads`):

    X_c,h = σ_c,sky·(d'_hᵀc_dir + d'_hᵀc_ind) + g_c,h·d_h,gr·(c_dir,gr + c_ind,gr)
            + σ_c,sun·(q_hᵀc_ind + E^sun_h),   g_c,h = σ_c,sky·w_h + σ_c,sun·(1 − w_h),

d' the patch levels without the ground slot, w_h the sky's share; its
variance is the same recombination's. The head's hourly reading (the
``annual_hourly.csv`` column, the zone metrics over modelled candidates) is
X_0 for one channel, the firmware's formula on the channels' real counts for
two, and its standard error the first channel's relative one.

The device in the control. A modelled photosensor with electronics
controls on what the device reports (:func:`control_outcome`): its setting
(the candidate set's ``gain`` and ``integration_ms``, else the part's
default, auto-ranged per reading), counts, full scale and noise, drawn per
hour from a stream seeded by the study's seed and the sensor's name and
indexed by the hour's row of the weather file (the same draw whatever the
hours analysed, the workers or the chunks). Closed loop: commissioned at
night, the set point is the device's noiseless reading of its lamps at the
level that gives the target; each hour the lamps settle at the lowest level
u ∈ [u_min, 1] whose reading of daylight plus lamps, R_h(X_h + u·S_e),
reaches the set point (1 where none does), the equilibrium of a
proportional loop on the reported signal; ideal electronics give
u = (SP − X_h)/S_e, the law of :mod:`simulator.study.annual.control`. Open
loop and switched: the device reads the daylight, its gain commissioned on
its noiseless reading under the CIE overcast sky. An hour is *saturated*
where a channel's count at that level reaches full scale: the reading is
then the full-scale one, flagged, and counted per candidate. A loop on a
quantised, noisy reading holds its zone only as finely as it reads: at
night the ideal law puts the zone exactly at target, a device within a
code and its noise of it, so an hour counts as below target where the zone
falls short by more than that (``target_tolerance_lx``: one code plus twice
the noise's standard deviation at the set point, times the zone's lux per
unit of the sensor's lamp signal).
"""

from __future__ import annotations

from dataclasses import dataclass, replace

import numpy as np

from simulator.study.annual import control as CT

__all__ = ["SUN", "sun_spectrum", "YearLight", "head_hourly", "apply_heads", "lamp_readings", "overcast_readings",
           "hour_noise", "control_outcome", "DeviceOutcome"]

#: the key of the annual sun's spectral factors beside the groups'
SUN = "[annual] sun"


def sun_spectrum(study, scene, groups: dict, label: str):
    """The annual sun's spectrum: that of the ``[[group]]`` holding the stage's DistantLight (its ``spectrum``,
    else the light's own; ``sun_group`` where it is traced), else the stage's one DistantLight's, else D65."""
    from pathlib import Path

    from simulator.scene.model import LightKind
    from simulator.spectra.sources import emitter_spectrum

    distant = [l for l in scene.lights if l.kind == LightKind.DISTANT]
    for g in study.group:
        if any(l.name in set(groups[g.name]) for l in distant) and g.spectrum is not None:
            return emitter_spectrum(g.spectrum, Path(label).parent)
    if len(distant) == 1 and distant[0].spectrum is not None:
        return emitter_spectrum(distant[0].spectrum)
    return emitter_spectrum("D65")


@dataclass
class YearLight:
    """The year's levels as year.py recombines them (see :func:`simulator.study.annual.year.hourly`)."""

    d: np.ndarray  #: (H, 146) sky patch and ground levels
    q: np.ndarray  #: (H, 146) the sun's light in patches
    sun: np.ndarray  #: (H, S) direct sun through each head's response (lux)
    sky_share: np.ndarray  #: (H,) the ground's share of sky light
    sun_bin: np.ndarray | None = None
    sun_scale: np.ndarray | None = None


def _subset(co, ids: list[int]):
    """The coefficients of candidates ``ids`` alone."""
    k = list(ids)
    return replace(co, dir=co.dir[k], dir_cov=co.dir_cov[k], ind=co.ind[k], ind_cov=co.ind_cov[k], lamp=co.lamp[k],
                   lamp_cov=co.lamp_cov[k], samples=co.samples[k], sun=None if co.sun is None else co.sun[k],
                   sun_var=None if co.sun_var is None else co.sun_var[k])  # fmt: skip


def head_hourly(heads, sky_group: str, co, yl: YearLight, stderr: bool = True):
    """Each modelled candidate's hourly channel signals (list of (C, H)), readings (H, n) and their
    standard errors (H, n; None without ``stderr``). The candidates of one model share its factors: one
    recombination per model and channel."""
    from simulator.study.annual.coefficients import hourly

    n = len(heads.index)
    h = yl.d.shape[0]
    chans, value = [None] * n, np.zeros((h, n))
    se = np.zeros((h, n)) if stderr else None
    by_model: dict = {}
    for k in range(n):
        by_model.setdefault(id(heads.models[k]), []).append(k)
    for ks in by_model.values():
        f, m = heads.factors[ks[0]], heads.models[ks[0]]
        ids = [int(heads.index[k]) for k in ks]
        sub = _subset(co, ids)
        x = []
        for c in range(len(m.channels)):
            fs, fu = float(f[sky_group][c]), float(f[SUN][c])
            d = yl.d * fs
            d[:, -1] = yl.d[:, -1] * (fs * yl.sky_share + fu * (1.0 - yl.sky_share))
            scale = None if yl.sun_scale is None else yl.sun_scale * fu
            mean, e = hourly(sub, d, yl.q * fu, yl.sun[:, ids] * fu, stderr=stderr and c == 0, sun_bin=yl.sun_bin,
                             sun_scale=scale)  # fmt: skip
            x.append(mean)
            if c == 0 and stderr:
                e0 = e
        x = np.array(x)  # (C, H, len(ks))
        for j, k in enumerate(ks):
            chans[k] = x[:, :, j]
            value[:, k] = _optics(m, x[:, :, j])
            if stderr:
                se[:, k] = np.divide(e0[:, j] * value[:, k], x[0, :, j], out=np.zeros(h), where=x[0, :, j] > 0)
    return chans, value, se


def _optics(model, x: np.ndarray) -> np.ndarray:
    """The head's reading of channel signals ``x`` (C, N): the first channel, or the two-channel formula on
    the channels' real counts (:meth:`simulator.sensor_models.model.SensorModel.optics_value`)."""
    if not model.two_channel:
        return np.array(x[0], float)
    from simulator.sensor_models.electronics import Setting, firmware_values

    el = model.electronics
    f = el.sensitivity(Setting(el.scale_gain, el.scale_integration_ms))
    counts = np.stack([x[c] * ch.counts_per_unit * f for c, ch in enumerate(model.channels)], axis=1)
    n = counts.shape[0]
    return firmware_values(el, counts, np.full(n, el.scale_gain), np.full(n, el.scale_integration_ms))


def apply_heads(heads, mean: np.ndarray, value: np.ndarray, stderr: np.ndarray | None = None, se=None) -> None:
    """Put the heads' readings into the hourly readings (H, S) in place."""
    mean[:, heads.index] = value
    if stderr is not None and se is not None:
        stderr[:, heads.index] = se


def head_sun(heads, sun: np.ndarray) -> np.ndarray:
    """The direct sun (H, S) as the heads report it (one channel: σ_sun × it; ASE over modelled candidates)."""
    out = sun.copy()
    for k, i in enumerate(heads.index):
        m, f = heads.models[k], heads.factors[k][SUN]
        out[:, i] = _optics(m, np.array([sun[:, i] * float(f[c]) for c in range(len(m.channels))]))
    return out


def lamp_channels(heads, k: int, lamp_row: np.ndarray, lamp_names: list, gsel: list[int]) -> np.ndarray:
    """Head k's channel signals (C,) of the lamp groups ``gsel`` at full output (``lamp_row`` (G,) its lux)."""
    f, m = heads.factors[k], heads.models[k]
    return np.array([sum(float(f[lamp_names[g]][c]) * float(lamp_row[g]) for g in gsel) for c in range(len(m.channels))])


def lamp_readings(heads, lamp: np.ndarray, lamp_names: list, gsel: list[int]) -> np.ndarray:
    """Every candidate's reading (S,) of the lamp groups ``gsel`` at full output: lux, the heads' reports
    (``heads`` None: no modelled candidate)."""
    out = lamp[:, gsel].sum(axis=1)
    for k, i in enumerate(() if heads is None else heads.index):
        out[i] = float(_optics(heads.models[k], lamp_channels(heads, k, lamp[i], lamp_names, gsel)[:, None])[0])
    return out


def overcast_channels(heads, k: int, sky_group: str, overcast_lx: float) -> np.ndarray:
    """Head k's channel signals (C,) under the CIE overcast sky whose (true, through r) reading is ``overcast_lx``."""
    f = heads.factors[k][sky_group]
    return np.asarray(f, float) * overcast_lx


def overcast_readings(heads, sky_group: str, df: np.ndarray, sky_lx: float) -> np.ndarray:
    """Daylight factors (S,) with the heads' as they report the overcast sky (its ``sky_lx`` horizontal)."""
    out = df.copy()
    for k, i in enumerate(heads.index):
        x = overcast_channels(heads, k, sky_group, float(df[i]) * sky_lx)
        out[i] = float(_optics(heads.models[k], x[:, None])[0]) / sky_lx
    return out


def hour_noise(seed: int, sensor: str, rows: np.ndarray, n_rows: int, channels: int) -> np.ndarray:
    """Standard normal draws (len(rows), channels) of a device's noise in the weather rows ``rows``: row r's
    draw is row r of one stream per sensor (:func:`simulator.sensor_models.electronics.reading_stream` of
    the seed and ``<sensor>|hours``), so it is the same whatever hours are analysed."""
    from simulator.sensor_models.electronics import reading_stream

    return reading_stream(seed, f"{sensor}|hours").standard_normal((n_rows, channels))[np.asarray(rows)]


@dataclass(frozen=True)
class DeviceOutcome(CT.ControlOutcome):
    """A control's year on a device's readings: also the occupied hours it saturated, and how far below
    target (lux) the zone may fall and still count as at target: the zone illuminance one code of the
    reading and twice its noise stand for, as near the target as the device holds it."""

    saturated_hours: float = 0.0
    target_tolerance_lx: float = 0.0


#: halvings of [u_min, 1] where the reading of daylight plus lamps has no closed form (a two-channel formula)
_BISECTIONS = 30


def _levels_closed_loop(m, setting, x_day: np.ndarray, lamp: np.ndarray, setpoint: float, z: np.ndarray,
                        u_min: float) -> np.ndarray:  # fmt: skip
    """The lowest u ∈ [u_min, 1] per hour whose device reading of x_day + u·lamp reaches ``setpoint`` (1
    where none does); ``x_day`` (C, H), ``lamp`` (C,), ``z`` (H, C)."""
    from simulator.sensor_models.electronics import read_devices, signal_reaching

    el, gain, t = m.electronics, setting[0], setting[1]
    if len(m.channels) == 1 and el.firmware == "linear":
        x_star = signal_reaching(el, m.channels[0], setpoint, z[:, 0], gain, t)
        with np.errstate(invalid="ignore"):
            u = (x_star - x_day[0]) / lamp[0]
        u = np.where(np.isposinf(x_star), 1.0, np.where(np.isneginf(x_star), u_min, u))
        return np.clip(u, u_min, 1.0)

    def reaches(u):
        return read_devices(el, m.channels, (x_day + u[None, :] * lamp[:, None]).T, z, gain, t).value >= setpoint

    h = x_day.shape[1]
    lo, hi = np.full(h, u_min), np.ones(h)
    at_lo, at_hi = reaches(lo), reaches(hi)
    for _ in range(_BISECTIONS):
        mid = 0.5 * (lo + hi)
        r = reaches(mid)
        hi, lo = np.where(r, mid, hi), np.where(r, lo, mid)
    return np.where(at_lo, u_min, np.where(at_hi, hi, 1.0))


def control_outcome(spec, m, setting, x_day: np.ndarray, lamp: np.ndarray, overcast: np.ndarray, overcast_zone_lx: float,
                    zone_day: np.ndarray, lamp_zone_lx: float, target_lx: float, z: np.ndarray):  # fmt: skip
    """A modelled photosensor's year under control ``spec`` (a ``[[control]]``), on what its device reports.

    Parameters
    ----------
    m : SensorModel
        With electronics.
    setting : (gain, integration_ms)
        As the candidate set states them (None: the part's default).
    x_day : ndarray, shape (C, H)
        Its channel signals of daylight in the occupied hours.
    lamp : ndarray, shape (C,)
        Its channel signals of the controlled lamps at full output.
    overcast : ndarray, shape (C,)
        Its channel signals under the CIE overcast sky of the daylight factor; ``overcast_zone_lx`` the
        zone's mean daylight then (open-loop commissioning).
    zone_day : ndarray, shape (H,)
        The zone's mean daylight illuminance.
    z : ndarray, shape (H, C)
        The hours' noise draws (:func:`hour_noise`).

    Returns
    -------
    DeviceOutcome, ndarray of bool (H,)
        The outcome (with the hours saturated) and the hours the device saturated. An hour is below
        target where the zone falls short of it by more than the device can hold (``target_tolerance_lx``,
        :func:`precision` at the set point, or at the daylight signal the open loop reads as the target,
        in zone lux): a loop on a quantised, noisy reading settles within that of its set point.
    """
    from simulator.sensor_models.electronics import read_devices

    el, gain, t = m.electronics, setting[0], setting[1]
    h = x_day.shape[1]
    tol = 0.0
    if spec.model == "closed_loop":
        if lamp_zone_lx <= 0 or not np.any(lamp > 0):
            u = np.ones(h)  # nothing to regulate on (as the ideal law)
        else:
            cal = lamp * min(1.0, target_lx / lamp_zone_lx)
            setpoint = float(read_devices(el, m.channels, cal[None, :], 0.0, gain, t).value[0])
            u = _levels_closed_loop(m, setting, x_day, lamp, setpoint, z, spec.min_level)
            full = float(_optics(m, lamp[:, None])[0])
            tol = lamp_zone_lx / full * precision(m, cal, gain, t) if full > 0 else 0.0
        seen = read_devices(el, m.channels, (x_day + u[None, :] * lamp[:, None]).T, z, gain, t)
    else:
        seen = read_devices(el, m.channels, x_day.T, z, gain, t)
        ov = float(read_devices(el, m.channels, overcast[None, :], 0.0, gain, t).value[0])
        k = overcast_zone_lx / ov if ov > 0 else 0.0
        u = CT.levels(spec.model, seen.value, 0.0, lamp_zone_lx, target_lx, spec.min_level, spec.deadband, k)
        if k > 0 and overcast_zone_lx > 0:  # the precision of its estimate where that estimate is the target
            tol = k * precision(m, overcast * (target_lx / overcast_zone_lx), gain, t)
    lit = np.asarray(zone_day, np.float64) + u * lamp_zone_lx
    below = float(np.sum(lit < target_lx - tol - 1e-9 * target_lx))
    energy = float(np.sum(u)) / max(len(u), 1)
    return DeviceOutcome(u, energy, below, energy + below / max(len(u), 1), float(seen.saturated.sum()), tol), seen.saturated


def precision(m, x: np.ndarray, gain, integration_ms) -> float:
    """How finely the device reads channel signals ``x`` (C,): one code of its first channel plus twice its
    noise's standard deviation, in its reported unit, at the setting it takes for ``x``."""
    from simulator.sensor_models.electronics import Setting, firmware_value, read_device

    el = m.electronics
    d = read_device(el, m.channels, list(np.asarray(x, float)), 0, "", gain, integration_ms)
    if el.firmware == "linear":
        lsb = 1.0 / (m.channels[0].counts_per_unit * el.sensitivity(d.setting))
    else:
        c = np.asarray(d.mean_counts, float)
        s = Setting(d.setting.gain, d.setting.integration_ms)
        lsb = abs(firmware_value(el, c + np.eye(len(c))[0], s) - firmware_value(el, c, s))
    return lsb + 2.0 * d.noise_sd


def setting_of(sensor) -> tuple:
    """(gain, integration_ms) a candidate's sensor states."""
    return (getattr(sensor, "gain", None), getattr(sensor, "integration_ms", None))
