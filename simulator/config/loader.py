"""Run configs: a TOML file read into a fully validated :class:`RunConfig`.

A config names the stage to trace, how to read its light values, the
simulation settings, and the sensors (single ``[[sensor]]`` entries and
``[[grid]]`` rectangles expanded into irradiance sensors at cell centres).
Everything is checked here, before any stage is read or kernel compiled: the
first problem found is raised as a :class:`~simulator.errors.UserError` whose
one-line message names the config file and the key path, e.g.
``configs/a.toml: sensor[2].normal: zero-length vector``.

Paths in a config (``stage``, ``output.csv``) are relative to the config
file's folder; paths given on the command line (see :func:`apply_overrides`)
are relative to the current directory.

Schema
------
::

    stage = "../stages/quickstart.usda"   # required, must exist
    light_units = "photometric"           # or "radiometric"
    radiometric_spectrum = "E"            # or "D65"
    variants = { reflectance = "rho_0_9" } # optional: variant set -> variant,
                                          # selected on every prim with that set

    [simulation]
    samples = 1024        # int > 0 (first-batch size when adaptive)
    seed = 1              # 0 <= int < 2**31
    method = "auto"       # auto | analytic | light | bsdf | mis | path
    device = "cpu"        # cpu | cuda | auto
    rel_error = 0.01      # optional, 0 < x < 1: adaptive stopping target
    abs_error = 0.0       # >= 0, absolute floor near zero
    max_samples = 1048576 # optional int > 0, per-sensor cap when adaptive
    time_limit_s = 60.0   # optional float > 0
    max_depth = -1        # int >= -1; -1 = unlimited (Russian roulette)
    threads = 0           # int >= 0; 0 = all cores

    [[sensor]]            # irradiance | radiance | patch | probe
    name = "desk"
    kind = "irradiance"
    position = [0, 0, 0.75]
    normal = [0, 0, 1]

    [[sensor]]            # full-sphere light probe
    name = "centre"
    kind = "probe"
    position = [0, 0, 1.5]
    resolution = [64, 32] # lat-long map (width, height) in pixels, optional

    [[grid]]              # expanded into IRRADIANCE sensors "floor[i,j]"
    name = "floor"
    position = [0, 0, 0]
    normal = [0, 0, 1]
    size = [4, 3]
    up = [0, 1, 0]
    spacing = 0.5         # or [sx, sy]

    [output]
    csv = "out.csv"       # default: "<config stem>.csv" beside the config

Vectors are in the probesim world frame (metres, right-handed, Z up).
"""

from __future__ import annotations

import difflib
import math
import os
import tomllib
from dataclasses import dataclass, field, replace
from pathlib import Path
from typing import Any

import numpy as np

from simulator.errors import UserError
from simulator.engine.methods import COMPONENTS, METHODS  # estimator and component names
from simulator.scene.model import DEFAULT_PROBE_RESOLUTION, MAX_PROBE_PIXELS, SENSOR_KINDS, Sensor, SensorKind, patch_width_axis
from simulator.units import SPECTRA

__all__ = [
    "COMPONENTS",
    "METHODS",
    "DEVICES",
    "LIGHT_UNITS",
    "SENSOR_KINDS",
    "DEFAULT_MAX_SAMPLES",
    "DEFAULT_PROBE_RESOLUTION",
    "SensorKind",
    "SimulationConfig",
    "GridConfig",
    "OutputConfig",
    "RunConfig",
    "load_config",
    "apply_overrides",
]

#: device names accepted by ``simulation.device`` and ``--device``
DEVICES = ("cpu", "cuda", "auto")
#: accepted values of ``light_units``
LIGHT_UNITS = ("photometric", "radiometric")
#: per-sensor sample cap of an adaptive run when ``max_samples`` is absent
DEFAULT_MAX_SAMPLES = 2**20

_SEED_LIMIT = 2**31
# below this sine of the angle between two directions they count as parallel
_PARALLEL_SIN = 1e-6

_TOP_KEYS = ("stage", "light_units", "radiometric_spectrum", "variants", "simulation", "sensor", "grid", "output")
_SIM_KEYS = (
    "samples",
    "seed",
    "method",
    "device",
    "rel_error",
    "abs_error",
    "max_samples",
    "time_limit_s",
    "max_depth",
    "threads",
    "component",
    "confidence",
)
_SENSOR_COMMON_KEYS = ("name", "kind", "position")
_SENSOR_KIND_KEYS = {
    "irradiance": ("normal",),
    "radiance": ("direction", "half_angle_deg"),
    "patch": ("normal", "size", "up"),
    "probe": ("resolution",),
}
_SENSOR_ALL_KEYS = _SENSOR_COMMON_KEYS + ("normal", "direction", "half_angle_deg", "size", "up", "resolution")
_GRID_KEYS = ("name", "position", "normal", "size", "up", "spacing")
_OUTPUT_KEYS = ("csv",)


# --------------------------------------------------------------------------- records


@dataclass(frozen=True)
class SimulationConfig:
    """The ``[simulation]`` table.

    Attributes
    ----------
    samples : int
        Samples per sensor (the fixed budget), or the first-batch size of an
        adaptive run. > 0.
    seed : int
        Random seed, ``0 <= seed < 2**31``.
    method : str
        One of :data:`METHODS`.
    device : str
        One of :data:`DEVICES`.
    rel_error : float or None
        Adaptive stopping target: 95% confidence half-width over |estimate|,
        in (0, 1). None: fixed budget of ``samples``.
    abs_error : float
        Absolute half-width floor for readings near zero, >= 0.
    max_samples : int or None
        Per-sensor sample cap of an adaptive run; None when absent (see
        :attr:`sample_cap`).
    time_limit_s : float or None
        Wall-clock limit in seconds, > 0; None when absent.
    max_depth : int
        Bounce cap of the ``path`` method; -1 = unlimited.
    threads : int
        CPU worker threads; 0 = all cores.
    confidence : float
        Confidence of the adaptive stop's interval, in (0.5, 1): 0.95 (the
        default) stops when 1.96·stderr ≤ the target, so about 1 sensor in 20
        ends beyond it; 0.999 uses 3.29·stderr, for a guarantee across many
        sensors.
    component : str
        Which light the readings count: ``total``, ``direct`` (straight from
        emitters) or ``indirect`` (reflected at least once; method ``path``).
    """

    samples: int = 1024
    seed: int = 1
    method: str = "auto"
    device: str = "cpu"
    rel_error: float | None = None
    abs_error: float = 0.0
    max_samples: int | None = None
    time_limit_s: float | None = None
    max_depth: int = -1
    threads: int = 0
    component: str = "total"
    confidence: float = 0.95

    @property
    def adaptive(self) -> bool:
        """True when sensors stop on ``rel_error`` rather than a fixed budget."""
        return self.rel_error is not None

    @property
    def sample_cap(self) -> int:
        """``max_samples``, or :data:`DEFAULT_MAX_SAMPLES` when absent."""
        return DEFAULT_MAX_SAMPLES if self.max_samples is None else self.max_samples


@dataclass(frozen=True)
class GridConfig:
    """One ``[[grid]]`` rectangle and the cells it was expanded into.

    Cell ``(i, j)`` has its centre at
    ``centre + ((i + 0.5) / nx - 0.5) * width * right
    + ((j + 0.5) / ny - 0.5) * height * up``
    and is the irradiance sensor named ``f"{name}[{i},{j}]"``.

    Attributes
    ----------
    name : str
    source : str
        Config key, e.g. ``"grid[1]"``.
    nx, ny : int
        Cell counts along the width (``right``) and height (``up``) axes.
    centre : ndarray, shape (3,)
        Centre of the rectangle, metres.
    normal : ndarray, shape (3,)
        Unit normal the cells' sensors face.
    right : ndarray, shape (3,)
        Unit width axis, ``normalize(cross(up, normal))``.
    up : ndarray, shape (3,)
        Unit height axis, orthogonal to ``normal``.
    size : tuple of float
        ``(width, height)`` of the rectangle, metres.
    spacing : tuple of float
        The requested ``(sx, sy)`` spacing (cells are ``size / (nx, ny)``).
    sensor_names : tuple of str
        Cell sensor names in the order they appear in ``RunConfig.sensors``:
        ``j`` outer, ``i`` inner (index ``j * nx + i``).
    """

    name: str
    source: str
    nx: int
    ny: int
    centre: np.ndarray
    normal: np.ndarray
    right: np.ndarray
    up: np.ndarray
    size: tuple[float, float]
    spacing: tuple[float, float]
    sensor_names: tuple[str, ...] = ()

    @property
    def cell_size(self) -> tuple[float, float]:
        """Actual cell ``(width, height)``: the rectangle tiled exactly."""
        return self.size[0] / self.nx, self.size[1] / self.ny

    def cell_name(self, i: int, j: int) -> str:
        """Sensor name of cell ``(i, j)``."""
        return f"{self.name}[{i},{j}]"

    def cell_centre(self, i: int, j: int) -> np.ndarray:
        """World position of the centre of cell ``(i, j)``, metres."""
        u = ((i + 0.5) / self.nx - 0.5) * self.size[0]
        v = ((j + 0.5) / self.ny - 0.5) * self.size[1]
        return self.centre + u * self.right + v * self.up


@dataclass(frozen=True)
class OutputConfig:
    """The ``[output]`` table.

    Attributes
    ----------
    csv : Path
        Absolute path of the results CSV.
    """

    csv: Path


@dataclass(frozen=True)
class RunConfig:
    """A validated run config.

    Attributes
    ----------
    path : Path
        Absolute path of the config file.
    stage : Path
        Absolute path of the USD stage (it existed when the config was read).
    light_units : str
        ``"photometric"`` or ``"radiometric"``.
    radiometric_spectrum : str
        Spectrum of lights in radiometric mode, one of
        :data:`simulator.units.SPECTRA`.
    simulation : SimulationConfig
    sensors : list of Sensor
        ``[[sensor]]`` entries, then grid cells, in file order.
    grids : list of GridConfig
    output : OutputConfig
    raw : dict
        The parsed TOML, for the run record.
    overrides : dict
        Command-line values applied by :func:`apply_overrides` (name to the
        value given), for the run record; empty for a plain config.
    variants : dict of str to str
        Variant selections, variant-set name to variant name, applied to the
        stage before it is read (whether the stage offers them is checked
        when it is read); empty: the stage's own selections.
    """

    path: Path
    stage: Path
    light_units: str
    radiometric_spectrum: str
    simulation: SimulationConfig
    sensors: list[Sensor]
    grids: list[GridConfig]
    output: OutputConfig
    raw: dict = field(default_factory=dict)
    overrides: dict = field(default_factory=dict)
    variants: dict[str, str] = field(default_factory=dict)


# --------------------------------------------------------------------------- checking helpers


def _toml_type(value: Any) -> str:
    """TOML's name for the type of a parsed value."""
    if isinstance(value, bool):
        return "boolean"
    if isinstance(value, int):
        return "integer"
    if isinstance(value, float):
        return "float"
    if isinstance(value, str):
        return "string"
    if isinstance(value, list):
        return "array"
    if isinstance(value, dict):
        return "table"
    return "date/time" if value is not None else "nothing"


class _Checker:
    """Builds :class:`UserError` as ``"<file>: <key>: <message>"`` (one line).

    With ``file_label=None`` (command-line flags) the file part is left out.
    """

    def __init__(self, file_label: str | None):
        self.file = file_label

    def fail(self, key: str, message: str) -> UserError:
        parts = [p for p in (self.file, key) if p] + [" ".join(str(message).split())]
        return UserError(": ".join(parts))

    # -- structure

    def table(self, value: Any, key: str) -> dict:
        if not isinstance(value, dict):
            raise self.fail(key, f"expected a table, got {_toml_type(value)}")
        return value

    def keys(self, table: dict, allowed: tuple[str, ...], key: str) -> None:
        for k in table:
            if k not in allowed:
                path = f"{key}.{k}" if key else k
                hint = difflib.get_close_matches(k, allowed, n=1)
                did = f"did you mean {hint[0]!r}? " if hint else ""
                raise self.fail(path, f"unknown key ({did}expected one of: {', '.join(allowed)})")

    # -- scalars

    def string(self, value: Any, key: str) -> str:
        if not isinstance(value, str):
            raise self.fail(key, f"expected a string, got {_toml_type(value)}")
        return value

    def choice(self, value: Any, key: str, choices: tuple[str, ...], what: str = "value") -> str:
        value = self.string(value, key)
        if value not in choices:
            raise self.fail(key, f"unknown {what} {value!r} (expected one of: {', '.join(choices)})")
        return value

    def integer(self, value: Any, key: str, *, lo: int | None = None, hi: int | None = None) -> int:
        if isinstance(value, bool) or not isinstance(value, int):
            raise self.fail(key, f"expected an integer, got {_toml_type(value)}")
        if lo is not None and value < lo:
            raise self.fail(key, f"must be >= {lo}, got {value}")
        if hi is not None and value >= hi:
            raise self.fail(key, f"must be < {hi}, got {value}")
        return int(value)

    def number(self, value: Any, key: str) -> float:
        if isinstance(value, bool) or not isinstance(value, (int, float)):
            raise self.fail(key, f"expected a number, got {_toml_type(value)}")
        value = float(value)
        if not math.isfinite(value):
            raise self.fail(key, f"must be a finite number, got {value}")
        return value

    def positive(self, value: Any, key: str) -> float:
        value = self.number(value, key)
        if value <= 0.0:
            raise self.fail(key, f"must be > 0, got {value:g}")
        return value

    # -- arrays

    def numbers(self, value: Any, key: str, n: int) -> list[float]:
        if not isinstance(value, list):
            raise self.fail(key, f"expected an array of {n} numbers, got {_toml_type(value)}")
        if len(value) != n:
            raise self.fail(key, f"expected an array of {n} numbers, got {len(value)} element(s)")
        return [self.number(v, f"{key}[{k}]") for k, v in enumerate(value)]

    def point(self, value: Any, key: str) -> np.ndarray:
        return np.array(self.numbers(value, key, 3), dtype=np.float64)

    def direction(self, value: Any, key: str) -> np.ndarray:
        v = self.point(value, key)
        length = float(np.linalg.norm(v))
        if not length > 0.0 or not math.isfinite(length):
            raise self.fail(key, "zero-length vector" if length == 0.0 else "vector length is not finite")
        return v / length

    def size(self, value: Any, key: str) -> tuple[float, float]:
        w, h = self.numbers(value, key, 2)
        for k, x in enumerate((w, h)):
            if x <= 0.0:
                raise self.fail(f"{key}[{k}]", f"must be > 0, got {x:g}")
        return w, h

    def up_axis(self, value: Any, key: str, normal: np.ndarray, normal_key: str) -> np.ndarray:
        """Unit ``up`` made orthogonal to ``normal`` (Gram–Schmidt)."""
        up = self.direction(value, key)
        ortho = up - float(np.dot(up, normal)) * normal
        length = float(np.linalg.norm(ortho))
        if length < _PARALLEL_SIN:
            raise self.fail(key, f"parallel to {normal_key}; up must point along the height side")
        return ortho / length


def _require(ck: _Checker, table: dict, name: str, key: str) -> Any:
    """``table[name]``, or an error naming ``key.name`` (``name`` at top level)."""
    if name not in table:
        raise ck.fail(f"{key}.{name}" if key else name, "required key is missing")
    return table[name]


def _array_of_tables(ck: _Checker, value: Any, key: str) -> list[dict]:
    if not isinstance(value, list):
        raise ck.fail(key, f"expected an array of tables ([[{key}]]), got {_toml_type(value)}")
    for k, item in enumerate(value):
        if not isinstance(item, dict):
            raise ck.fail(f"{key}[{k}]", f"expected a table ([[{key}]]), got {_toml_type(item)}")
    return value


# --------------------------------------------------------------------------- sections


def _simulation(ck: _Checker, value: Any) -> SimulationConfig:
    key = "simulation"
    table = ck.table(value, key)
    ck.keys(table, _SIM_KEYS, key)
    out: dict[str, Any] = {}
    k = f"{key}."
    if "samples" in table:
        out["samples"] = ck.integer(table["samples"], k + "samples", lo=1)
    if "seed" in table:
        out["seed"] = ck.integer(table["seed"], k + "seed", lo=0, hi=_SEED_LIMIT)
    if "method" in table:
        out["method"] = ck.choice(table["method"], k + "method", METHODS, "method")
    if "device" in table:
        out["device"] = ck.choice(table["device"], k + "device", DEVICES, "device")
    if "rel_error" in table:
        r = ck.number(table["rel_error"], k + "rel_error")
        if not 0.0 < r < 1.0:
            raise ck.fail(k + "rel_error", f"must be between 0 and 1 (exclusive), got {r:g}")
        out["rel_error"] = r
    if "abs_error" in table:
        a = ck.number(table["abs_error"], k + "abs_error")
        if a < 0.0:
            raise ck.fail(k + "abs_error", f"must be >= 0, got {a:g}")
        out["abs_error"] = a
    if "max_samples" in table:
        out["max_samples"] = ck.integer(table["max_samples"], k + "max_samples", lo=1)
    if "time_limit_s" in table:
        out["time_limit_s"] = ck.positive(table["time_limit_s"], k + "time_limit_s")
    if "max_depth" in table:
        out["max_depth"] = ck.integer(table["max_depth"], k + "max_depth", lo=-1)
    if "threads" in table:
        out["threads"] = ck.integer(table["threads"], k + "threads", lo=0)
    if "component" in table:
        out["component"] = ck.choice(table["component"], k + "component", COMPONENTS, "component")
    if "confidence" in table:
        c = ck.number(table["confidence"], k + "confidence")
        if not 0.5 < c < 1.0:
            raise ck.fail(k + "confidence", f"must be between 0.5 and 1 (exclusive), got {c:g}")
        out["confidence"] = c
    return SimulationConfig(**out)


def _variants(ck: _Checker, value: Any) -> dict[str, str]:
    """``variants``: a table of variant-set name -> variant name, all strings."""
    table = ck.table(value, "variants")
    out: dict[str, str] = {}
    for name, choice in table.items():
        key = f"variants.{name}"
        if not name.strip():
            raise ck.fail(key, "empty variant set name")
        choice = ck.string(choice, key)
        if not choice.strip():
            raise ck.fail(key, "empty variant name")
        out[name] = choice
    return out


def _sensor(ck: _Checker, table: dict, index: int) -> Sensor:
    key = f"sensor[{index}]"
    ck.keys(table, _SENSOR_ALL_KEYS, key)
    kind_name = ck.choice(_require(ck, table, "kind", key), f"{key}.kind", tuple(SENSOR_KINDS), "sensor kind")
    allowed = _SENSOR_COMMON_KEYS + _SENSOR_KIND_KEYS[kind_name]
    for k in table:
        if k not in allowed:
            raise ck.fail(
                f"{key}.{k}",
                f"not valid for kind {kind_name!r} (keys for {kind_name}: {', '.join(allowed)})",
            )
    name = f"sensor[{index}]"
    if "name" in table:
        name = ck.string(table["name"], f"{key}.name")
        if not name.strip():
            raise ck.fail(f"{key}.name", "empty name")
    position = ck.point(_require(ck, table, "position", key), f"{key}.position")
    kind = SENSOR_KINDS[kind_name]
    if kind == SensorKind.IRRADIANCE:
        normal = ck.direction(_require(ck, table, "normal", key), f"{key}.normal")
        return Sensor(name=name, kind=kind, position=position, normal=normal, source=key)
    if kind == SensorKind.RADIANCE:
        look = ck.direction(_require(ck, table, "direction", key), f"{key}.direction")
        half = 0.0
        if "half_angle_deg" in table:
            half = ck.number(table["half_angle_deg"], f"{key}.half_angle_deg")
            if not 0.0 <= half < 90.0:
                raise ck.fail(f"{key}.half_angle_deg", f"must be >= 0 and < 90 degrees, got {half:g}")
        return Sensor(
            name=name, kind=kind, position=position, normal=look, half_angle=math.radians(half), source=key
        )
    if kind == SensorKind.PROBE:
        res = DEFAULT_PROBE_RESOLUTION
        if "resolution" in table:
            value = table["resolution"]
            rkey = f"{key}.resolution"
            if not isinstance(value, list) or len(value) != 2:
                got = f"{len(value)} element(s)" if isinstance(value, list) else _toml_type(value)
                raise ck.fail(rkey, f"expected an array of 2 integers (width, height), got {got}")
            res = tuple(ck.integer(v, f"{rkey}[{k}]", lo=1) for k, v in enumerate(value))
            if res[0] * res[1] > MAX_PROBE_PIXELS:
                raise ck.fail(rkey, f"{res[0]} x {res[1]} pixels is more than the {MAX_PROBE_PIXELS} a probe map may hold")
        # a probe has no facing; normal and up are placeholders (the map's
        # frame is the world's, see simulator.engine.probes)
        return Sensor(
            name=name, kind=kind, position=position, normal=np.array([0.0, 0.0, 1.0]),
            up=np.array([0.0, 1.0, 0.0]), resolution=(int(res[0]), int(res[1])), source=key,
        )  # fmt: skip
    # patch
    normal = ck.direction(_require(ck, table, "normal", key), f"{key}.normal")
    size = ck.size(_require(ck, table, "size", key), f"{key}.size")
    up = ck.up_axis(_require(ck, table, "up", key), f"{key}.up", normal, f"{key}.normal")
    return Sensor(name=name, kind=kind, position=position, normal=normal, up=up, size=size, source=key)


def _grid(ck: _Checker, table: dict, index: int) -> tuple[GridConfig, list[Sensor]]:
    key = f"grid[{index}]"
    ck.keys(table, _GRID_KEYS, key)
    name = ck.string(_require(ck, table, "name", key), f"{key}.name")
    if not name.strip():
        raise ck.fail(f"{key}.name", "empty name")
    centre = ck.point(_require(ck, table, "position", key), f"{key}.position")
    normal = ck.direction(_require(ck, table, "normal", key), f"{key}.normal")
    w, h = ck.size(_require(ck, table, "size", key), f"{key}.size")
    up = ck.up_axis(_require(ck, table, "up", key), f"{key}.up", normal, f"{key}.normal")
    spacing_value = _require(ck, table, "spacing", key)
    if isinstance(spacing_value, list):
        sx, sy = ck.size(spacing_value, f"{key}.spacing")
    else:
        if isinstance(spacing_value, bool) or not isinstance(spacing_value, (int, float)):
            raise ck.fail(
                f"{key}.spacing",
                f"expected a number or an array of 2 numbers, got {_toml_type(spacing_value)}",
            )
        sx = sy = ck.positive(spacing_value, f"{key}.spacing")
    right = patch_width_axis(up, normal)
    nx = max(1, round(w / sx))
    ny = max(1, round(h / sy))
    grid = GridConfig(
        name=name,
        source=key,
        nx=nx,
        ny=ny,
        centre=centre,
        normal=normal,
        right=right,
        up=up,
        size=(w, h),
        spacing=(sx, sy),
        sensor_names=tuple(f"{name}[{i},{j}]" for j in range(ny) for i in range(nx)),
    )
    sensors = [
        Sensor(
            name=grid.cell_name(i, j),
            kind=SensorKind.IRRADIANCE,
            position=grid.cell_centre(i, j),
            normal=normal.copy(),
            grid=name,
            source=key,
        )
        for j in range(ny)
        for i in range(nx)
    ]
    return grid, sensors


def _output(ck: _Checker, value: Any, base: Path, default: Path) -> OutputConfig:
    table = ck.table(value, "output")
    ck.keys(table, _OUTPUT_KEYS, "output")
    if "csv" not in table:
        return OutputConfig(csv=default)
    text = ck.string(table["csv"], "output.csv")
    if not text.strip():
        raise ck.fail("output.csv", "empty path")
    return OutputConfig(csv=_resolve(base, text))


def _resolve(base: Path, text: str | os.PathLike) -> Path:
    p = Path(text).expanduser()
    if not p.is_absolute():
        p = base / p
    return p.resolve()


# --------------------------------------------------------------------------- public API


def load_config(path: str | os.PathLike) -> RunConfig:
    """Read and fully validate a run config.

    Parameters
    ----------
    path : str or path-like
        The TOML config file. Messages name it as given.

    Returns
    -------
    RunConfig
        Paths absolute; sensors built (grid cells expanded), directions
        normalised, ``raw`` holding the parsed TOML.

    Raises
    ------
    UserError
        The first problem found, as one line
        ``"<path>: <key path>: <what is wrong>"``: an unreadable file, invalid
        TOML, an unknown key, a wrong type, a value out of range, a missing
        stage file, or a duplicate sensor name.
    """
    label = os.fspath(path)
    ck = _Checker(label)
    cfg_path = Path(label).expanduser().resolve()
    try:
        with open(cfg_path, "rb") as fh:
            raw = tomllib.load(fh)
    except FileNotFoundError:
        raise ck.fail("", "config file not found") from None
    except IsADirectoryError:
        raise ck.fail("", "is a directory, not a config file") from None
    except OSError as exc:
        raise ck.fail("", f"cannot read config: {exc.strerror or exc}") from None
    except UnicodeDecodeError as exc:
        raise ck.fail("", f"invalid TOML: not UTF-8 text ({exc.reason} at byte {exc.start})") from None
    except tomllib.TOMLDecodeError as exc:
        raise ck.fail("", f"invalid TOML: {exc}") from None

    base = cfg_path.parent
    ck.keys(raw, _TOP_KEYS, "")

    stage_text = ck.string(_require(ck, raw, "stage", ""), "stage")
    if not stage_text.strip():
        raise ck.fail("stage", "empty path")
    stage = _resolve(base, stage_text)
    if not stage.exists():
        raise ck.fail("stage", f"stage file not found: {stage}")
    if not stage.is_file():
        raise ck.fail("stage", f"not a file: {stage}")

    light_units = "photometric"
    if "light_units" in raw:
        light_units = ck.choice(raw["light_units"], "light_units", LIGHT_UNITS, "light units")
    spectrum = "E"
    if "radiometric_spectrum" in raw:
        spectrum = ck.choice(raw["radiometric_spectrum"], "radiometric_spectrum", tuple(SPECTRA), "spectrum")

    variants = _variants(ck, raw["variants"]) if "variants" in raw else {}
    simulation = _simulation(ck, raw["simulation"]) if "simulation" in raw else SimulationConfig()

    sensors: list[Sensor] = []
    owner: dict[str, str] = {}  # sensor name -> config key that defined it
    for k, table in enumerate(_array_of_tables(ck, raw.get("sensor", []), "sensor")):
        s = _sensor(ck, table, k)
        if s.name in owner:
            raise ck.fail(f"sensor[{k}].name", f"duplicate sensor name {s.name!r} (also {owner[s.name]})")
        owner[s.name] = s.source
        sensors.append(s)

    grids: list[GridConfig] = []
    grid_owner: dict[str, str] = {}
    for k, table in enumerate(_array_of_tables(ck, raw.get("grid", []), "grid")):
        g, cells = _grid(ck, table, k)
        if g.name in grid_owner:
            raise ck.fail(f"grid[{k}].name", f"duplicate grid name {g.name!r} (also {grid_owner[g.name]})")
        grid_owner[g.name] = g.source
        for s in cells:
            if s.name in owner:
                raise ck.fail(
                    f"grid[{k}].name",
                    f"cell sensor name {s.name!r} is already used by {owner[s.name]}",
                )
            owner[s.name] = s.source
        grids.append(g)
        sensors.extend(cells)

    default_csv = base / f"{cfg_path.stem}.csv"
    output = _output(ck, raw["output"], base, default_csv) if "output" in raw else OutputConfig(csv=default_csv)

    return RunConfig(
        path=cfg_path,
        stage=stage,
        light_units=light_units,
        radiometric_spectrum=spectrum,
        simulation=simulation,
        sensors=sensors,
        grids=grids,
        output=output,
        raw=raw,
        variants=variants,
    )


def apply_overrides(
    cfg: RunConfig,
    *,
    seed: int | None = None,
    samples: int | None = None,
    device: str | None = None,
    csv: str | os.PathLike | None = None,
    method: str | None = None,
    rel_error: float | None = None,
    confidence: float | None = None,
    variants: list[str] | None = None,
) -> RunConfig:
    """Apply command-line flags to a config.

    Parameters
    ----------
    cfg : RunConfig
        A config from :func:`load_config`; left unchanged.
    seed : int, optional
        Replaces ``simulation.seed``; ``0 <= seed < 2**31``.
    samples : int, optional
        Replaces ``simulation.samples``; > 0.
    device : str, optional
        Replaces ``simulation.device``; one of :data:`DEVICES`.
    csv : str or path-like, optional
        Replaces ``output.csv``; resolved against the current directory.
    method : str, optional
        Replaces ``simulation.method``; one of :data:`METHODS`.
    rel_error : float, optional
        Replaces ``simulation.rel_error`` (makes the run adaptive); in (0, 1).
    confidence : float, optional
        Replaces ``simulation.confidence``; in (0.5, 1).
    variants : list of str, optional
        ``"set=variant"`` selections (``--variant``), added to the config's
        ``variants`` table and overriding the same set there.

    Returns
    -------
    RunConfig
        A new config; ``overrides`` records the flags given.

    Raises
    ------
    UserError
        A flag value is invalid; the one-line message names the flag
        (``--samples: must be >= 1, got 0``).
    """
    ck = _Checker(None)
    sim: dict[str, Any] = {}
    given: dict[str, Any] = {}
    if seed is not None:
        sim["seed"] = ck.integer(seed, "--seed", lo=0, hi=_SEED_LIMIT)
        given["seed"] = sim["seed"]
    if samples is not None:
        sim["samples"] = ck.integer(samples, "--samples", lo=1)
        given["samples"] = sim["samples"]
    if device is not None:
        sim["device"] = ck.choice(device, "--device", DEVICES, "device")
        given["device"] = device
    if method is not None:
        sim["method"] = ck.choice(method, "--method", METHODS, "method")
        given["method"] = method
    if rel_error is not None:
        r = ck.number(rel_error, "--rel-error")
        if not 0.0 < r < 1.0:
            raise ck.fail("--rel-error", f"must be between 0 and 1 (exclusive), got {r:g}")
        sim["rel_error"] = r
        given["rel_error"] = r
    if confidence is not None:
        c = ck.number(confidence, "--confidence")
        if not 0.5 < c < 1.0:
            raise ck.fail("--confidence", f"must be between 0.5 and 1 (exclusive), got {c:g}")
        sim["confidence"] = c
        given["confidence"] = c
    chosen = dict(cfg.variants)
    for item in variants or ():
        name, sep, choice = str(item).partition("=")
        if not sep or not name.strip() or not choice.strip():
            raise ck.fail("--variant", f"expected SET=VARIANT, got {item!r}")
        chosen[name.strip()] = choice.strip()
    if variants:
        given["variants"] = list(variants)
    output = cfg.output
    if csv is not None:
        text = os.fspath(csv)
        if not str(text).strip():
            raise ck.fail("--csv", "empty path")
        output = replace(output, csv=_resolve(Path.cwd(), text))
        given["csv"] = str(output.csv)
    return replace(
        cfg,
        simulation=replace(cfg.simulation, **sim),
        output=output,
        variants=chosen,
        overrides={**cfg.overrides, **given},
    )

