"""The study file: a TOML placement study read into a validated :class:`Study`.

Checked here, before any stage is read: unknown keys, wrong types and values
out of range are one-line :class:`~simulator.errors.UserError` messages that
name the file and the key, in the style of ``probesim run``, e.g.
``office_study.toml: scenario[2].levels.sky: Input should be greater than or equal to 0``.
Cross-references (a zone naming a candidate set, a scenario naming a group)
are checked here too; what needs the stage (prim paths, light patterns,
variant names) is checked when the stage is read (see
:mod:`simulator.study.inputs.scenarios` and :mod:`simulator.study.inputs.candidates`).

Schema
------
::

    stage = "../stages/office.usda"    # required
    project = "Office, level 2"        # the report's title (default: the stage's file name)
    light_units = "photometric"        # or "radiometric"
    seed = 1                           # study seed: chunk seeds derive from it

    [simulation]                       # as a run config's, minus time_limit_s
    samples = 256                      # (a wall-clock stop is not reproducible)
    rel_error = 0.05
    max_samples = 8192

    [compute]
    mode = "auto"                      # auto | inprocess | local
    workers = 0                        # LocalCluster workers; 0 = one per core
    scheduler = "tcp://host:8786"      # a running dask scheduler (optional)
    retries = 2                        # re-runs of a failed chunk
    sensor_block = "auto"              # sensors per chunk, or "auto": from the study's size

    [[candidates]]                     # a grid on prims ...
    name = "workplane"
    kind = "irradiance"                # irradiance (cosine) | photosensor (cone)
    on = ["/Office/Room/Floor"]        # flat prims; the grid lies on their plane
    height_m = 0.8                     # along each prim's front normal
    spacing_m = "en12464"              # or a number, metres
    wall_band_m = 0.5                  # band along the prim's edges left out
    drop_inside = ["/Office/Furniture/*"]  # points inside these prims' boxes dropped

    [[candidates]]                     # ... or an explicit list
    name = "manual"
    kind = "photosensor"
    half_angle_deg = 30                # photosensor cone
    points = [[1.5, 2.0, 2.98]]
    normal = [0, 0, -1]
    # model = "ceiling_photosensor"    # a sensor model: its angular and spectral response (and
    # gain = 1, integration_ms = 100   # in an annual control its device, at this setting)

    [[group]]                          # a light group: paths or fnmatch patterns
    name = "window_row"
    lights = ["/Office/Lights/WindowRow/*"]
    spectrum = "LED-B2"                # what sensor models read it at (default: its lights' own)

    [[group]]                          # ... or a USD collection (UsdCollectionAPI)
    name = "window_side"
    collection = "/Office/Lights.collection:windowSide"

    [[group]]                          # ... or a sky split into Tregenza's 145 patches
    name = "sky"                       # (one DomeLight): daylight coefficients,
    lights = ["/Office/Sky"]           # any sky a recombination of them
    sky = "tregenza"

    [[scenario]]                       # levels: group -> dimming (lists: a product)
    name = "evening"
    levels = { window_row = [0.5, 1.0], corridor_row = 1.0 }
    sun = { azimuth_deg = 250, elevation_deg = 30 }   # or latitude_deg,
                                       # longitude_deg, time (ISO 8601 with offset)
    variants = { reflectance = "light" }
    # allow_boost = true               # levels above 1 (a boost); refused without it

    [[scenario]]                       # a CIE sky on a split sky group: patch levels
    name = "clear_sky"                 # L_p / L_dome, times the group's level
    levels = { sky = 1.0 }
    sky = { group = "sky", cie = 12, horizontal_lx = 15000, ground = 0.0,
            sun = { azimuth_deg = 200, elevation_deg = 40 } }
                                       # cie: 1..15 (ISO 15469 general sky),
                                       # "overcast" (the traditional CIE sky) or
                                       # "uniform"; horizontal_lx: the sky's
                                       # unobstructed horizontal illuminance
                                       # (default: the dome's authored π·L); sun:
                                       # for the sky's formula only (default: the
                                       # scenario's sun, else the stage's); ground:
                                       # the dome below the horizon, relative to
                                       # its authored radiance (default 0)

    [[zone]]
    name = "window_zone"
    candidates = "workplane"
    region = [0, 0, 3, 4]              # x0, y0, x1, y1 in metres (optional)
    targets = { mean = 500, u0 = 0.6 } # mean, min, max (reading units), u0, min_max

    [placement]
    k = 2
    candidates = ["ceiling"]           # candidate sets to choose from
    target = "each_zone"               # or one zone's name
    objective = "correlation"          # correlation | max_rel_error | p95_rel_error
    replicates = 200                   # parametric bootstrap for score errors

    [output]
    dir = "../out/office_study"        # default: "<study stem>.out/" beside the file
    heat_map_scale = "shared"          # the plans' colour scale: one per zone for all scenarios;
                                       # "per_scenario": each plan its own; "log": one logarithmic

    [annual]                           # a year of daylight (simulator.study.annual.year);
    weather = "../stages/weather/greensboro_tmy3_lux.csv"  # EPW or TMY3
    sky_group = "sky"                  # a group with sky = "tregenza"
    illuminance = "file"               # or "efficacy" (Perez 1990 on the irradiances)
    ground_reflectance = 0.2           # the dome below the horizon
    occupied_h = [8, 18]               # LM-83 hours, local standard time
    # da_lx, ase_lx, ase_hours, udi_lx, en17037_lx, step_h, replicates, sun_patches;
    # sun_indirect = "traced" with sun_group (the DistantLight's group) and sun_bin_deg;
    # glare_index = "dgp" (or "dgps") at the stage's glare views, glare_limit = 0.40

    [shading]                          # operable shading (simulator.study.annual.shading)
    variant_set = "blinds"             # the stage's variant set of the window's states
    states = ["up", "down"]            # its variants, least shaded first; each traced once
    rule = "lm83"                      # lm83 (share, zones) | glare (dgp_limit, views) | schedule
    diffusers = { "/Office/Blinds/Shade" = 0.10 }   # flat shade prims: diffuse transmittance

    [[control]]                        # photosensor control (simulator.study.annual.control)
    zone = "window_zone"
    groups = ["window_row"]            # light groups it dims
    model = "closed_loop"              # closed_loop | open_loop | switched
    photosensor = "ceiling"            # a candidate, or a set: the best annual control
    target_lx = 500                    # default: the zone's mean target
    min_level = 0.1                    # dimming floor; deadband = 0.2 (switched)

An annual study may have no ``[[scenario]]``.
"""

from __future__ import annotations

import difflib
import os
import tomllib
from pathlib import Path
from typing import Annotated, Literal, Union

from pydantic import BaseModel, ConfigDict, Field, ValidationError, field_validator, model_validator

from simulator.errors import UserError

__all__ = ["Study", "load_study", "CandidateSpec", "GroupSpec", "ScenarioSpec", "ZoneSpec", "PlacementSpec", "SunSpec", "SkySpec", "AnnualSpec", "ControlSpec",
           "ShadingSpec"]

_SEED_LIMIT = 2**31
Level = Annotated[float, Field(ge=0.0, le=1e6, allow_inf_nan=False)]
Vec3 = tuple[float, float, float]


class _Model(BaseModel):
    model_config = ConfigDict(extra="forbid", frozen=True, strict=False)


class SimulationSpec(_Model):
    """Trace settings; as a run config's ``[simulation]`` without ``seed``
    (the study's seed drives per-chunk seeds) and ``time_limit_s`` (a
    wall-clock stop would make results depend on the machine)."""

    samples: int = Field(256, ge=1, description="samples per sensor and pass (adaptive: the first batch)")
    method: Literal["auto", "light", "bsdf", "mis", "path", "guided"] = Field(
        "auto", description="estimator, as a run config's (no analytic/exact)"
    )
    device: Literal["cpu", "cuda", "auto"] = Field("cpu", description="cpu | cuda | auto")
    rel_error: float | None = Field(
        None, gt=0.0, lt=1.0,
        description=(
            "adaptive: a sensor stops when every scenario's recombined reading meets this relative half-width"
        )
    )
    abs_error: float = Field(0.0, ge=0.0, description="adaptive: or this absolute half-width, in the reading's unit")
    max_samples: int | None = Field(None, ge=1, description="adaptive: per-sensor sample cap")
    max_depth: int = Field(-1, ge=-1, description="path bounce cap; -1: none (Russian roulette)")
    threads: int = Field(0, ge=0, description="CPU worker threads; 0: all cores")
    component: Literal["total", "direct", "indirect"] = Field("total", description="total | direct | indirect")
    confidence: float = Field(0.95, gt=0.5, lt=1.0, description="adaptive: confidence of the stopping interval")


class ComputeSpec(_Model):
    mode: Literal["auto", "inprocess", "local"] = Field(
        "auto",
        description=(
            "where chunks run: auto (in this process on ≤ 2 cores, else a dask LocalCluster), inprocess, local"
        )
    )
    workers: int = Field(0, ge=0, description="LocalCluster worker processes; 0: one per core")
    scheduler: str | None = Field(None, description="a running dask scheduler, tcp://host:8786 or tls://...")
    retries: int = Field(2, ge=0, le=20, description="re-runs of a failed chunk")
    sensor_block: Union[Literal["auto"], Annotated[int, Field(ge=1)]] = Field(
        "auto", description="sensors per chunk, or \"auto\": the smallest block whose chunks cost ≤ 1.2× one run"
    )

    @field_validator("scheduler")
    @classmethod
    def _address(cls, v):
        if v is not None and "://" not in v:
            raise ValueError(f"expected an address such as tcp://host:8786, got {v!r}")
        return v


class CandidateSpec(_Model):
    name: str = Field(min_length=1, description="the set's name (zones, areas, placement and control refer to it)")
    kind: Literal["irradiance", "photosensor", "cylindrical", "semicylindrical"] = Field(
        "irradiance",
        description=(
            "irradiance (cosine) | photosensor (radiance in a cone) | cylindrical | semicylindrical"
        )
    )
    half_angle_deg: float = Field(30.0, gt=0.0, lt=90.0, description="photosensor: half angle of its cone")
    model: str | None = Field(
        None, min_length=1, description="irradiance, photosensor: a sensor model (probesim sensor --list, or a .toml "
        "beside the study): the set reads through its angular and spectral response instead of the cosine or the "
        "cone, and an annual control through its electronics")
    gain: Union[Literal["auto"], Annotated[float, Field(gt=0.0)]] | None = Field(
        None, description="with a model with electronics: the part's gain the installed device runs at (default: the "
        "part's)")
    integration_ms: float | None = Field(
        None, gt=0.0, description="with a model with electronics: its integration time (default: the part's)")
    facing: Vec3 | None = Field(None, description="semicylindrical: where the half cylinders face (across the axis)")
    on: list[str] | None = Field(None, description="flat prims (paths) to grid; the grid lies on their plane")
    height_m: float = Field(
        0.0, description="the grid's offset along each prim's front normal (0.8: a work plane over the floor)"
    )
    spacing_m: Union[float, str] = Field(
        "en12464", description="grid spacing, or \"en12464\": p = 0.2·5^log10(d), d the longer side"
    )
    wall_band_m: float = Field(0.5, ge=0.0, description="band along the prim's edges left out")
    drop_inside: list[str] = Field(
        [], description="prims (paths or patterns) whose boxes drop the points inside them (furniture)"
    )
    points: list[Vec3] | None = Field(
        None, description="an explicit list of [x, y, z] instead of on", json_schema_extra={"unit": "m"}
    )
    normal: Vec3 | None = Field(None, description="points: the direction the sensors face")

    @field_validator("spacing_m")
    @classmethod
    def _spacing(cls, v):
        if isinstance(v, str) and v != "en12464":
            raise ValueError(f"expected a spacing in metres or \"en12464\", got {v!r}")
        if not isinstance(v, str) and not v > 0.0:
            raise ValueError(f"must be > 0, got {v:g}")
        return v

    @model_validator(mode="after")
    def _one_source(self):
        if self.kind == "semicylindrical" and self.facing is None:
            raise ValueError("a semicylindrical set needs 'facing' (the direction the half cylinders face)")
        if self.kind != "semicylindrical" and self.facing is not None:
            raise ValueError("facing is for kind = \"semicylindrical\"")
        if self.model is not None and self.kind not in ("irradiance", "photosensor"):
            raise ValueError(f"model is for kind = \"irradiance\" or \"photosensor\", not {self.kind!r}")
        if self.model is None and (self.gain is not None or self.integration_ms is not None):
            raise ValueError("gain and integration_ms are for a set with a model (model = \"...\")")
        if (self.on is None) == (self.points is None):
            raise ValueError("give either 'on' (prims to grid) or 'points' (an explicit list), not both or neither")
        if self.points is not None:
            if not self.points:
                raise ValueError("points: empty list")
            if self.normal is None:
                raise ValueError("points need 'normal' (the direction the sensors face)")
            if sum(c * c for c in self.normal) == 0.0:
                raise ValueError("normal: zero-length vector")
        else:
            if not self.on:
                raise ValueError("on: empty list")
            if self.normal is not None:
                raise ValueError("normal is for explicit points; a grid's sensors face its prim's front normal")
        return self


class GroupSpec(_Model):
    """A light group: prim paths or patterns (``lights``), a USD collection, or both (their union)."""

    name: str = Field(min_length=1, description="the group's name (scenario levels refer to it)")
    lights: list[str] = Field([], description="light prim paths or fnmatch patterns")
    collection: str | None = Field(
        None, min_length=1,
        description=(
            "a USD collection, \"/Prim.collection:name\", resolved to the lights it includes"
        )
    )
    sky: Literal["tregenza"] | None = Field(
        None,
        description=(
            "\"tregenza\": the group's one DomeLight traced as 145 sky patches and a ground (daylight coefficients)"
        )
    )
    spectrum: Union[str, Annotated[float, Field(gt=0.0)]] | None = Field(
        None, description="the group's emission spectrum as a sensor model reads it: an illuminant (\"LED-B2\"), a "
        "temperature in K or an SPD .csv beside the study (default: its lights' own)")

    @model_validator(mode="after")
    def _some_lights(self):
        if not self.lights and self.collection is None:
            raise ValueError("give lights (prim paths or patterns) or a collection")
        return self


class SunSpec(_Model):
    azimuth_deg: float | None = Field(
        None, ge=-360.0, le=360.0, description="sun azimuth from north (+Y) toward east (+X)"
    )
    elevation_deg: float | None = Field(None, ge=-90.0, le=90.0, description="sun elevation above the horizon")
    latitude_deg: float | None = Field(
        None, ge=-90.0, le=90.0, description="or: site latitude (with longitude_deg and time; pvlib's solar position)"
    )
    longitude_deg: float | None = Field(None, ge=-180.0, le=180.0, description="site longitude, east positive")
    time: str | None = Field(None, description="ISO 8601 date and time with its UTC offset")

    @model_validator(mode="after")
    def _one_way(self):
        angles = self.azimuth_deg is not None or self.elevation_deg is not None
        place = any(v is not None for v in (self.latitude_deg, self.longitude_deg, self.time))
        if angles == place:
            raise ValueError("give azimuth_deg and elevation_deg, or latitude_deg, longitude_deg and time")
        if angles and (self.azimuth_deg is None or self.elevation_deg is None):
            raise ValueError("give both azimuth_deg and elevation_deg")
        if place and None in (self.latitude_deg, self.longitude_deg, self.time):
            raise ValueError("give latitude_deg, longitude_deg and time together")
        return self


class SkySpec(_Model):
    """A sky on a split sky group (``[[group]] sky = "tregenza"``): its patch levels L_p / L_dome."""

    group: str = Field(min_length=1, description="the split sky group (sky = \"tregenza\") it sets")
    cie: Union[Literal["overcast", "uniform"], Annotated[int, Field(ge=1, le=15)]] = Field(
        description="CIE standard general sky type 1–15, \"overcast\" or \"uniform\""
    )
    horizontal_lx: float | None = Field(
        None, gt=0.0, allow_inf_nan=False,
        description=(
            "the sky's unobstructed horizontal illuminance (default: the dome's authored π·L)"
        )
    )
    ground: float = Field(
        0.0, ge=0.0, le=1e6, allow_inf_nan=False,
        description=(
            "the dome below the horizon, relative to its authored radiance"
        )
    )
    sun: SunSpec | None = Field(
        None,
        description=(
            "the sun for the sky's formula only, as scenario.sun (default: the scenario's, else the stage's)"
        )
    )


class ScenarioSpec(_Model):
    """A ``[[scenario]]``: its groups' dimming levels, a sun, a sky and variant selections.

    A level is a fraction of the group's authored output: 0 is off, 1 full
    output. A level above 1 (a boost: more than the stage's lamps give) is
    refused unless the scenario says ``allow_boost = true``, so that a level
    typed as a percentage (``100``) is not traced as a hundredfold lamp.
    """

    name: str = Field(min_length=1, description="the scenario's name")
    levels: dict[str, Union[Level, list[Level]]] = Field(
        description="group → dimming level; lists expand into their product"
    )
    sun: SunSpec | None = Field(
        None,
        description=(
            "turns the stage's DistantLight: azimuth_deg/elevation_deg, or latitude_deg/longitude_deg/time"
        )
    )
    sky: SkySpec | None = Field(None, description="a CIE sky on a split sky group: its patch levels")
    variants: dict[str, str] = Field({}, description="USD variant selections, set → variant")
    allow_boost: bool = Field(
        False, description="levels above 1 are meant (a boost beyond the stage's output); without it they are refused"
    )

    @field_validator("levels")
    @classmethod
    def _non_empty(cls, v):
        if not v:
            raise ValueError("no group is named: give at least one group's level")
        for g, lv in v.items():
            if isinstance(lv, list) and not lv:
                raise ValueError(f"{g}: empty list of levels")
        return v

    @model_validator(mode="after")
    def _boost_asked(self):
        if self.allow_boost:
            return self
        for g, lv in self.levels.items():
            for x in lv if isinstance(lv, list) else [lv]:
                if x > 1.0:
                    raise ValueError(f"levels.{g}: {x:g} is above 1 (full output; a level is a fraction, not a percentage): "
                                    "set allow_boost = true on the scenario if a boost is meant")
        return self


class ZoneSpec(_Model):
    name: str = Field(min_length=1, description="the zone's name")
    candidates: str = Field(description="the candidate set it judges")
    region: tuple[float, float, float, float] | None = Field(
        None, description="x0, y0, x1, y1: the candidates inside (default: all)", json_schema_extra={"unit": "m"}
    )
    targets: dict[Literal["mean", "min", "max", "u0", "min_max"], float] = Field(
        {}, description="mean, min, max (reading units), u0, min_max: pass/fail/unsure per scenario"
    )

    @field_validator("region")
    @classmethod
    def _box(cls, v):
        if v is not None and not (v[0] < v[2] and v[1] < v[3]):
            raise ValueError("expected [x0, y0, x1, y1] with x0 < x1 and y0 < y1")
        return v


class AreaSpec(_Model):
    """An EN 12464-1 area (:mod:`simulator.study.figures.areas`)."""

    name: str = Field(min_length=1, description="the area's name")
    kind: Literal["task", "walls", "ceiling", "cylindrical"] = Field(
        "task", description="task | walls | ceiling | cylindrical"
    )
    candidates: str = Field(description="the candidate set it is read on")
    task: tuple[float, float, float, float] | None = Field(
        None, description="task: x0, y0, x1, y1 of the task area", json_schema_extra={"unit": "m"}
    )
    region: tuple[float, float, float, float] | None = Field(
        None, description="other kinds: the candidates inside it (default: all)", json_schema_extra={"unit": "m"}
    )
    required_lx: float | None = Field(
        None, gt=0.0, description="task: the task's maintained Ē_m; others: default from the standard"
    )
    u0: float | None = Field(None, gt=0.0, le=1.0, description="task: the task's U0; others: default 0.10")
    surround_m: float = Field(0.5, ge=0.5, description="width of the immediate surrounding band")
    background_m: float = Field(3.0, ge=3.0, description="width of the background band")
    space: Literal["general", "office"] = Field(
        "general", description="walls/ceiling: general (50/30 lx) or office (75/50 lx)"
    )
    maintenance_factor: float = Field(1.0, gt=0.0, le=1.0, description="every figure is maintained: × this factor")
    horizontal: str | None = Field(None, description="cylindrical: a horizontal set at the same points, for E_z/E_h")
    ugr_limit: float | None = Field(None, gt=0.0, description="the task's UGR_L: UGR at the observers, of the lamps, is judged against it")
    observers: list[tuple[float, float, float, float, float, float]] | None = Field(
        None, description="with ugr_limit: [[x, y, z, dx, dy, dz], ...] eyes and view directions (default: the task's "
                          "sides, 1.2 m above the floor, looking across)", json_schema_extra={"unit": "m"})

    @model_validator(mode="after")
    def _fields(self):
        if self.observers is not None and self.ugr_limit is None:
            raise ValueError("observers are for a UGR check: give ugr_limit (the standard's UGR_L for the task)")
        for key, v in (("task", self.task), ("region", self.region)):
            if v is not None and not (v[0] < v[2] and v[1] < v[3]):
                raise ValueError(f"{key}: expected [x0, y0, x1, y1] with x0 < x1 and y0 < y1")
        if self.kind == "task":
            if self.task is None or self.required_lx is None or self.u0 is None:
                raise ValueError("a task area needs task = [x0, y0, x1, y1], required_lx and u0 (from the standard's table for the task)")
        elif self.task is not None:
            raise ValueError(f"task is for kind = \"task\", not {self.kind!r} (give region)")
        if self.horizontal is not None and self.kind != "cylindrical":
            raise ValueError("horizontal is for kind = \"cylindrical\"")
        return self


class PlacementSpec(_Model):
    k: int = Field(1, ge=1, le=64, description="sensors to choose")
    candidates: list[str] = Field(min_length=1, description="candidate sets to choose from")
    target: str = Field("each_zone", description="\"each_zone\", or one zone's name")
    objective: Literal["correlation", "max_rel_error", "p95_rel_error"] = Field(
        "correlation", description="correlation | max_rel_error | p95_rel_error (after a per-sensor linear calibration)"
    )
    replicates: int = Field(200, ge=20, le=10000, description="parametric bootstrap replicates for the score errors")


class OutputSpec(_Model):
    dir: str | None = Field(
        None, description="output folder, relative to the study (default: <study stem>.out/ beside it)"
    )
    heat_map_scale: Literal["shared", "per_scenario", "log"] = Field(
        "shared", description="the plans' colour scale: shared (one per zone for all scenarios), per_scenario (each "
                              "plan its own) or log (one logarithmic scale)"
    )


class AnnualSpec(_Model):
    """A year of daylight from a climate file (:mod:`simulator.study.annual.year`)."""

    weather: str = Field(min_length=1, description="EPW (.epw) or TMY3 (.csv) climate file, relative to the study")
    sky_group: str = Field(min_length=1, description="a [[group]] with sky = \"tregenza\"")
    illuminance: Literal["file", "efficacy"] = Field(
        "file", description="file (the file's illuminance fields) or efficacy (Perez 1990 on its irradiances)"
    )
    ground_reflectance: float = Field(0.2, ge=0.0, le=1.0, description="the ground below the horizon")
    step_h: int = Field(1, ge=1, le=24, description="every n-th daylight hour")
    occupied_h: tuple[float, float] = Field(
        (8.0, 18.0), description="occupied hours [start, end], local standard time (IES LM-83)"
    )
    da_lx: float = Field(300.0, gt=0.0, description="daylight autonomy threshold (DA300)")
    ase_lx: float = Field(1000.0, gt=0.0, description="annual sunlight exposure threshold (ASE1000)")
    ase_hours: float = Field(250.0, ge=0.0, description="ASE: hours above ase_lx that count a point (ASE1000/250h)")
    udi_lx: tuple[float, float] = Field((100.0, 2000.0), description="useful daylight illuminance band [lower, upper]")
    en17037_lx: tuple[float, float] = Field(
        (300.0, 100.0), description="EN 17037 minimum: [target, minimum target] illuminances"
    )
    replicates: int = Field(64, ge=8, le=4096, description="bootstrap replicate years for the metrics' standard errors")
    sun_patches: int = Field(
        4, ge=1, le=8, description="nearest sky patches the sun's interreflected light is spread over"
    )
    sun_indirect: Literal["patches", "traced"] = Field(
        "patches", description="patches (no extra trace) or traced (the sun traced at binned positions)"
    )
    sun_group: str | None = Field(
        None, min_length=1, description="traced: a [[group]] holding the stage's one DistantLight"
    )
    sun_bin_deg: float = Field(6.0, ge=1.0, le=30.0, description="traced: size of the sun-position bins")
    glare_index: Literal["dgp", "dgps"] = Field(
        "dgp", description="the stage's glare views, every hour: dgp (sky, sun and shade as sources) or dgps (from E_v alone)"
    )
    glare_limit: float = Field(0.40, gt=0.0, lt=1.0, description="glare autonomy: the share of occupied hours below this DGP")

    @model_validator(mode="after")
    def _ranges(self):
        if not 0.0 <= self.occupied_h[0] < self.occupied_h[1] <= 24.0:
            raise ValueError("occupied_h: expected [start, end] hours with 0 <= start < end <= 24")
        if not 0.0 < self.udi_lx[0] < self.udi_lx[1]:
            raise ValueError("udi_lx: expected [lower, upper] with 0 < lower < upper")
        return self


class ShadingSpec(_Model):
    """Operable shading of a window group (:mod:`simulator.study.annual.shading`): its states, the rule that picks one each hour."""

    variant_set: str = Field(min_length=1, description="the stage's variant set whose variants are the shading states")
    states: list[str] = Field(min_length=1, description="its variants, least shaded first (LM-83: shades up, then down)")
    rule: Literal["lm83", "glare", "schedule"] = Field(
        "lm83", description="each hour the first state that: lm83, lets no more than share of the points get ase_lx of "
                            "direct sun; glare, keeps DGP under dgp_limit at every view; schedule, the hour's state")
    zones: list[str] = Field([], description="lm83: the zones whose points are counted (default: every zone's)")
    share: float = Field(0.02, ge=0.0, lt=1.0, description="lm83: the share of points in direct sun that closes the shades")
    views: list[str] = Field([], description="glare: the stage's glare views that judge (default: all)")
    dgp_limit: float = Field(0.40, gt=0.0, le=1.0, description="glare: the DGP a view may not exceed")
    schedule: dict[str, list[tuple[float, float, float, float]]] = Field(
        {}, description="schedule: state → [[month from, month to, hour from, hour to], ...] (LST; other hours: the first state)")
    diffusers: dict[str, Annotated[float, Field(gt=0.0, le=1.0)]] = Field(
        {}, description="flat shade prims → diffuse transmittance: each passes τ·E/π, E the light on its outer face")


class ControlSpec(_Model):
    """Photosensor control of a zone's light groups over the annual hours (:mod:`simulator.study.annual.control`)."""

    zone: str = Field(description="the zone whose lamps it dims")
    groups: list[str] = Field(min_length=1, description="light groups the control dims")
    model: Literal["closed_loop", "open_loop", "switched"] = Field(
        "closed_loop", description="closed_loop | open_loop | switched"
    )
    photosensor: str = Field(description="a candidate's name, or a candidate set: the best annual control")
    target_lx: float | None = Field(None, gt=0.0, description="default: the zone's mean target")
    min_level: float = Field(0.1, ge=0.0, le=1.0, description="dimming floor (closed and open loop)")
    deadband: float = Field(
        0.2, ge=0.0, le=10.0, description="switched: off above target·(1 + deadband), on below target"
    )


class Study(_Model):
    """A whole study file; see the module docstring for the schema."""

    stage: str = Field(description="the USD stage, relative to the study")
    project: str | None = Field(None, min_length=1, description="the report's title (default: the stage's file name)")
    light_units: Literal["photometric", "radiometric"] = Field(
        "photometric", description="photometric | radiometric, as a run config's"
    )
    seed: int = Field(1, ge=0, lt=_SEED_LIMIT, description="study seed: each chunk's seed derives from it")
    simulation: SimulationSpec = SimulationSpec()
    compute: ComputeSpec = ComputeSpec()
    candidates: list[CandidateSpec] = Field(min_length=1)
    group: list[GroupSpec] = Field(min_length=1)
    scenario: list[ScenarioSpec] = []
    zone: list[ZoneSpec] = []
    area: list[AreaSpec] = []
    placement: PlacementSpec | None = None
    output: OutputSpec = OutputSpec()
    annual: AnnualSpec | None = None
    control: list[ControlSpec] = []
    shading: ShadingSpec | None = None

    @model_validator(mode="after")
    def _references(self):
        def unique(items, what):
            seen = set()
            for i, it in enumerate(items):
                if it.name in seen:
                    raise _RefError(f"{what}[{i}].name", f"duplicate name {it.name!r}")
                seen.add(it.name)
            return seen

        cands = unique(self.candidates, "candidates")
        groups = unique(self.group, "group")
        unique(self.scenario, "scenario")
        zones = unique(self.zone, "zone")
        split = {g.name for g in self.group if g.sky is not None}
        if not self.scenario and self.annual is None:
            raise _RefError("scenario", "give at least one [[scenario]] (or an [annual] table)")
        _check_annual(self, groups, split, zones, cands)
        _check_patch_batches(self, split)
        for i, sc in enumerate(self.scenario):
            for g in sc.levels:
                if g not in groups:
                    raise _RefError(f"scenario[{i}].levels.{g}", f"no [[group]] of that name{_hint(g, groups)}")
            if sc.sky is not None and sc.sky.group not in split:
                raise _RefError(f"scenario[{i}].sky.group", f"no [[group]] named {sc.sky.group!r} with sky = \"tregenza\""
                                f"{_hint(sc.sky.group, split)}")  # fmt: skip
        for i, z in enumerate(self.zone):
            if z.candidates not in cands:
                raise _RefError(f"zone[{i}].candidates", f"no [[candidates]] named {z.candidates!r}{_hint(z.candidates, cands)}")
        unique(self.area, "area")
        for i, a in enumerate(self.area):
            for key in ("candidates", "horizontal"):
                c = getattr(a, key)
                if c is not None and c not in cands:
                    raise _RefError(f"area[{i}].{key}", f"no [[candidates]] named {c!r}{_hint(c, cands)}")
        if self.placement is not None:
            for j, c in enumerate(self.placement.candidates):
                if c not in cands:
                    raise _RefError(f"placement.candidates[{j}]", f"no [[candidates]] named {c!r}{_hint(c, cands)}")
            t = self.placement.target
            if t != "each_zone" and t not in zones:
                raise _RefError("placement.target", f"expected 'each_zone' or a zone name, got {t!r}{_hint(t, zones)}")
            if not self.zone:
                raise _RefError("placement", "needs at least one [[zone]] to predict")
            if not self.scenario:
                raise _RefError("placement", "needs [[scenario]] entries to predict (an annual study chooses photosensors by [[control]])")
        return self


#: Samples in one kernel block (``simulator.engine.driver.BLOCK``): a sky split into patches
#: estimates its covariance from block means, so an adaptive run needs two blocks for any error at all.
SAMPLES_PER_BLOCK = 32


def _check_patch_batches(study: "Study", split: set) -> None:
    """A sky traced as patches needs at least two batches per sensor, or its errors cannot be estimated.

    The patches' covariance is the batch-means estimate over B − 1 degrees of
    freedom (``simulator.engine.stats.GroupBatchStats``). A fixed budget under
    two blocks is drawn in smaller batches (``driver.MIN_GROUP_BATCHES``), so
    only one sample per sensor leaves B − 1 = 0; an adaptive run's batches are
    whole blocks, so its ``max_samples`` must allow two. Either way every hourly
    error, DF error and control score error would otherwise be undefined."""
    if not split:
        return
    sim = study.simulation
    if sim.rel_error is None and sim.samples < 2:
        raise _RefError("simulation.samples", f"a sky split into patches (group {sorted(split)[0]!r}) needs at least "
                        f"2 samples per sensor (two batches) to estimate its errors; got {sim.samples}")  # fmt: skip
    if sim.rel_error is not None and sim.max_samples is not None and sim.max_samples <= SAMPLES_PER_BLOCK:
        raise _RefError("simulation.max_samples", f"a sky split into patches (group {sorted(split)[0]!r}) needs more "
                        f"than {SAMPLES_PER_BLOCK} samples per sensor to estimate its errors; got {sim.max_samples}")


def _check_annual(study: "Study", groups: set, split: set, zones: set, cands: set) -> None:
    """Cross-references of ``[annual]`` and ``[[control]]``."""
    a = study.annual
    if a is not None and a.sky_group not in split:
        raise _RefError("annual.sky_group", f"no [[group]] named {a.sky_group!r} with sky = \"tregenza\"{_hint(a.sky_group, split)}")
    if a is not None and a.sun_indirect == "traced":
        if a.sun_group is None:
            raise _RefError("annual.sun_group", "sun_indirect = \"traced\" needs sun_group (a [[group]] holding the DistantLight)")
        if a.sun_group not in groups or a.sun_group in split:
            raise _RefError("annual.sun_group", f"no lamp [[group]] named {a.sun_group!r}{_hint(a.sun_group, groups - split)}")
    if study.control and a is None:
        raise _RefError("control", "needs an [annual] table (control runs over the year's hours)")
    sh = study.shading
    if sh is not None:
        if a is None:
            raise _RefError("shading", "needs an [annual] table (the shades are operated over the year's hours)")
        if len(set(sh.states)) != len(sh.states):
            raise _RefError("shading.states", "a state is named twice")
        for j, z in enumerate(sh.zones):
            if z not in zones:
                raise _RefError(f"shading.zones[{j}]", f"no [[zone]] named {z!r}{_hint(z, zones)}")
        if sh.rule == "lm83" and not sh.zones and not zones:
            raise _RefError("shading.rule", "lm83 counts the points of the zones: the study has no [[zone]]")
        for st, entries in sh.schedule.items():
            if st not in sh.states:
                raise _RefError(f"shading.schedule.{st}", f"not one of the states {sh.states}{_hint(st, sh.states)}")
            for k, (m0, m1, h0, h1) in enumerate(entries):
                if not (1 <= m0 <= 12 and 1 <= m1 <= 12 and 0 <= h0 < h1 <= 24):
                    raise _RefError(f"shading.schedule.{st}[{k}]", "expected [month from, month to, hour from, hour to] "
                                    "with months 1-12 and 0 <= hour from < hour to <= 24")  # fmt: skip
        if sh.rule == "schedule" and not sh.schedule:
            raise _RefError("shading.schedule", "rule = \"schedule\" needs a schedule (state → hours)")
        if sh.rule != "schedule" and sh.schedule:
            raise _RefError("shading.schedule", f"is for rule = \"schedule\", not {sh.rule!r}")
        for key, rule in (("zones", "lm83"), ("views", "glare")):
            if getattr(sh, key) and sh.rule != rule:
                raise _RefError(f"shading.{key}", f"is for rule = \"{rule}\", not {sh.rule!r}")
        for prim in sh.diffusers:
            if not prim.startswith("/"):
                raise _RefError(f"shading.diffusers.{prim}", "expected a prim path such as /Office/Blinds/Shade")
    for i, c in enumerate(study.control):
        if c.zone not in zones:
            raise _RefError(f"control[{i}].zone", f"no [[zone]] named {c.zone!r}{_hint(c.zone, zones)}")
        for j, g in enumerate(c.groups):
            if g not in groups or g in split:
                raise _RefError(f"control[{i}].groups[{j}]", f"no lamp [[group]] named {g!r}{_hint(g, groups - split)}")
        z = next(zz for zz in study.zone if zz.name == c.zone)
        if c.target_lx is None and "mean" not in z.targets:
            raise _RefError(f"control[{i}].target_lx", f"zone {c.zone!r} has no mean target: give target_lx")


class _RefError(ValueError):
    """A cross-reference problem, raised with its own key path."""

    def __init__(self, key: str, message: str):
        super().__init__(message)
        self.key = key


def _hint(name: str, known) -> str:
    m = difflib.get_close_matches(name, sorted(known), n=1)
    return f" (did you mean {m[0]!r}?)" if m else ""


def _key_path(loc: tuple) -> str:
    out = ""
    for part in loc:
        if isinstance(part, int):
            out += f"[{part}]"
        elif str(part).startswith(("constrained-", "function-", "list[", "literal[", "tuple[", "float", "int", "str")):
            continue  # pydantic's union-branch labels are not keys
        else:
            out += f".{part}" if out else str(part)
    return out


def _message(err: dict) -> str:
    msg = err["msg"]
    for prefix in ("Value error, ", "Assertion failed, "):
        if msg.startswith(prefix):
            msg = msg[len(prefix):]
    if err["type"] == "extra_forbidden":
        return "unknown key"
    if err["type"] == "missing":
        return "required key is missing"
    return " ".join(msg.split())


def load_study(path: str | os.PathLike, overrides: dict | None = None) -> tuple[Study, Path]:
    """Read and validate a study file.

    Parameters
    ----------
    overrides : dict, optional
        Command-line values, ``{(table, ..., key): (flag, value)}`` (e.g.
        ``{("simulation", "samples"): ("--samples", 64)}``), written into the
        file's tables before validation, so a flag obeys its key's own rule;
        a message about one names the flag.

    Returns
    -------
    (Study, Path)
        The model and the file's absolute path (relative paths in it are
        relative to its folder).

    Raises
    ------
    UserError
        ``"<file>: <key path>: <what is wrong>"`` for the first problem.
    """
    label = os.fspath(path)
    p = Path(label).expanduser().resolve()
    try:
        with open(p, "rb") as fh:
            raw = tomllib.load(fh)
    except FileNotFoundError:
        raise UserError(f"{label}: study file not found") from None
    except IsADirectoryError:
        raise UserError(f"{label}: is a directory, not a study file") from None
    except OSError as exc:
        raise UserError(f"{label}: cannot read study file: {exc.strerror or exc}") from None
    except (UnicodeDecodeError, tomllib.TOMLDecodeError) as exc:
        raise UserError(f"{label}: invalid TOML: {exc}") from None
    flags = {}
    for loc, (flag, value) in (overrides or {}).items():
        table = raw
        for part in loc[:-1]:
            table = table.setdefault(part, {})
            if not isinstance(table, dict):
                raise UserError(f"{label}: {_key_path(loc[:-1])}: must be a table")
        table[loc[-1]] = value
        flags[tuple(loc)] = flag
    try:
        study = Study.model_validate(raw)
    except ValidationError as exc:
        err = exc.errors()[0]
        ctx_err = (err.get("ctx") or {}).get("error")
        if isinstance(ctx_err, _RefError):
            raise UserError(f"{label}: {ctx_err.key}: {ctx_err}") from None
        key = flags.get(tuple(err["loc"])) or _key_path(err["loc"])
        if err["type"] == "extra_forbidden" and err["loc"]:
            hint = _allowed_hint(err["loc"])
            raise UserError(f"{label}: {key}: unknown key{hint}") from None
        raise UserError(f"{label}: {key + ': ' if key else ''}{_message(err)}") from None
    stage = (p.parent / study.stage).resolve() if not Path(study.stage).is_absolute() else Path(study.stage)
    if not stage.is_file():
        raise UserError(f"{label}: stage: stage file not found: {stage}")
    return study, p


def _allowed_hint(loc: tuple) -> str:
    """``(did you mean 'x'?)`` for an unknown key, from the model at that place."""
    model: type[BaseModel] = Study
    for part in loc[:-1]:
        if isinstance(part, int):
            continue
        field = model.model_fields.get(part)
        if field is None:
            return ""
        ann = field.annotation
        inner = getattr(ann, "__args__", (ann,))
        nxt = next((a for a in inner if isinstance(a, type) and issubclass(a, BaseModel)), None)
        if nxt is None:
            inner2 = [getattr(a, "__args__", ()) for a in inner]
            nxt = next((b for args in inner2 for b in args if isinstance(b, type) and issubclass(b, BaseModel)), None)
        if nxt is None:
            return ""
        model = nxt
    name = str(loc[-1])
    allowed = list(model.model_fields)
    m = difflib.get_close_matches(name, allowed, n=1)
    did = f"did you mean {m[0]!r}? " if m else ""
    return f" ({did}expected one of: {', '.join(allowed)})"
