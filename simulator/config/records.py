"""What a validated config hands on: frozen records and the accepted names.

These are the types the rest of probesim reads (:class:`RunConfig` and its
parts). They hold checked values only; the rules that check a file live in
:mod:`simulator.config.schema` and :mod:`simulator.config.sensors`, which
build these records.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from simulator.engine.methods import COMPONENTS, METHODS  # estimator and component names, defined once
from simulator.scene.model import MAX_PROBE_PIXELS, Sensor  # noqa: F401  (MAX_PROBE_PIXELS re-exported)

__all__ = [
    "METHODS",
    "COMPONENTS",
    "DEVICES",
    "LIGHT_UNITS",
    "MAX_PROBE_PIXELS",
    "DEFAULT_MAX_SAMPLES",
    "SEED_LIMIT",
    "SimulationConfig",
    "GridConfig",
    "OutputConfig",
    "RunConfig",
]

#: device names accepted by ``simulation.device`` and ``--device``
DEVICES = ("cpu", "cuda", "auto")
#: accepted values of ``[output] csv_columns``: the columns of the run's sensor kinds, or all of them
CSV_COLUMN_SETS = ("kinds", "full")
#: accepted values of ``light_units``
LIGHT_UNITS = ("photometric", "radiometric")
#: per-sensor sample cap of an adaptive run when ``max_samples`` is absent
DEFAULT_MAX_SAMPLES = 2**20
#: seeds are ``0 <= seed < SEED_LIMIT`` (they seed 32-bit signed counters)
SEED_LIMIT = 2**31


@dataclass(frozen=True)
class SimulationConfig:
    """The ``[simulation]`` table.

    The defaults here are the defaults of a config that leaves a key out.

    Attributes
    ----------
    samples : int
        Samples per sensor (the fixed budget). In an adaptive run: where the
        config (or ``--samples``) gives it, the first batch, a floor every
        sensor draws; where it is left out, the upper bound of a first batch
        the engine sizes from a short pilot (see :attr:`samples_set`). > 0.
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
        Absolute half-width floor for readings near zero, >= 0 (units of the
        reading).
    max_samples : int or None
        Per-sensor sample cap of an adaptive run; None when absent (see
        :attr:`sample_cap`).
    time_limit_s : float or None
        Wall-clock limit in seconds, > 0; None when absent.
    max_depth : int
        Bounce cap of the ``path`` method; -1 = unlimited.
    threads : int
        CPU worker threads; 0 = all cores.
    component : str
        Which light the readings count: ``total``, ``direct`` (straight from
        emitters) or ``indirect`` (reflected at least once; method ``path``).
    confidence : float
        Confidence of the adaptive stop's interval, in (0.5, 1): 0.95 (the
        default) stops when 1.96·stderr ≤ the target, so about 1 sensor in 20
        ends beyond it; 0.999 uses 3.29·stderr, for a guarantee across many
        sensors.
    samples_set : bool
        False only where a config file and its flags leave ``samples`` out
        (records built in code keep ``samples`` as their first batch).
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
    samples_set: bool = True

    @property
    def adaptive(self) -> bool:
        """True when sensors stop on ``rel_error`` rather than a fixed budget."""
        return self.rel_error is not None

    @property
    def sample_cap(self) -> int:
        """``max_samples``, or :data:`DEFAULT_MAX_SAMPLES` when absent."""
        return DEFAULT_MAX_SAMPLES if self.max_samples is None else self.max_samples

    @property
    def choose_first_batch(self) -> bool:
        """True when an adaptive run's first batch is the engine's to size
        (``samples`` left out: it is then the batch's upper bound)."""
        return self.adaptive and not self.samples_set


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
        The requested ``(sx, sy)`` spacing, metres (cells are
        ``size / (nx, ny)``).
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
        """Actual cell ``(width, height)`` in metres: the rectangle tiled exactly."""
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
    csv_columns : str
        Its column set, one of :data:`CSV_COLUMN_SETS` (see :func:`simulator.io.results.csv_columns`).
    """

    csv: Path
    csv_columns: str = "kinds"


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
        Command-line values applied by
        :func:`simulator.config.overrides.apply_overrides` (name to the value
        given), for the run record; empty for a plain config.
    variants : dict
        Variant selections applied to the stage before it is read (whether
        the stage offers them is checked when it is read): variant-set name
        to variant name (every prim with the set), or prim path to a dict of
        variant-set name to variant name (that prim only; see
        :mod:`simulator.config.variants`); empty: the stage's own selections.
    time : float or None
        USD time code the stage is read at; None: its earliest time sample
        (``Usd.TimeCode.EarliestTime()``).
    times : tuple of float or None
        Several time codes (``times``): the run reads every sensor at each
        (:func:`simulator.pipeline.run`); None: one reading, at ``time``.
    spectra : simulator.spectra.config.SpectraSettings or None
        ``output.responses`` and ``[spectra]``, resolved; None when the
        config has neither (the run writes only the standard columns).
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
    variants: dict = field(default_factory=dict)
    spectra: object | None = None
    time: float | None = None
    times: tuple[float, ...] | None = None
