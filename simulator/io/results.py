"""Readings as rows, and the files they go to: CSV (always) and a JSON run record.

Writers see plain numbers only: no Warp, no USD. Files are written to a
temporary name beside the target and renamed into place, so an interrupted
run never leaves a half-written CSV.
"""

from __future__ import annotations

import csv
import io
import json
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from simulator.config.records import CSV_COLUMN_SETS  # declared once, with the config's choices
from simulator.io.atomic import write_all_atomic
from simulator.scene.model import SENSOR_SPECS, SensorKind, Sensor

__all__ = ["COLUMNS", "CSV_COLUMN_SETS", "csv_columns", "PROBE_COLUMNS", "Reading", "readings_from", "probe_readings", "extra_columns", "write_outputs", "record_text", "format_table", "json_default"]


def _value_columns() -> tuple[str, ...]:
    """Every sensor kind's value columns (``SensorKindSpec.columns``), in
    kind order, each once; kinds with ``extra_columns`` are left out."""
    out: list[str] = []
    for spec in SENSOR_SPECS:
        if spec.extra_columns:
            continue  # written only when a run holds one (extra_columns)
        for group in spec.columns:
            out += [c for c in group.columns if c not in out]
    return tuple(out)


#: CSV columns, in order; units are in the names. A column that does not
#: apply to a sensor's kind is left empty, never 0.
COLUMNS = ("sensor", "kind", "x", "y", "z", "dx", "dy", "dz", *_value_columns(), "samples", "seconds", "method", "target_met")
#: ``[output] csv_columns`` (``probesim run --csv-columns``): ``"kinds"``, the columns of the sensor kinds
#: the run holds (:func:`csv_columns`); ``"full"``, every column of :data:`COLUMNS` whatever the kinds
#: the columns every row of a run fills: who, what, where
_ALWAYS = ("sensor", "kind", "x", "y", "z")
#: columns only a probe fills: scalar irradiance (fluence rate, ∫L dω over the
#: sphere) and the unit mean direction of arrival (normalised ∫L·ω dω,
#: radiometric) with its angular standard error; the six face irradiances and
#: SH coefficients go to ``<csv stem>.probes.json`` (see simulator.io.maps)
PROBE_COLUMNS = tuple(c for group in SENSOR_SPECS[SensorKind.PROBE].columns for c in group.columns)


@dataclass
class Reading:
    """One sensor's row: quantity name → value, plus bookkeeping."""

    sensor: Sensor
    values: dict[str, float]
    samples: int
    seconds: float
    method: str
    target_met: bool | None


def readings_from(sensors: list[Sensor], mean: np.ndarray, stderr: np.ndarray, samples, seconds, method, target_met) -> list[Reading]:
    """Turn per-sensor estimates (channel 0 radiometric, 1 photometric) into rows.

    Each kind fills the column groups its ``SensorKindSpec.columns`` names:
    a patch's estimate is its mean irradiance, and its flux that × its area.
    ``method`` is one name for all, or one per sensor.
    """
    rows = []
    if np.asarray(mean).dtype == np.float64 and np.asarray(stderr).dtype == np.float64:
        # Python floats: the same doubles and the same products as float64 scalars, without indexing numpy per row
        mean, stderr = np.asarray(mean).tolist(), np.asarray(stderr).tolist()
    for i, s in enumerate(sensors):
        m, e = mean[i], stderr[i]
        v: dict[str, float] = {}
        for group in s.spec.columns:
            val, val_se, photo, photo_se = group.columns
            if group.factor == "area":
                area = s.size[0] * s.size[1]
                v.update({val: m[0] * area, val_se: e[0] * area, photo: m[1] * area, photo_se: e[1] * area})
            else:
                v.update({val: m[0], val_se: e[0], photo: m[1], photo_se: e[1]})
        met = None if target_met is None else bool(target_met[i])
        m_i = method if isinstance(method, str) else method[i]
        rows.append(Reading(s, {k: float(x) for k, x in v.items()}, int(samples[i]), float(seconds[i]), m_i, met))
    return rows


def probe_readings(results, method: str) -> list[Reading]:
    """Rows of probes from :class:`simulator.engine.probes.ProbeResult` objects.

    A probe fills :data:`PROBE_COLUMNS` only; ``samples`` counts directions.
    """
    rows = []
    for r in results:
        (val, se) = r.scalar_irradiance
        m, m_se = r.mean_direction(0)
        v = {
            "scalar_irradiance_W_m2": val[0], "scalar_irradiance_stderr_W_m2": se[0],
            "scalar_illuminance_lx": val[1], "scalar_illuminance_stderr_lx": se[1],
        }  # fmt: skip
        if np.all(np.isfinite(m)):  # no light at all: no direction (left empty)
            v.update(mean_direction_x=m[0], mean_direction_y=m[1], mean_direction_z=m[2], mean_direction_stderr_deg=m_se)
        rows.append(Reading(r.sensor, {k: float(x) for k, x in v.items()}, int(r.samples), float(r.seconds), method, r.target_met))
    return rows


def _fmt(x) -> str:
    if x is None:
        return ""
    if isinstance(x, bool):
        return "true" if x else "false"
    if isinstance(x, (int, np.integer)):
        return str(int(x))
    if isinstance(x, (float, np.floating)):
        return f"{float(x):.9g}"
    return str(x)


def extra_columns(rows: list[Reading]) -> list[str]:
    """Columns beyond :data:`COLUMNS` that rows carry (response columns such as
    ``ppfd_umol_m2_s``, see :mod:`simulator.spectra.posthoc`), in first-seen order.
    They follow the standard columns; a run without them writes exactly
    :data:`COLUMNS`."""
    known = set(COLUMNS)
    seen: dict[str, None] = {}
    for r in rows:
        for k in r.values:
            if k not in known:
                seen[k] = None
    return list(seen)


def csv_columns(rows: list[Reading], columns: str = "full") -> tuple[str, ...]:
    """The CSV header of a run's rows.

    Parameters
    ----------
    columns : {"kinds", "full"}
        ``"full"``: :data:`COLUMNS` then :func:`extra_columns`, the 32-column
        layout whatever the sensors. ``"kinds"``: the same columns in the
        same order, keeping only those the run's sensor kinds have:
        ``sensor, kind, x, y, z``; ``dx, dy, dz`` if a kind is directed (all
        but probes); each present kind's value columns
        (``SensorKindSpec.columns``: irradiance 4, radiance 4, patch 8 with
        its flux, probe 8, cylindrical 4, semicylindrical 4); the extra
        (response) columns; ``samples, seconds, method``; and ``target_met``
        where a row has one (an adaptive or interrupted run). So a run of
        one kind leaves no cell empty; a run mixing kinds leaves a kind's
        cells empty in the other kinds' rows, as the full set does.
    """
    full = COLUMNS + tuple(extra_columns(rows))
    if columns == "full":
        return full
    if columns != "kinds":
        raise ValueError(f"columns must be one of {CSV_COLUMN_SETS}, not {columns!r}")
    specs = {r.sensor.kind: r.sensor.spec for r in rows}.values()
    keep = set(_ALWAYS) | {"samples", "seconds", "method"}
    if any(spec.directed for spec in specs):
        keep |= {"dx", "dy", "dz"}
    for spec in specs:
        keep |= {c for group in spec.columns for c in group.columns}
    if any(r.target_met is not None for r in rows):
        keep.add("target_met")
    keep |= set(extra_columns(rows))
    return tuple(c for c in full if c in keep)


def _cells(values: list) -> list[str]:
    """:func:`_fmt` of each value of one column, with fast paths for a column of one type (a
    1,024-row CSV's 32 columns cell by cell took ~15 ms)."""
    kinds = set(map(type, values))
    if kinds == {float}:
        return [format(x, ".9g") for x in values]
    if kinds == {np.float64}:
        return [format(float(x), ".9g") for x in values]
    if kinds == {type(None)}:
        return [""] * len(values)
    if kinds == {str}:
        return values
    return [_fmt(x) for x in values]


def _csv_text(rows: list[Reading], column_set: str = "full") -> str:
    """The CSV: a header of :func:`csv_columns` (``column_set`` "full": :data:`COLUMNS` and
    :func:`extra_columns`), one row per reading, each cell :func:`_fmt` of its value (empty where the
    column does not apply), built column by column."""
    buf = io.StringIO()
    w = csv.writer(buf, lineterminator="\n")
    columns = csv_columns(rows, column_set)
    w.writerow(columns)
    sensors = [r.sensor for r in rows]
    directed = [s.spec.directed for s in sensors]
    fixed = {
        "sensor": [s.name for s in sensors], "kind": [s.spec.name for s in sensors],
        "x": [s.position[0] for s in sensors], "y": [s.position[1] for s in sensors], "z": [s.position[2] for s in sensors],
        "dx": [s.normal[0] if d else None for s, d in zip(sensors, directed)],
        "dy": [s.normal[1] if d else None for s, d in zip(sensors, directed)],
        "dz": [s.normal[2] if d else None for s, d in zip(sensors, directed)],
        "samples": [r.samples for r in rows], "seconds": [r.seconds for r in rows],
        "method": [r.method for r in rows], "target_met": [r.target_met for r in rows],
    }  # fmt: skip
    cells = []
    present = {k for r in rows for k in r.values}
    for c in columns:
        if c not in present and c not in fixed:  # a column no row fills (another kind's)
            cells.append([""] * len(rows))
            continue
        in_values = [r.values.get(c, _ABSENT) for r in rows]  # a reading's value wins over the fixed fields
        if c in fixed:
            in_values = [f if v is _ABSENT else v for v, f in zip(in_values, fixed[c])]
        else:
            in_values = [None if v is _ABSENT else v for v in in_values]
        cells.append(_cells(in_values))
    w.writerows(zip(*cells))
    return buf.getvalue()


_ABSENT = object()


def write_outputs(csv_path: Path, rows: list[Reading], record: dict, extra: dict | None = None,
                  encoded: dict[str, str] | None = None, csv_columns: str = "full") -> Path:
    """Write the CSV, its run record (``<csv stem>.run.json``) and ``extra``
    files (path → text, bytes or a writer callable, e.g. from
    :mod:`simulator.io.maps`) atomically, all renamed into place together.

    ``csv_columns``: the CSV's column set (:data:`CSV_COLUMN_SETS`, see :func:`csv_columns`; ``probesim
    run`` passes its config's ``[output] csv_columns``, "kinds" by default).

    ``encoded``: top-level keys of ``record`` whose value is given already
    encoded, as ``json.dumps(value, indent=2, sort_keys=True)`` (see
    :func:`record_text`).

    Returns the run record's path.
    """
    record_path = csv_path.with_name(csv_path.stem + ".run.json")
    write_all_atomic(
        {
            **(extra or {}),
            csv_path: _csv_text(rows, csv_columns),
            record_path: record_text(record, encoded),
        }
    )
    return record_path


def record_text(record: dict, encoded: dict[str, str] | None = None) -> str:
    """``json.dumps(record, indent=2, sort_keys=True)`` and a newline, byte for byte, with the values of
    the keys in ``encoded`` taken from their given top-level encoding: a value one level down is that
    text with two spaces after each newline (JSON strings hold no raw newline)."""
    if not encoded:
        return json.dumps(record, indent=2, sort_keys=True, default=json_default) + "\n"
    marks = {k: f"\x00encoded {k}\x00" for k in encoded if k in record}
    text = json.dumps({**record, **marks}, indent=2, sort_keys=True, default=json_default)
    for k, mark in marks.items():
        text = text.replace(json.dumps(mark), encoded[k].replace("\n", "\n  "), 1)
    return text + "\n"


def json_default(o):
    """``default`` for :func:`json.dumps` of a record: arrays → lists, numpy scalars → numbers, paths → text.

    Raises
    ------
    TypeError
        For any other object (as :func:`json.dumps` expects).
    """
    if isinstance(o, np.ndarray):
        return o.tolist()
    if isinstance(o, (np.integer, np.floating)):
        return o.item()
    if isinstance(o, Path):
        return str(o)
    raise TypeError(f"not JSON serialisable: {type(o).__name__}")


def format_table(rows: list[Reading], max_rows: int = 30, photometric_first: bool = False) -> str:
    """A terminal table: one line per sensor (grids summarised past ``max_rows``).

    ``photometric_first`` (a run whose ``light_units`` are photometric): the
    reading, its ± and relative error are the photometric quantity (lx,
    cd/m², lm) and the radiometric twin (W/m², W/m²/sr, W) is the second
    column; otherwise the other way round. The relative error is the same
    either way for a grey scene, the two channels' own for a coloured one.
    """
    second = "radiometric" if photometric_first else "photometric"
    lines = [f"{'sensor':<24} {'kind':<10} {'reading':>14} {'± stderr':>12} {'rel':>7}  {second:>14}  {'samples':>8}"]
    shown = rows if len(rows) <= max_rows else [r for r in rows if r.sensor.grid is None][:max_rows]
    for r in shown:
        v = r.values
        g = r.sensor.spec.columns[r.sensor.spec.headline]  # a probe's: scalar irradiance (fluence rate)
        first, twin = ((2, 3, g.photometric_unit), (0, g.unit)) if photometric_first else ((0, 1, g.unit), (2, g.photometric_unit))
        val, err, unit = v[g.columns[first[0]]], v[g.columns[first[1]]], first[2]
        ph, phu = v[g.columns[twin[0]]], twin[1]
        rel = f"{100 * err / abs(val):.2f}%" if val else "-"
        lines.append(
            f"{r.sensor.name[:24]:<24} {r.sensor.spec.name:<10} {val:>9.4g} {unit:<4} {err:>12.3g} {rel:>7}  {ph:>9.4g} {phu:<5} {r.samples:>8}"
        )
    grids: dict[str, list[Reading]] = {}
    for r in rows:
        if r.sensor.grid is not None:
            grids.setdefault(r.sensor.grid, []).append(r)
    if len(rows) > max_rows:
        for name, g in grids.items():
            lx = np.array([r.values["illuminance_lx"] for r in g])
            w = np.array([r.values["irradiance_W_m2"] for r in g])
            radiometric = f"irradiance min/mean/max {w.min():.4g}/{w.mean():.4g}/{w.max():.4g} W/m²"
            photometric = f"illuminance {lx.min():.4g}/{lx.mean():.4g}/{lx.max():.4g} lx"
            if photometric_first:
                photometric = photometric.replace("illuminance ", "illuminance min/mean/max ")
                radiometric = radiometric.replace("irradiance min/mean/max ", "irradiance ")
            pair = (photometric, radiometric) if photometric_first else (radiometric, photometric)
            lines.append(f"grid {name}: {len(g)} sensors, {pair[0]}, {pair[1]}, "
                         f"uniformity (min/mean) {lx.min() / lx.mean() if lx.mean() else 0:.3f}")
    return "\n".join(lines)
