"""A run over several USD time codes (``times = [...]``): one row per sensor and time.

A sensor authored on a prim whose transform has time samples moves along
its path (a robot's sensor, one on a moving luminaire); config sensors stay
where they are. The stage is read at every time code. Time codes at which
everything but the sensors reads the same (geometry, materials, lights:
:func:`scene_key`) are traced together: their sensors, one copy per time,
go to one engine in one run, so the geometry is uploaded once and the
pilots (guide, splits, roulette) serve them all; a time at which the stage
differs gets a trace of its own. Every copy keeps its own random stream
(its index in its trace), so the readings do not depend on how the times
group. The CSV has the column ``time_code`` after the standard ones; the
run record is the first trace's, with ``times`` (the codes, how they were
grouped) and the samples of all. Maps and probes are not read along time.
"""

from __future__ import annotations

import dataclasses
import hashlib

import numpy as np

from simulator.errors import UserError
from simulator.scene.model import SensorKind

__all__ = ["TIME_COLUMN", "scene_key", "run_times"]

#: the CSV column of a reading's time code
TIME_COLUMN = "time_code"
#: what a per-time copy's name adds inside its trace (taken off again in the CSV)
_SEP = "@t="


def scene_key(scene) -> str:
    """A digest of everything but the sensors that a trace reads: the triangles, their materials and
    emission, and every light's kind, placement, emission, size and shaping."""
    h = hashlib.sha256()
    g = scene.geometry
    for a in (g.points, g.triangles, g.albedo, g.emission, g.two_sided):
        h.update(np.ascontiguousarray(a).tobytes())
    for a in (g.surface_id, g.albedo_rgb, g.emission_rgb, g.reflectance_id):
        h.update(b"-" if a is None else np.ascontiguousarray(a).tobytes())
    h.update(repr([dataclasses.astuple(x) if dataclasses.is_dataclass(x) else repr(x) for x in g.surfaces]).encode())
    for light in scene.lights:
        h.update(f"{light.name}|{int(light.kind)}|{light.emission}|{light.width}|{light.height}|{light.radius}|"
                 f"{light.length}|{light.half_angle}|{light.texture}|{light.color}|{light.spectrum}".encode())
        h.update(np.ascontiguousarray(light.position, np.float64).tobytes())
        h.update(np.ascontiguousarray(light.frame, np.float64).tobytes())
        if light.shaping is not None:
            sh = light.shaping
            h.update(repr((sh.cone_angle_rad, sh.cone_softness, sh.focus, sh.focus_tint, sh.ies_scale,
                           sh.absolute, sh.light_loss_factor, id(sh.ies) if sh.ies is not None else None)).encode())
    return h.hexdigest()


def _named(rows) -> list:
    """Rows of a trace of per-time copies under their sensors' own names, with their time code."""
    for r in rows:
        name, code = r.sensor.name.rsplit(_SEP, 1)
        r.sensor = dataclasses.replace(r.sensor, name=name)
        r.values = {**r.values, TIME_COLUMN: float(code)} if r.values else {TIME_COLUMN: float(code)}
    return rows


def run_times(cfg, pipeline, progress=None, log=print, write: bool = True):
    """Read ``cfg``'s sensors at each of ``cfg.times`` (see module docstring); returns the
    :class:`simulator.pipeline.RunOutput` of the whole series. ``pipeline`` is the
    :mod:`simulator.pipeline` module, whose ``run`` calls this (passed, not imported, so the
    two modules do not import each other).

    Raises
    ------
    UserError
        A probe among the sensors (maps are not read along time), or a sensor name used twice at a time.
    """
    from simulator.io.results import write_outputs

    RunOutput, cached_scene, collect_sensors, run = pipeline.RunOutput, pipeline.cached_scene, pipeline.collect_sensors, pipeline.run

    times = list(cfg.times)
    at = [dataclasses.replace(cfg, time=t, times=None) for t in times]
    scenes = [cached_scene(c)[0] for c in at]
    groups: dict[str, list[int]] = {}
    for i, sc in enumerate(scenes):
        groups.setdefault(scene_key(sc), []).append(i)
    rows, records = [], []
    for members in groups.values():
        sensors = []
        for i in members:
            for s in collect_sensors(at[i], scenes[i]):
                if s.kind == SensorKind.PROBE:
                    raise UserError(f"{cfg.path}: times: probe {s.name!r} is not read along time (maps are one time's)")
                sensors.append(dataclasses.replace(s, name=f"{s.name}{_SEP}{times[i]!r}"))
        out = run(at[members[0]], progress, log, write=False, sensors=sensors)
        if out.interrupted:  # Ctrl-C: what was read so far, and no further trace
            records.append((members, out.record))
            rows += _named(out.rows)
            break
        rows += _named(out.rows)
        records.append((members, out.record))
    order = {t: k for k, t in enumerate(times)}
    rows.sort(key=lambda r: order[r.values[TIME_COLUMN]])  # stable: each time's rows in sensor order
    record = dict(records[0][1])
    record["samples_total"] = sum(r["samples_total"] for _, r in records)
    record["sensors"] = len(rows)
    record["sensors_read"] = sum(1 for r in rows if r.values)
    record["times"] = {"codes": times, "traces": [[times[i] for i in m] for m, _ in records],
                       "note": "times in one trace share the stage's reading but their sensors'; maps and probes "
                               "are not written along time"}
    record["interrupted"] = any(r["interrupted"] for _, r in records)
    if not write:
        return RunOutput(rows, None, None, record, scenes[0], record["interrupted"])
    record_path = write_outputs(cfg.output.csv, rows, record, csv_columns=cfg.output.csv_columns)
    return RunOutput(rows, cfg.output.csv, record_path, record, scenes[0], record["interrupted"])
