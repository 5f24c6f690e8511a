"""The run config file as pydantic models: what each table may say.

One model per TOML table, its fields in the order messages list them; the
rules of each value are in its type (:mod:`simulator.config.fields`). The
sensor kinds are in :mod:`simulator.config.sensors`. Paths are checked as
text here and resolved by :mod:`simulator.config.loader`; command-line
flags are checked by these same models (:mod:`simulator.config.overrides`).

::

    stage = "../stages/quickstart.usda"   # required, must exist
    light_units = "photometric"           # or "radiometric"
    radiometric_spectrum = "E"            # or "D65"
    variants = { reflectance = "rho_0_9" } # optional: variant set -> variant,
                                          # selected on every prim with that set, or
                                          # "/Prim/Path" = { set = "variant" } on one prim
                                          # (simulator.config.variants)
    time = 24.0                           # optional: the USD time code the stage is read at
                                          # (default: its earliest time sample)

    [simulation]
    samples = 1024        # int > 0; adaptive: the first batch (a floor), or left
                          # out: the engine sizes it from a pilot, at most 1024
    seed = 1              # 0 <= int < 2**31
    method = "auto"       # auto | analytic | light | bsdf | mis | path
    device = "cpu"        # cpu | cuda | auto
    rel_error = 0.01      # optional, 0 < x < 1: adaptive stopping target
    abs_error = 0.0       # >= 0, absolute floor near zero
    max_samples = 1048576 # optional int > 0, per-sensor cap when adaptive
    time_limit_s = 60.0   # optional float > 0, seconds
    max_depth = -1        # int >= -1; -1 = unlimited (Russian roulette)
    threads = 0           # int >= 0; 0 = all cores
    component = "total"   # total | direct | indirect
    confidence = 0.95     # 0.5 < x < 1: confidence of the adaptive stop

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
    size = [4, 3]         # metres
    up = [0, 1, 0]
    spacing = 0.5         # or [sx, sy], metres

    [output]
    csv = "out.csv"       # default: "<config stem>.csv" beside the config
    csv_columns = "kinds" # the columns of the run's sensor kinds; "full": all 32
    responses = ["par", "melanopic_edi"]  # optional: extra response columns

    [spectra]             # optional: the lights' spectral shape
    lights = "D65"        # illuminant, temperature (K) or SPD .csv

``output.responses`` and ``[spectra]`` are checked by
:func:`simulator.spectra.config.load_spectra_settings` (they are opaque
here so that its one-line messages name the entry at fault).

Vectors are in the probesim world frame (metres, right-handed, Z up).
"""

from __future__ import annotations

from typing import Annotated, Any

from pydantic import Field

from simulator.config.fields import (
    Count, Direction, Integer, Number, Point, Positive, Size, Spacing, Text, UpDirection, choice, interval,
    nonblank, tables,
)  # fmt: skip
from simulator.config.records import (
    COMPONENTS, CSV_COLUMN_SETS, DEVICES, LIGHT_UNITS, METHODS, SEED_LIMIT, GridConfig, SimulationConfig,
)  # fmt: skip
from simulator.config.sensors import MODEL_NAME, ModelName, SensorEntry
from simulator.config.table import Table
from simulator.config.variants import Variants
from simulator.scene.model import Sensor, SensorKind, patch_width_axis
from simulator.units import SPECTRA

__all__ = ["Simulation", "Grid", "Output", "RunFile", "Variants"]

_D = SimulationConfig()  # the defaults


class Simulation(Table):
    """``[simulation]``; see :class:`~simulator.config.records.SimulationConfig` for the meaning of each key."""

    samples: Count = Field(
        _D.samples,
        description="samples per sensor (fixed budget); adaptive: the first batch, a floor (left out: the engine "
        "sizes it from a pilot, at most 1024)",
    )
    seed: Annotated[
        Integer,
        Field(ge=0, lt=SEED_LIMIT, description="random seed, 0 ≤ seed < 2³¹: the same seed, config and device give the "
              "same CSV"),
    ] = _D.seed
    method: Annotated[
        Text, choice(METHODS, "method"),
        Field(description="estimator: auto | analytic | exact | light | bsdf | mis | path | guided (auto plans each "
              "sensor)"),
    ] = _D.method
    device: Annotated[Text, choice(DEVICES, "device"), Field(description="cpu | cuda | auto")] = _D.device
    rel_error: Annotated[Number, interval(0.0, 1.0)] | None = Field(
        _D.rel_error,
        description="adaptive: stop each sensor when its confidence half-width is under this share of its reading, "
        "0 < x < 1 (unset: fixed budget)",
    )
    abs_error: Annotated[
        Number,
        Field(ge=0.0, description="adaptive: or when the half-width is under this absolute floor, in the reading's "
              "unit (readings near 0)"),
    ] = _D.abs_error
    max_samples: Count | None = Field(_D.max_samples, description="adaptive: per-sensor sample cap")
    time_limit_s: Positive | None = Field(_D.time_limit_s, description="adaptive: wall-clock limit of the run")
    max_depth: Annotated[
        Integer, Field(ge=-1, description="path bounce cap; -1: none (unbiased Russian roulette ends paths)")
    ] = _D.max_depth
    threads: Annotated[Integer, Field(ge=0, description="CPU worker threads; 0: all cores")] = _D.threads
    component: Annotated[
        Text, choice(COMPONENTS, "component"),
        Field(description="total | direct (straight from emitters) | indirect (reflected at least once)"),
    ] = _D.component
    confidence: Annotated[
        Number, interval(0.5, 1.0),
        Field(description="adaptive: confidence of the stopping interval, 0.5 < x < 1 (0.999: the target for nearly "
              "every sensor of many)"),
    ] = _D.confidence

    def to_record(self) -> SimulationConfig:
        return SimulationConfig(**dict(self), samples_set="samples" in self.model_fields_set)


class Grid(Table):
    """``[[grid]]``: a rectangle of irradiance sensors at the centres of its cells.

    ``size`` (metres) is split into ``max(1, round(width / sx))`` ×
    ``max(1, round(height / sy))`` cells for ``spacing`` ``(sx, sy)``.
    """

    name: Annotated[Text, nonblank("empty name"), Field(description="the cells are named name[i,j]")]
    position: Annotated[Point, Field(description="centre of the rectangle", json_schema_extra={"unit": "m"})]
    normal: Annotated[Direction, Field(description="the side the cells face (toward the light they measure)")]
    size: Annotated[Size, Field(description="width, height of the rectangle", json_schema_extra={"unit": "m"})]
    up: Annotated[UpDirection, Field(description="direction of the height side (not parallel to normal)")]
    spacing: Annotated[
        Spacing,
        Field(description="cell size: one number or [sx, sy]; cells = round(size / spacing)",
              json_schema_extra={"unit": "m"}),
    ]
    model: ModelName | None = MODEL_NAME

    def cells(self) -> tuple[int, int]:
        """``(nx, ny)``: the cell counts along the width and height, from size and spacing alone."""
        (w, h), (sx, sy) = self.size, self.spacing
        return max(1, round(w / sx)), max(1, round(h / sy))

    def to_grid(self, source: str) -> tuple[GridConfig, list[Sensor]]:
        """The grid record and its cell sensors (``j`` outer, ``i`` inner), defined at config key ``source``."""
        (w, h), (sx, sy) = self.size, self.spacing
        right = patch_width_axis(self.up, self.normal)
        nx, ny = self.cells()
        grid = GridConfig(
            name=self.name, source=source, nx=nx, ny=ny, centre=self.position, normal=self.normal, right=right,
            up=self.up, size=(w, h), spacing=(sx, sy),
            sensor_names=tuple(f"{self.name}[{i},{j}]" for j in range(ny) for i in range(nx)),
        )  # fmt: skip
        cells = [
            Sensor(
                name=grid.cell_name(i, j), kind=SensorKind.IRRADIANCE, position=grid.cell_centre(i, j),
                normal=self.normal.copy(), grid=self.name, source=source, azimuth_ref=self.up.copy(),
            )  # fmt: skip
            for j in range(ny)
            for i in range(nx)
        ]
        return grid, cells


class Output(Table):
    """``[output]``: ``csv`` is resolved against the config's folder (default ``<config stem>.csv`` there)."""

    csv: Annotated[Text, nonblank("empty path")] | None = Field(
        None,
        description="the CSV written, relative to the config (default: <config stem>.csv beside it); the run "
        "record, maps and probes go beside it",
    )
    csv_columns: Annotated[Text, choice(CSV_COLUMN_SETS, "CSV column set")] = Field(
        "kinds",
        description='the CSV\'s columns: "kinds", those of the run\'s sensor kinds (no cell empty in a run of one '
        'kind), or "full", all 32 whatever the kinds (--csv-columns)',
    )
    #: response names / custom tables, checked by :mod:`simulator.spectra.config`
    responses: Any = Field(
        None, json_schema_extra={"type": "list"},
        description='extra spectral response columns: "par", "epar", "scotopic", "melanopic", "melanopic_edi", ... '
        'or { custom = "diode.csv", name = "diode" }',
    )




class RunFile(Table):
    """A whole run config file."""

    stage: Annotated[
        Text, nonblank("empty path"), Field(description="the USD stage (.usda/.usdc/.usdz), relative to the config")
    ]
    light_units: Annotated[
        Text, choice(LIGHT_UNITS, "light units"),
        Field(description="photometric: a light's intensity is cd/m² (lx for a normalized DistantLight); "
              "radiometric: W/m²/sr (W/m²)"),
    ] = "photometric"
    radiometric_spectrum: Annotated[
        Text, choice(tuple(SPECTRA), "spectrum"),
        Field(description="spectrum of radiometric lights: E (equal energy) or D65"),
    ] = "E"
    variants: Variants = Field(
        {},
        description='USD variant selections applied before reading: { set = "variant" } on every prim with that '
        'set, or "/Prim/Path" = { set = "variant" } on one prim',
    )
    time: Number | None = Field(
        None, description="USD time code the stage is read at (default: each attribute's earliest sample)"
    )
    times: Annotated[list[Number], Field(min_length=1, max_length=100_000)] | None = Field(
        None, description="or several: one CSV row per sensor and time code (a sensor prim with time samples moves "
        "along its path), one trace for the times the rest of the stage is the same at")
    simulation: Simulation = Simulation()
    sensor: Annotated[list[SensorEntry], tables("sensor")] = []
    grid: Annotated[list[Grid], tables("grid")] = []
    output: Output = Output()
    #: ``[spectra]``, checked by :mod:`simulator.spectra.config`
    spectra: Any = Field(
        None, json_schema_extra={"type": "table"},
        description='one key, lights: the lights\' spectral shape, an illuminant ("D65", "A"), a temperature (3000) '
        'or an SPD .csv (default: D65, or radiometric_spectrum)',
    )
