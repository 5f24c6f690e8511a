"""A sensor model as a file says it, and the bundled ones.

A model is a TOML file (bundled in ``simulator/sensor_models/data/``, or
the user's, relative to the config that names it)::

    name = "my_head"                 # how CSVs and records name it
    title = "A photometer head"      # optional
    reports = "illuminance"          # illuminance (lx) | irradiance (W/m², 380–780 nm) | ppfd (µmol/m²/s)
    calibration = "A"                # reads the true quantity under this illuminant at normal incidence
    source = "where the numbers come from"

    [angular]                        # one of:
    cos_power = 1.0                  #   r = cosⁿ θ
    # half_power_angle_deg = 45      #   cosⁿ θ with r = ½ at this angle
    # table = "head.csv"             #   angle_deg,response[,response_<azimuth>...]

    [[channel]]                      # one or more; the first is the reported one
    name = "als"
    responsivity = "photopic"        # photopic | par | a responsivity CSV (300–1100 nm)
    counts_per_unit = 100.0          # with [electronics]: counts per unit of `reports` under the
                                     # calibration illuminant at the reference gain and time
    dark_counts_per_s = 0.0

    [electronics]                    # optional: without it the device reports the optics' signal
    bits = 16
    gains = [1, 2]
    integration_ms = [100, 800]
    reference_gain = 1
    reference_integration_ms = 100
    time_scaled = true
    read_noise_counts = 1.0
    electrons_per_count = 4.0        # optional: shot noise
    auto_range = false
    auto_range_max = 0.8
    firmware = "linear"              # linear | two_channel
    # two_channel: scale_gain, scale_integration_ms, segments = [[ratio_max, k0, k1, power], ...]

Every problem is one line naming the file and the key (or the CSV's row).
"""

from __future__ import annotations

import difflib
import math
import tomllib
from dataclasses import dataclass, field
from functools import lru_cache
from pathlib import Path

import numpy as np

from simulator.errors import UserError
from simulator.sensor_models.angular import AngularResponse, cos_power, half_power, read_table
from simulator.sensor_models.electronics import Electronics, Segment
from simulator.sensor_models.spectral import (
    QUANTITIES, Channel, calibration_factor, calibration_spectrum, f1_prime, mismatch_factor, named_responsivity,
    responsivity_csv,
)  # fmt: skip

__all__ = ["SensorModel", "BUNDLED_DIR", "bundled_names", "load_model", "model_file", "din_class", "DIN_CLASSES"]

#: where the bundled models live
BUNDLED_DIR = Path(__file__).with_name("data")

#: DIN 5032-7 class limits (f1′, f2), fractions, best first; class L's f2 is class A's (DIN 5032-7 applies
#: class A's limits to a class L meter away from normal incidence) — docs/REFERENCES.md §Sensor models
DIN_CLASSES = (("L", 0.015, 0.015), ("A", 0.03, 0.015), ("B", 0.06, 0.03), ("C", 0.09, 0.06))


def din_class(f1p: float, f2: float) -> str:
    """The best DIN 5032-7 class whose f1′ and f2 limits the model meets, or ``"none"``."""
    for name, l1, l2 in DIN_CLASSES:
        if f1p <= l1 + 1e-12 and f2 <= l2 + 1e-12:
            return name
    return "none"


@dataclass(frozen=True)
class SensorModel:
    """A validated model (see module docstring).

    Attributes
    ----------
    name, title, source : str
    quantity : str
        A key of :data:`simulator.sensor_models.spectral.QUANTITIES`.
    calibration : str
        The calibration illuminant's name.
    angular : AngularResponse
    channels : tuple of Channel
    electronics : Electronics or None
    path : Path or None
        The file it was read from.
    notes : tuple of str
    """

    name: str
    title: str
    source: str
    quantity: str
    calibration: str
    angular: AngularResponse
    channels: tuple[Channel, ...]
    electronics: Electronics | None = None
    path: Path | None = None
    notes: tuple[str, ...] = field(default=())

    @property
    def calibration_wide(self) -> np.ndarray:
        return calibration_spectrum(self.calibration).on_wide_grid()

    def calibration_factors(self) -> list[float]:
        """k_c of each channel (:func:`simulator.sensor_models.spectral.calibration_factor`)."""
        cal = self.calibration_wide
        return [calibration_factor(ch.responsivity, self.quantity, cal) for ch in self.channels]

    def f1_prime(self) -> float:
        """f1′ of the first channel (meaningful for an illuminance model)."""
        return f1_prime(self.channels[0].responsivity)

    def f2(self) -> float:
        return self.angular.f2()

    @property
    def two_channel(self) -> bool:
        return self.electronics is not None and self.electronics.firmware == "two_channel"

    def optics_value(self, signals) -> float:
        """What the head reports through ideal electronics (noiseless, no dark counts, unquantised): the
        first channel's signal, or a two-channel part's firmware formula on its channels' real counts
        (homogeneous in the light: any setting gives it; the formula's nominal one is used)."""
        if not self.two_channel:
            return float(signals[0])
        from simulator.sensor_models.electronics import Setting, firmware_value

        el = self.electronics
        s = Setting(el.scale_gain, el.scale_integration_ms)
        counts = np.array([x * ch.counts_per_unit * el.sensitivity(s) for x, ch in zip(signals, self.channels)])
        return firmware_value(el, counts, s)

    def signals_per_true(self, light_wide: np.ndarray) -> list[float]:
        """Each channel's signal per unit of the true quantity of a light (spectrum on the wide grid) at
        normal incidence: k_c ∫ S s_c / ∫ S q."""
        from simulator.sensor_models.spectral import quantity_weights
        from simulator.spectra.wide import wide_weights

        true = float(quantity_weights(self.quantity) @ light_wide)
        return [k * float((ch.responsivity * wide_weights()) @ light_wide) / true
                for k, ch in zip(self.calibration_factors(), self.channels)]

    def mismatch(self, light_wide: np.ndarray) -> float:
        """The spectral mismatch correction factor F of a light: the true quantity over what the head
        reports of it (:meth:`optics_value`). One channel: ISO/CIE 19476's F (:func:`mismatch_factor`);
        two channels: that of the firmware's formula."""
        if self.two_channel:
            v = self.optics_value(self.signals_per_true(light_wide))
            return 1.0 / v if v > 0 else float("nan")
        return mismatch_factor(self.channels[0].responsivity, light_wide, self.quantity, self.calibration_wide)

    def indices(self) -> dict:
        """The quality indices and facts a record or ``probesim sensor`` shows."""
        out = {"name": self.name, "title": self.title, "reports": self.quantity, "calibration": self.calibration,
               "angular": self.angular.name, "integral_sr": self.angular.integral_sr(), "f2": self.f2(),
               "channels": [ch.name for ch in self.channels], "source": self.source}
        if self.quantity == "illuminance" and not self.two_channel:  # f1′ is one channel's index
            f1 = self.f1_prime()
            out.update(f1_prime=f1, din_5032_7_class=din_class(f1, out["f2"]))
        from simulator.spectra.sources import emitter_spectrum

        out["mismatch_F"] = {n: self.mismatch(emitter_spectrum(n).on_wide_grid()) for n in ("A", "D65", "LED-B3", "FL2")}
        if self.electronics is not None:
            el = self.electronics
            out["electronics"] = {"bits": el.bits, "gains": list(el.gains), "integration_ms": list(el.integration_ms),
                                  "auto_range": el.auto_range, "firmware": el.firmware,
                                  "full_scale": [self.full_scale_value(s) for s in (el.settings()[0], el.settings()[-1])]}
        out["notes"] = list(self.notes) + list(self.angular.notes) + [n for ch in self.channels for n in ch.notes]
        return out

    def full_scale_value(self, setting) -> float:
        """The first channel's signal at full scale at ``setting``, in the model's unit."""
        el = self.electronics
        return el.full_scale_at(setting) / (self.channels[0].counts_per_unit * el.sensitivity(setting))


def bundled_names() -> tuple[str, ...]:
    """The bundled models' names."""
    return tuple(sorted(p.stem for p in BUNDLED_DIR.glob("*.toml")))


def model_file(spec: str, base_dir: Path | None, where: str) -> Path:
    """The file a ``model = "..."`` names: a bundled name, or a .toml path relative to ``base_dir``."""
    if spec.lower().endswith(".toml"):
        p = Path(spec)
        if base_dir is not None and not p.is_absolute():
            p = base_dir / p
        if not p.is_file():
            raise UserError(f"{where}: sensor model file {p} not found")
        return p
    names = bundled_names()
    if spec not in names:
        hint = difflib.get_close_matches(spec, names, n=1)
        raise UserError(f"{where}: unknown sensor model {spec!r}" + (f" (did you mean {hint[0]!r}?)" if hint else "")
                        + f"; bundled: {', '.join(names)}, or a .toml file")
    return BUNDLED_DIR / f"{spec}.toml"


def load_model(spec: str, base_dir: Path | None = None, where: str = "model") -> SensorModel:
    """The model a ``model = "..."`` names (bundled name or file), read once per file.

    Raises
    ------
    UserError
        An unknown name (with the bundled ones), a missing file, or any problem in it: one line naming
        ``where``, the file and the key.
    """
    p = model_file(spec, base_dir, where)
    return _read(p.resolve(), p.stat().st_mtime_ns)


_TOP = ("name", "title", "reports", "calibration", "source", "angular", "channel", "electronics")
_ANGULAR = ("cos_power", "half_power_angle_deg", "table")
_CHANNEL = ("name", "responsivity", "shift_nm", "counts_per_unit", "dark_counts_per_s")
_ELECTRONICS = ("bits", "full_scale_counts", "gains", "integration_ms", "reference_gain", "reference_integration_ms",
                "default_gain", "default_integration_ms", "time_scaled", "read_noise_counts", "electrons_per_count",
                "auto_range", "auto_range_max", "firmware", "segments", "scale_gain", "scale_integration_ms")


def _fail(path: Path, key: str, what: str) -> UserError:
    return UserError(f"{path}: {key}: {what}")


def _keys(path, table: dict, allowed: tuple, prefix: str) -> None:
    for k in table:
        if k not in allowed:
            hint = difflib.get_close_matches(k, allowed, n=1)
            raise _fail(path, prefix + k, "unknown key" + (f" (did you mean {hint[0]!r}?)" if hint else "")
                        + f"; expected one of: {', '.join(allowed)}")


def _number(path, table: dict, key: str, prefix: str, default=None, positive=False, nonneg=False):
    if key not in table:
        if default is None:
            raise _fail(path, prefix + key, "required")
        return default
    v = table[key]
    if isinstance(v, bool) or not isinstance(v, (int, float)) or not math.isfinite(v):
        raise _fail(path, prefix + key, f"expected a number, got {v!r}")
    if positive and v <= 0:
        raise _fail(path, prefix + key, f"must be > 0, got {v!r}")
    if nonneg and v < 0:
        raise _fail(path, prefix + key, f"must be ≥ 0, got {v!r}")
    return float(v)


def _string(path, table: dict, key: str, prefix: str, default=None) -> str:
    if key not in table:
        if default is None:
            raise _fail(path, prefix + key, "required")
        return default
    v = table[key]
    if not isinstance(v, str) or not v.strip():
        raise _fail(path, prefix + key, f"expected a non-empty string, got {v!r}")
    return v


def _numbers(path, table: dict, key: str, prefix: str) -> tuple[float, ...]:
    v = table.get(key)
    if not isinstance(v, list) or not v:
        raise _fail(path, prefix + key, "required, a non-empty list of numbers")
    out = []
    for i, x in enumerate(v):
        if isinstance(x, bool) or not isinstance(x, (int, float)) or not math.isfinite(x) or x <= 0:
            raise _fail(path, f"{prefix}{key}[{i}]", f"expected a positive number, got {x!r}")
        out.append(float(x))
    return tuple(out)


@lru_cache(maxsize=64)
def _read(path: Path, mtime_ns: int) -> SensorModel:
    del mtime_ns  # part of the cache key: an edited file is read again
    try:
        raw = tomllib.loads(path.read_text(encoding="utf-8"))
    except tomllib.TOMLDecodeError as e:
        raise UserError(f"{path}: not valid TOML: {e}") from None
    _keys(path, raw, _TOP, "")
    name = _string(path, raw, "name", "")
    quantity = _string(path, raw, "reports", "", "illuminance")
    if quantity not in QUANTITIES:
        raise _fail(path, "reports", f"{quantity!r} is not one of {', '.join(QUANTITIES)}")
    calibration = _string(path, raw, "calibration", "", "A")
    try:
        calibration_spectrum(calibration)
    except UserError as e:
        raise _fail(path, "calibration", str(e)) from None
    angular = _angular(path, raw.get("angular"))
    channels_raw = raw.get("channel")
    if not isinstance(channels_raw, list) or not channels_raw:
        raise _fail(path, "channel", "required: one or more [[channel]] tables")
    electronics = _electronics(path, raw["electronics"]) if "electronics" in raw else None
    channels = tuple(_channel(path, c, i, electronics is not None) for i, c in enumerate(channels_raw))
    if electronics is not None and electronics.firmware == "two_channel" and len(channels) != 2:
        raise _fail(path, "electronics.firmware", f"two_channel needs exactly 2 [[channel]] tables, not {len(channels)}")
    model = SensorModel(name, _string(path, raw, "title", "", name), _string(path, raw, "source", "", ""), quantity,
                        calibration, angular, channels, electronics, path)
    try:
        model.calibration_factors()
    except UserError as e:
        raise _fail(path, "calibration", str(e)) from None
    return model


def _angular(path: Path, table) -> AngularResponse:
    if not isinstance(table, dict):
        raise _fail(path, "angular", "required: a table with one of " + ", ".join(_ANGULAR))
    _keys(path, table, _ANGULAR, "angular.")
    given = [k for k in _ANGULAR if k in table]
    if len(given) != 1:
        raise _fail(path, "angular", f"give exactly one of {', '.join(_ANGULAR)} (got {len(given)})")
    k = given[0]
    if k == "table":
        f = Path(_string(path, table, "table", "angular."))
        return read_table(f if f.is_absolute() else path.parent / f)
    v = _number(path, table, k, "angular.", positive=True)
    try:
        return cos_power(v) if k == "cos_power" else half_power(v)
    except ValueError as e:
        raise _fail(path, f"angular.{k}", str(e)) from None


def _channel(path: Path, table, i: int, electronics: bool) -> Channel:
    prefix = f"channel[{i}]."
    if not isinstance(table, dict):
        raise _fail(path, f"channel[{i}]", "expected a table")
    _keys(path, table, _CHANNEL, prefix)
    name = _string(path, table, "name", prefix, f"ch{i}")
    spec = _string(path, table, "responsivity", prefix)
    notes: tuple[str, ...] = ()
    if spec.lower().endswith(".csv"):
        f = Path(spec)
        s, notes = responsivity_csv(f if f.is_absolute() else path.parent / f)
    else:
        try:
            s = named_responsivity(spec)
        except KeyError:
            raise _fail(path, prefix + "responsivity", f"{spec!r}: expected 'photopic', 'par' or a .csv file") from None
    shift = _number(path, table, "shift_nm", prefix, 0.0)
    if shift != 0.0:  # the curve moved along λ: s(λ) = s₀(λ − shift)
        from simulator.spectra.wide import WIDE_NM

        s = np.interp(WIDE_NM - shift, WIDE_NM, s, left=0.0, right=0.0)
        s = s / s.max()
        spec = f"{spec} shifted {shift:+g} nm"
    cpu = _number(path, table, "counts_per_unit", prefix, positive=True) if electronics else None
    dark = _number(path, table, "dark_counts_per_s", prefix, 0.0, nonneg=True)
    return Channel(name, s, spec, cpu, dark, notes)


def _electronics(path: Path, table) -> Electronics:
    p = "electronics."
    if not isinstance(table, dict):
        raise _fail(path, "electronics", "expected a table")
    _keys(path, table, _ELECTRONICS, p)
    bits = table.get("bits")
    if isinstance(bits, bool) or not isinstance(bits, int) or not 1 <= bits <= 32:
        raise _fail(path, p + "bits", f"expected an integer 1–32, got {bits!r}")
    gains, times = _numbers(path, table, "gains", p), _numbers(path, table, "integration_ms", p)
    ref_g = _number(path, table, "reference_gain", p, gains[0], positive=True)
    ref_t = _number(path, table, "reference_integration_ms", p, times[0], positive=True)
    firmware = _string(path, table, "firmware", p, "linear")
    if firmware not in ("linear", "two_channel"):
        raise _fail(path, p + "firmware", f"{firmware!r} is not one of linear, two_channel")
    flags = {}
    for key, default in (("time_scaled", True), ("auto_range", False)):
        v = table.get(key, default)
        if not isinstance(v, bool):
            raise _fail(path, p + key, f"expected true or false, got {v!r}")
        flags[key] = v
    e_per = table.get("electrons_per_count")
    if e_per is not None:
        e_per = _number(path, table, "electrons_per_count", p, positive=True)
    segments: tuple[Segment, ...] = ()
    if firmware == "two_channel":
        raw = table.get("segments")
        if not isinstance(raw, list) or not raw:
            raise _fail(path, p + "segments", "required for two_channel: [[ratio_max, k0, k1, power], ...]")
        segs = []
        for i, row in enumerate(raw):
            if (not isinstance(row, list) or len(row) != 4 or
                    any(isinstance(x, bool) or not isinstance(x, (int, float)) or not math.isfinite(x) for x in row)):
                raise _fail(path, f"{p}segments[{i}]", f"expected [ratio_max, k0, k1, power], got {row!r}")
            if segs and row[0] <= segs[-1].ratio_max:
                raise _fail(path, f"{p}segments[{i}]", "ratio_max must increase")
            segs.append(Segment(*map(float, row)))
        segments = tuple(segs)
    auto_max = _number(path, table, "auto_range_max", p, 0.8, positive=True)
    if auto_max > 1:
        raise _fail(path, p + "auto_range_max", f"a fraction of full scale, ≤ 1, got {auto_max!r}")
    fs = ()
    if "full_scale_counts" in table:
        fs = _numbers(path, table, "full_scale_counts", p)
        if len(fs) != len(times) or any(f > (1 << bits) - 1 or f != int(f) for f in fs):
            raise _fail(path, p + "full_scale_counts", f"one whole count ≤ 2^bits − 1 per integration time ({len(times)})")
    default_gain = table.get("default_gain")
    if default_gain is not None and default_gain != "auto":
        default_gain = _number(path, table, "default_gain", p, positive=True)
    if default_gain == "auto" and not flags["auto_range"]:
        raise _fail(path, p + "default_gain", "'auto' needs auto_range = true")
    default_t = table.get("default_integration_ms")
    if default_t is not None:
        default_t = _number(path, table, "default_integration_ms", p, positive=True)
    el = Electronics(bits, gains, times, ref_g, ref_t, flags["time_scaled"],
                     _number(path, table, "read_noise_counts", p, 0.0, nonneg=True), e_per, flags["auto_range"],
                     auto_max, firmware, segments, _number(path, table, "scale_gain", p, ref_g, positive=True),
                     _number(path, table, "scale_integration_ms", p, ref_t, positive=True), tuple(int(f) for f in fs),
                     default_gain, default_t)
    for key, g, t in (("default_gain", default_gain, None), ("default_integration_ms", None, default_t)):
        try:
            el.check_setting(g, t, f"{path}: electronics")
        except UserError as e:
            raise UserError(str(e).replace("electronics.gain", "electronics." + key).replace(
                "electronics.integration_ms", "electronics." + key)) from None
    return el
