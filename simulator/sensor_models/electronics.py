"""A sensor model's electronics: from each channel's signal to counts, and from counts to the value it reports.

Per channel c, at gain g and integration time t (the part's own lists; a
reading at a gain or time not in them is refused), the mean count is

    μ_c = X_c · counts_per_unit_c · (g / g_ref) · (t / t_ref)^τ + dark_c · t,

X_c the channel's calibrated signal through the head's optics
(:mod:`.spectral`), ``counts_per_unit`` its counts per unit of the model's
quantity at the reference gain and time, τ = 1 for a part whose counts
grow with integration time (an integrating ADC) and 0 for one that
normalises its result (OPT3001), ``dark`` its mean dark counts per second.

**Noise** (the device's own, apart from the Monte Carlo standard error): the
count before conversion is normal with mean μ_c and variance
σ_c² = σ_read² + μ_c / e_c, read noise σ_read (counts) and shot noise from
e_c electrons per count (left out where the part gives none), drawn once
per reading from a stream seeded by the run's seed and the sensor's name
(:func:`reading_stream`), so a run is byte-identical whatever its threads or
workers. The analogue count is then converted: the code is ⌊count⌋ clipped
to [0, 2^bits − 1]; a count at or above full scale is *saturated*, reported
at full scale and flagged, never silently clipped.

**Auto-ranging** (``gain = "auto"``, the default of a part that ranges): the
part picks the most sensitive (gain, time) pair (largest g·t^τ, then the
shortest time) whose noiseless count of every channel stays at or under
``auto_range_max`` × full scale, and the least sensitive where none does
(that reading saturates, flagged). An OPT3001's automatic full-scale
setting picks its exponent the same way. A sensor that sets neither gain
nor time reads at the part's ``default_gain`` and ``default_integration_ms``
(``"auto"``: ranged), else at its reference setting.

**Firmware**: ``linear``: value = code₀ / (counts_per_unit₀ · (g/g_ref) ·
(t/t_ref)^τ), one LSB apart; ``two_channel``: the datasheet's piecewise
formula in the ratio of the two channels' codes, each first scaled to the
formula's nominal gain and time (``scale_gain``, ``scale_integration_ms``):
for the first segment whose ``ratio_max`` ≥ C₁/C₀,
value = k₀·C₀ − k₁·C₀·(C₁/C₀)^p (p = 1: k₀·C₀ − k₁·C₁), 0 past the last.
"""

from __future__ import annotations

import hashlib
import math
from dataclasses import dataclass, field

import numpy as np

from simulator.errors import UserError

__all__ = ["Segment", "Electronics", "Setting", "DeviceReading", "reading_stream", "read_device", "firmware_value",
           "candidate_settings", "DeviceReadings", "read_devices", "firmware_values", "signal_reaching"]


@dataclass(frozen=True)
class Segment:
    """One piece of a two-channel formula: used where C₁/C₀ ≤ ``ratio_max``."""

    ratio_max: float
    k0: float
    k1: float
    power: float = 1.0


@dataclass(frozen=True)
class Setting:
    gain: float
    integration_ms: float


@dataclass(frozen=True)
class Electronics:
    """See module docstring.

    Attributes
    ----------
    bits : int
        ADC resolution: full scale 2^bits − 1.
    gains, integration_ms : tuple of float
        The part's settings.
    reference_gain, reference_integration_ms : float
        The setting ``counts_per_unit`` is given at.
    time_scaled : bool
        Counts grow with integration time (τ = 1).
    read_noise_counts : float
    electrons_per_count : float or None
        Shot noise; None: none modelled.
    auto_range : bool
        The part ranges by itself (``gain = "auto"`` allowed, and the default).
    auto_range_max : float
        Auto-ranging's ceiling, a fraction of full scale.
    firmware : {"linear", "two_channel"}
    segments : tuple of Segment
        ``two_channel`` only.
    scale_gain, scale_integration_ms : float
        ``two_channel``: the gain and time the formula's coefficients are for.
    """

    bits: int
    gains: tuple[float, ...]
    integration_ms: tuple[float, ...]
    reference_gain: float
    reference_integration_ms: float
    time_scaled: bool = True
    read_noise_counts: float = 0.0
    electrons_per_count: float | None = None
    auto_range: bool = False
    auto_range_max: float = 0.8
    firmware: str = "linear"
    segments: tuple[Segment, ...] = field(default=())
    scale_gain: float = 1.0
    scale_integration_ms: float = 1.0
    full_scale_counts: tuple[int, ...] = ()
    default_gain: float | str | None = None
    default_integration_ms: float | None = None

    @property
    def full_scale(self) -> int:
        """2^bits − 1, the register's largest code."""
        return (1 << self.bits) - 1

    def full_scale_at(self, s: "Setting") -> int:
        """The largest code at a setting: ``full_scale_counts`` of its integration time where the part
        states them (an integrating ADC that cannot count that far in a short time), else 2^bits − 1."""
        if self.full_scale_counts:
            for t, fs in zip(self.integration_ms, self.full_scale_counts):
                if math.isclose(t, s.integration_ms, rel_tol=1e-9):
                    return fs
        return self.full_scale

    def sensitivity(self, s: Setting) -> float:
        """(g / g_ref)·(t / t_ref)^τ: the factor on counts_per_unit."""
        f = s.gain / self.reference_gain
        if self.time_scaled:
            f *= s.integration_ms / self.reference_integration_ms
        return f

    def settings(self) -> list[Setting]:
        """Every (gain, time) pair, most sensitive first (ties: the shortest time first)."""
        out = [Setting(g, t) for g in self.gains for t in self.integration_ms]
        return sorted(out, key=lambda s: (-self.sensitivity(s), s.integration_ms))

    def check_setting(self, gain, integration_ms, where: str) -> None:
        """Refuse a gain or time the part does not have: one line ``<where>.gain: ...`` (``where`` names the
        config file and the sensor's key)."""
        gains = ", ".join(f"{g:g}" for g in self.gains)
        if gain == "auto":
            if not self.auto_range:
                raise UserError(f"{where}.gain: 'auto', but this part does not range by itself; choose one of {gains}")
        elif gain is not None and not any(math.isclose(gain, g, rel_tol=1e-9) for g in self.gains):
            raise UserError(f"{where}.gain: {gain:g} is not one of the part's gains ({gains})")
        if integration_ms is not None and not any(math.isclose(integration_ms, t, rel_tol=1e-9) for t in self.integration_ms):
            raise UserError(f"{where}.integration_ms: {integration_ms:g} is not one of the part's "
                            f"({', '.join(f'{t:g}' for t in self.integration_ms)})")


@dataclass
class DeviceReading:
    """What the device gives for one reading."""

    value: float  # the reported value, in the model's unit
    counts: tuple[int, ...]  # per channel: the ADC code
    saturated: bool
    noise_sd: float  # the standard deviation of the reported value from the device's noise (linear firmware: exact)
    setting: Setting
    mean_counts: tuple[float, ...]  # per channel: the noiseless count μ_c


def reading_stream(seed: int, sensor: str) -> np.random.Generator:
    """The noise stream of one reading: seeded by the run's seed and a SHA-256 of the sensor's name, so
    the draw does not depend on the order, threads or workers the readings came from."""
    digest = hashlib.sha256(sensor.encode("utf-8")).digest()
    return np.random.default_rng([int(seed), *np.frombuffer(digest[:16], np.uint32).tolist()])


def _mean_counts(el: Electronics, signals, channels, s: Setting) -> np.ndarray:
    f = el.sensitivity(s)
    return np.array([x * ch.counts_per_unit * f + ch.dark_counts_per_s * s.integration_ms * 1e-3
                     for x, ch in zip(signals, channels)], float)


def candidate_settings(el: Electronics, gain=None, integration_ms=None) -> list[Setting]:
    """The settings a reading at ``gain`` and ``integration_ms`` (as a sensor states them; None: the part's
    default) may be taken at, in the order auto-ranging tries them: one where the setting is fixed."""
    if gain is None and integration_ms is None:
        gain, integration_ms = el.default_gain, el.default_integration_ms
        if gain is None and integration_ms is None:
            return [Setting(el.reference_gain, el.reference_integration_ms)]
    if gain is None and integration_ms is not None:
        gain = "auto" if el.auto_range else el.reference_gain
    if gain != "auto" and integration_ms is None and not el.auto_range:
        integration_ms = el.reference_integration_ms
    if gain != "auto" and integration_ms is not None:
        return [Setting(float(gain), float(integration_ms))]
    cands = el.settings()
    if gain != "auto":
        cands = [s for s in cands if math.isclose(s.gain, gain, rel_tol=1e-9)]
    if integration_ms is not None:
        cands = [s for s in cands if math.isclose(s.integration_ms, integration_ms, rel_tol=1e-9)]
    return cands


def _choose(el: Electronics, signals, channels, gain, integration_ms) -> Setting:
    cands = candidate_settings(el, gain, integration_ms)
    if len(cands) == 1:
        return cands[0]
    for s in cands:
        if np.all(_mean_counts(el, signals, channels, s) <= el.auto_range_max * el.full_scale_at(s)):
            return s
    return cands[-1]


def _firmware(el: Electronics, codes: np.ndarray, channels, s: Setting) -> float:
    if el.firmware == "linear":
        return float(codes[0]) / (channels[0].counts_per_unit * el.sensitivity(s))
    # two_channel: the codes scaled to the formula's nominal gain and time
    scale = (el.scale_gain / s.gain) * (el.scale_integration_ms / s.integration_ms)
    c0, c1 = float(codes[0]) * scale, float(codes[1]) * scale
    if c0 <= 0:
        return 0.0
    ratio = c1 / c0
    for seg in el.segments:
        if ratio <= seg.ratio_max:
            return max(0.0, seg.k0 * c0 - seg.k1 * c0 * ratio ** seg.power)
    return 0.0


def read_device(el: Electronics, channels, signals, seed: int, sensor: str, gain=None,
                integration_ms=None) -> DeviceReading:
    """The device's reading of channel signals ``signals`` (one per channel, in the model's unit): the
    setting (given, or auto-ranged), the noisy counts, the codes, saturation and the reported value.

    ``noise_sd`` is the reported value's standard deviation from the noise: for linear firmware
    σ₀ / (counts_per_unit₀ · sensitivity) (quantisation's own ±½ LSB left out); for two-channel
    firmware the spread of the formula over the two channels' σ by first-order propagation."""
    s = _choose(el, signals, channels, gain, integration_ms)
    mu = _mean_counts(el, signals, channels, s)
    var = np.full(len(mu), el.read_noise_counts ** 2)
    if el.electrons_per_count:
        var = var + np.maximum(mu, 0.0) / el.electrons_per_count
    sd = np.sqrt(var)
    z = reading_stream(seed, sensor).standard_normal(len(mu))
    analogue = mu + sd * z
    fs = el.full_scale_at(s)
    saturated = bool(np.any(analogue >= fs))
    codes = np.clip(np.floor(analogue), 0, fs).astype(np.int64)
    value = _firmware(el, codes, channels, s)
    if el.firmware == "linear":
        noise_sd = float(sd[0]) / (channels[0].counts_per_unit * el.sensitivity(s))
    else:  # first-order propagation through the formula at the noiseless counts
        h = np.maximum(sd, 1e-6)
        grads = []
        for c in range(2):
            d = np.zeros(len(mu))
            d[c] = h[c]
            grads.append((_firmware_real(el, mu + d, s) - _firmware_real(el, mu - d, s)) / (2 * h[c]))
        noise_sd = float(math.hypot(grads[0] * sd[0], grads[1] * sd[1]))
    return DeviceReading(value, tuple(int(c) for c in codes), saturated, noise_sd, s, tuple(float(m) for m in mu))


def _firmware_real(el: Electronics, counts: np.ndarray, s: Setting) -> float:
    """The two-channel formula on real-valued counts (for the noise's propagation)."""
    return _firmware(el, np.asarray(counts, float), (None, None), s)


def firmware_value(el: Electronics, counts, s: Setting) -> float:
    """A two-channel part's formula on real-valued counts at setting ``s`` (no quantisation)."""
    return _firmware_real(el, np.asarray(counts, float), s)


# ---------------------------------------------------------------- many readings at once (a year's hours)


@dataclass
class DeviceReadings:
    """:class:`DeviceReading` of N readings, as arrays."""

    value: np.ndarray  # (N,) the reported values
    counts: np.ndarray  # (N, C) int64 ADC codes
    saturated: np.ndarray  # (N,) bool
    gain: np.ndarray  # (N,) the setting each was read at
    integration_ms: np.ndarray  # (N,)


def _setting_arrays(el: Electronics, channels, cands: list[Setting]):
    """Per candidate setting: counts per unit of each channel (S, C), dark counts (S, C), full scale (S,)."""
    sens = np.array([el.sensitivity(s) for s in cands])
    cpu = np.array([ch.counts_per_unit for ch in channels], float)
    dark = np.array([[ch.dark_counts_per_s * s.integration_ms * 1e-3 for ch in channels] for s in cands])
    fs = np.array([el.full_scale_at(s) for s in cands], float)
    return sens, cpu, dark, fs


def read_devices(el: Electronics, channels, signals, z, gain=None, integration_ms=None) -> DeviceReadings:
    """:func:`read_device` of N readings at once: ``signals`` (N, C) each channel's signal, ``z`` (N, C) the
    standard normal draws of their noise (0: the noiseless count, as a reading averaged over many
    conversions gives). Reading n is what :func:`read_device` gives for ``signals[n]`` with the draw
    ``z[n]`` in place of its own stream's: the same setting (auto-ranged per reading on its noiseless
    counts), counts, saturation and firmware."""
    x = np.atleast_2d(np.asarray(signals, float))
    zz = np.broadcast_to(np.asarray(z, float), x.shape)
    cands = candidate_settings(el, gain, integration_ms)
    sens, cpu, dark, fs = _setting_arrays(el, channels, cands)
    mu_all = x[:, None, :] * cpu[None, None, :] * sens[None, :, None] + dark[None, :, :]  # (N, S, C)
    if len(cands) == 1:
        pick = np.zeros(len(x), np.int64)
    else:
        ok = np.all(mu_all <= (el.auto_range_max * fs)[None, :, None], axis=2)
        pick = np.where(ok.any(axis=1), np.argmax(ok, axis=1), len(cands) - 1)
    rows = np.arange(len(x))
    mu = mu_all[rows, pick]  # (N, C)
    var = np.full_like(mu, el.read_noise_counts ** 2)
    if el.electrons_per_count:
        var = var + np.maximum(mu, 0.0) / el.electrons_per_count
    analogue = mu + np.sqrt(var) * zz
    top = fs[pick][:, None]
    saturated = np.any(analogue >= top, axis=1)
    codes = np.clip(np.floor(analogue), 0, top).astype(np.int64)
    g = np.array([s.gain for s in cands])[pick]
    t = np.array([s.integration_ms for s in cands])[pick]
    if el.firmware == "linear":
        value = codes[:, 0] / (channels[0].counts_per_unit * sens[pick])
    else:
        value = firmware_values(el, codes.astype(float), g, t)
    return DeviceReadings(value, codes, saturated, g, t)


def firmware_values(el: Electronics, counts: np.ndarray, gain: np.ndarray, integration_ms: np.ndarray) -> np.ndarray:
    """A two-channel part's formula on counts (N, 2) read at settings (N,) (:func:`_firmware`, vectorised)."""
    scale = (el.scale_gain / np.asarray(gain, float)) * (el.scale_integration_ms / np.asarray(integration_ms, float))
    c0, c1 = counts[:, 0] * scale, counts[:, 1] * scale
    out = np.zeros(len(c0))
    pos = c0 > 0
    ratio = np.divide(c1, c0, out=np.zeros_like(c0), where=pos)
    done = ~pos
    for seg in el.segments:
        m = ~done & (ratio <= seg.ratio_max)
        out[m] = np.maximum(0.0, seg.k0 * c0[m] - seg.k1 * c0[m] * ratio[m] ** seg.power)
        done |= m
    return out


def signal_reaching(el: Electronics, channel, value: float, z, gain=None, integration_ms=None) -> np.ndarray:
    """The smallest signal x of a one-channel part with linear firmware whose reading reaches ``value``,
    per reading (``z`` (N,), its noise draw): ``read_devices(x).value ≥ value`` exactly where the signal is
    at least the result (−inf: any signal; +inf: none, the part saturates below ``value``).

    At a setting of a counts per unit and dark counts b, a reading is ⌊μ + σ(μ)·z⌋/a with μ = a·x + b,
    σ² = σ_r² + μ/e; it reaches ``value`` where the code reaches C = ⌈a·value⌉, i.e. where
    μ + σ(μ)·z ≥ C: μ* = C − σ_r·z without shot noise, else μ* = e(t² − σ_r²) with t the positive root
    of e·t² + z·t − (C + e·σ_r²) = 0. Auto-ranging picks a setting by x alone, each over an interval of
    signals (from the largest limit of the settings tried before it to its own limit, auto_range_max ×
    full scale): the answer is the least over settings of the least x ≥ x* in the setting's interval."""
    z = np.asarray(z, float)
    cands = candidate_settings(el, gain, integration_ms)
    sens, cpu, dark, fs = _setting_arrays(el, [channel], cands)
    a = cpu[0] * sens  # (S,)
    b = dark[:, 0]
    limit = (el.auto_range_max * fs - b) / a  # the largest signal each setting is chosen for (when tried)
    best = np.full(len(z), np.inf)
    r2 = el.read_noise_counts ** 2
    e = el.electrons_per_count
    for j in range(len(cands)):
        lo = -np.inf if j == 0 else float(np.max(limit[:j]))
        hi = np.inf if (j == len(cands) - 1 or len(cands) == 1) else float(limit[j])
        if lo >= hi:
            continue  # never chosen
        code = math.ceil(value * a[j] * (1.0 - 1e-12))
        if code > fs[j]:
            continue  # the reading saturates below the value at this setting
        if code <= 0:
            x_star = np.full(len(z), -np.inf)
        else:
            if e:
                t = (-z + np.sqrt(z * z + 4.0 * e * (code + e * r2))) / (2.0 * e)
                mu = e * (t * t - r2)
                mu = np.where(mu < 0.0, code - math.sqrt(r2) * z, mu)  # below 0 counts there is no shot noise
            else:
                mu = code - math.sqrt(r2) * z
            x_star = (mu - b[j]) / a[j]
        cand = np.maximum(x_star, lo)
        best = np.where(cand <= hi, np.minimum(best, cand), best)
    return best
