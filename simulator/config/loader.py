"""Run configs: a TOML file read into a fully validated :class:`RunConfig`.

A config names the stage to trace, how to read its light values, the
simulation settings, and the sensors (single ``[[sensor]]`` entries and
``[[grid]]`` rectangles expanded into irradiance sensors at cell centres);
:mod:`simulator.config.schema` lists every key. Everything is checked here,
before any stage is read or kernel compiled: the first problem found is
raised as a :class:`~simulator.errors.UserError` whose one-line message
names the config file and the key path, e.g.
``configs/a.toml: sensor[2].normal: zero-length vector``.

Paths in a config (``stage``, ``output.csv``) are relative to the config
file's folder; paths given on the command line (see :func:`apply_overrides`)
are relative to the current directory.
"""

from __future__ import annotations

import os
import tomllib
from pathlib import Path

from pydantic_core import ValidationError

from simulator.config.capacity import too_many_sensors
from simulator.config.errors import translate, user_error
from simulator.config.overrides import apply_overrides
from simulator.config.paths import resolve_path
from simulator.config.records import (
    COMPONENTS, DEFAULT_MAX_SAMPLES, DEVICES, LIGHT_UNITS, MAX_PROBE_PIXELS, METHODS, GridConfig, OutputConfig,
    RunConfig, SimulationConfig,
)  # fmt: skip
from simulator.config.schema import RunFile
from simulator.errors import UserError
from simulator.scene.model import DEFAULT_PROBE_RESOLUTION, SENSOR_KINDS, Sensor, SensorKind

__all__ = [
    "COMPONENTS",
    "METHODS",
    "DEVICES",
    "LIGHT_UNITS",
    "SENSOR_KINDS",
    "DEFAULT_MAX_SAMPLES",
    "DEFAULT_PROBE_RESOLUTION",
    "MAX_PROBE_PIXELS",
    "SensorKind",
    "SimulationConfig",
    "GridConfig",
    "OutputConfig",
    "RunConfig",
    "load_config",
    "apply_overrides",
]


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
    cfg_path = Path(label).expanduser().resolve()
    raw = _read_toml(cfg_path, label)
    try:
        doc = RunFile.model_validate(raw)
    except ValidationError as exc:
        raise translate(exc, raw, label) from None

    base = cfg_path.parent
    stage = resolve_path(base, doc.stage)
    if not stage.exists():
        raise user_error(label, "stage", f"stage file not found: {stage}")
    if not stage.is_file():
        raise user_error(label, "stage", f"not a file: {stage}")

    default_csv = base / f"{cfg_path.stem}.csv"
    output = OutputConfig(csv=default_csv if doc.output.csv is None else resolve_path(base, doc.output.csv),
                          csv_columns=doc.output.csv_columns)
    sensors, grids = _sensors(doc, label)
    _attach_models(doc, sensors, base, label)
    spectra = None
    if doc.output.responses is not None or doc.spectra is not None:
        from simulator.spectra.config import load_spectra_settings

        spectra = load_spectra_settings(raw, Path(label).expanduser())  # messages name the file as given
    return RunConfig(
        path=cfg_path,
        stage=stage,
        light_units=doc.light_units,
        radiometric_spectrum=doc.radiometric_spectrum,
        simulation=doc.simulation.to_record(),
        sensors=sensors,
        grids=grids,
        output=output,
        raw=raw,
        variants=dict(doc.variants),
        spectra=spectra,
        time=doc.time,
        times=_times(doc, label),
    )


def _times(doc: RunFile, label: str) -> tuple[float, ...] | None:
    """``times`` as a tuple, refused beside ``time`` (one line naming the key)."""
    if doc.times is None:
        return None
    if doc.time is not None:
        raise user_error(label, "times", "give time (one reading) or times (several), not both")
    if len(set(doc.times)) != len(doc.times):
        raise user_error(label, "times", "a time code is given twice")
    return tuple(float(t) for t in doc.times)


def _attach_models(doc: RunFile, sensors: list[Sensor], base: Path, label: str) -> None:
    """Read the sensor models the entries name (each file once) and give each sensor its own; check
    ``gain`` and ``integration_ms`` against the part (one line naming the key)."""
    from simulator.sensor_models.model import load_model

    by_source = {s.source: [] for s in sensors}
    for s in sensors:
        by_source[s.source].append(s)
    for table, entries in (("sensor", doc.sensor), ("grid", doc.grid)):
        for k, entry in enumerate(entries):
            source = f"{table}[{k}]"
            model = getattr(entry, "model", None)
            gain, t_ms = getattr(entry, "gain", None), getattr(entry, "integration_ms", None)
            if model is None:
                for key, v in (("gain", gain), ("integration_ms", t_ms), ("azimuth_ref", getattr(entry, "azimuth_ref", None))):
                    if v is not None:
                        raise user_error(label, f"{source}.{key}", "only with a model (model = \"...\")")
                continue
            where = f"{label}: {source}.model"
            try:
                m = load_model(model, base, where)
            except UserError as e:  # a model file's own mistake: named through the config's key
                raise UserError(str(e) if str(e).startswith(where) else f"{where}: {e}") from None
            if gain is not None and gain != "auto" and (isinstance(gain, bool) or not isinstance(gain, (int, float))
                                                       or not gain > 0):
                raise user_error(label, f"{source}.gain", f'expected a positive number or "auto", got {gain!r}')
            if m.electronics is None:
                if gain is not None or t_ms is not None:
                    raise user_error(label, f"{source}.{'gain' if gain is not None else 'integration_ms'}",
                                     f"model {m.name!r} has no electronics")
            else:
                m.electronics.check_setting(None if gain is None else gain, t_ms, f"{label}: {source}")
            for s in by_source.get(source, ()):
                s.model = m


def _read_toml(cfg_path: Path, label: str) -> dict:
    """The parsed file, or a one-line error naming it."""
    try:
        with open(cfg_path, "rb") as fh:
            return tomllib.load(fh)
    except FileNotFoundError:
        raise user_error(label, "", "config file not found") from None
    except IsADirectoryError:
        raise user_error(label, "", "is a directory, not a config file") from None
    except OSError as exc:
        raise user_error(label, "", f"cannot read config: {exc.strerror or exc}") from None
    except UnicodeDecodeError as exc:
        raise user_error(label, "", f"invalid TOML: not UTF-8 text ({exc.reason} at byte {exc.start})") from None
    except tomllib.TOMLDecodeError as exc:
        raise user_error(label, "", f"invalid TOML: {exc}") from None


def _sensors(doc: RunFile, label: str) -> tuple[list[Sensor], list[GridConfig]]:
    """``[[sensor]]`` entries then grid cells, in file order; names must be unique."""
    sensors: list[Sensor] = []
    owner: dict[str, str] = {}  # sensor name -> config key that defined it
    for k, entry in enumerate(doc.sensor):
        source = f"sensor[{k}]"
        s = entry.to_sensor(source if entry.name is None else entry.name, source)
        if s.name in owner:
            raise user_error(label, f"{source}.name", f"duplicate sensor name {s.name!r} (also {owner[s.name]})")
        owner[s.name] = source
        sensors.append(s)

    grids: list[GridConfig] = []
    grid_owner: dict[str, str] = {}
    counts = [entry.cells() for entry in doc.grid]
    why = too_many_sensors(len(sensors) + sum(nx * ny for nx, ny in counts)) if counts else None
    if why is not None:  # refused before a cell is built: billions of them would fill the memory first
        k = max(range(len(counts)), key=lambda i: counts[i][0] * counts[i][1])  # the largest grid is named
        nx, ny = counts[k]
        raise user_error(label, f"grid[{k}].spacing", f"{nx:,} x {ny:,} cells: {why}; use a coarser spacing or a smaller size")
    for k, entry in enumerate(doc.grid):
        source = f"grid[{k}]"
        if entry.name in grid_owner:
            raise user_error(label, f"{source}.name", f"duplicate grid name {entry.name!r} (also {grid_owner[entry.name]})")
        grid_owner[entry.name] = source
        g, cells = entry.to_grid(source)
        for s in cells:
            if s.name in owner:
                raise user_error(label, f"{source}.name", f"cell sensor name {s.name!r} is already used by {owner[s.name]}")
            owner[s.name] = source
        grids.append(g)
        sensors.extend(cells)
    return sensors, grids
