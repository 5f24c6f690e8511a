"""The annual outputs: hourly series (hour × sensor), zone metrics, control figures, and the JSON record.

``annual_hourly.csv`` and ``annual_hourly_stderr.csv``: one row per analysed
hour (its end and centre, local standard time; the sun; the hour's diffuse,
direct-normal and built global horizontal illuminance; whether occupied),
then one column per sensor (lux; cd/m² for a photosensor cone). The CSVs
hold only numbers that follow from the study file, the stage and the
weather file, so they are byte-identical across in-process, cluster and
resumed runs; times go to ``annual.json``.
"""

from __future__ import annotations

import csv
import io
import json
import math
from pathlib import Path

import numpy as np

from simulator.io.results import json_default
from simulator.study.trace.chunks import atomic_write
from simulator.study.annual.metrics import METRICS

__all__ = ["write_annual_outputs", "annual_note", "HOUR_COLUMNS"]

HOUR_COLUMNS = ("hour_end", "hour_centre", "sun_azimuth_deg", "sun_elevation_deg", "diffuse_horizontal_lx", "direct_normal_lx",
                "global_horizontal_lx", "occupied")  # fmt: skip


def _f(x) -> str:
    x = float(x)
    return "nan" if math.isnan(x) else f"{x:.6g}"


def hourly_csv(res, values: np.ndarray) -> str:
    buf = io.StringIO()
    w = csv.writer(buf, lineterminator="\n")
    w.writerow(HOUR_COLUMNS + tuple(c.sensor.name for c in res.sensors))
    wt = res.weather
    for k, r in enumerate(res.rows):
        w.writerow([wt.end[r].isoformat(), wt.centre[r].isoformat(), _f(wt.sun_azimuth_deg[r]), _f(wt.sun_elevation_deg[r]),
                    _f(res.skies.dhi_lx[k]), _f(res.skies.dni_lx[k]), _f(res.skies.global_lx[k]), int(res.occupied[k]),
                    *(_f(v) for v in values[k])])  # fmt: skip
    return buf.getvalue()


def metrics_csv(res) -> str:
    buf = io.StringIO()
    w = csv.writer(buf, lineterminator="\n")
    w.writerow(("zone", "metric", "value", "stderr", "unit", "definition"))
    for z, m in res.metrics.items():
        for k, (unit, what) in METRICS.items():
            v, se = m[k]
            w.writerow((z, k, _f(v), _f(se), unit, what))
    return buf.getvalue()


def control_csv(res) -> str:
    buf = io.StringIO()
    w = csv.writer(buf, lineterminator="\n")
    device = _device_columns(res)
    w.writerow(("zone", "model", "groups", "target_lx", "lamps_zone_lx", "photosensor", "relative_energy", "relative_energy_stderr",
                "hours_below_target", "hours_below_target_stderr", "score", "score_stderr", "chosen") + device)  # fmt: skip
    for c in res.controls:
        for row in c["candidates"]:
            w.writerow((c["zone"], c["model"], ";".join(c["groups"]), _f(c["target_lx"]), _f(c["lamps_zone_lx"]), row["photosensor"],
                        _f(row["relative_energy"]), _f(row["relative_energy_stderr"]), _f(row["hours_below"]),
                        _f(row["hours_below_stderr"]), _f(row["score"]), _f(row["score_stderr"]),
                        int(row["photosensor"] == c["chosen"])) + tuple(_f(row[k]) if k in row else "" for k in device))  # fmt: skip
    return buf.getvalue()


def _device_columns(res) -> tuple[str, ...]:
    """The columns of photosensors read through a sensor model's electronics (none where no candidate is one)."""
    keys = ("hours_saturated", "hours_saturated_stderr")
    return keys if any(keys[0] in r for c in res.controls for r in c["candidates"]) else ()


def record(res, study) -> dict:
    return {
        "annual": study.annual.model_dump(mode="json"),
        "weather": {"path": res.weather.path, "site": res.weather.site, "latitude_deg": res.weather.latitude_deg,
                    "longitude_deg": res.weather.longitude_deg, "tz_h": res.weather.tz_h, "rows": len(res.weather)},  # fmt: skip
        "hours": {"analysed": int(len(res.rows)), "occupied": int(res.occupied.sum()), "daylight": int(res.daylight.sum())},
        "notes": res.notes,
        "metrics": {z: {k: {"value": v, "stderr": se} for k, (v, se) in m.items()} for z, m in res.metrics.items()},
        "controls": [{k: v for k, v in c.items() if k != "level"} for c in res.controls],
        "chunks": {"total": res.chunks_total, "computed": res.chunks_computed},
        "timings_s": res.timings_s,
        "cpu_s": res.cpu_s,
        "method": "sky: Perez all-weather over Tregenza patches, direct and interreflected daylight coefficients traced once; "
                  "sun: direct light exact by shadow rays per hour, interreflected light from the indirect coefficients of the "
                  "patches nearest the sun; errors: hourly from the covariance, metrics from replicate years",
        **({"sensor_models": res.sensor_models} if getattr(res, "sensor_models", None) else {}),
    }  # fmt: skip


def write_annual_outputs(res, study, out_dir: Path, path: Path | None = None) -> list[Path]:
    """Write the annual CSVs and ``annual.json`` into ``out_dir``; returns the paths. With ``path`` (the
    study file of a study with no scenarios) also ``report.html``, the annual section alone."""
    files = {
        out_dir / "annual_hourly.csv": hourly_csv(res, res.mean).encode(),
        out_dir / "annual_hourly_stderr.csv": hourly_csv(res, res.stderr).encode(),
        out_dir / "annual_metrics.csv": metrics_csv(res).encode(),
    }
    if res.controls:
        files[out_dir / "annual_control.csv"] = control_csv(res).encode()
    if path is not None:
        from simulator.study.annual.report import annual_page

        files[out_dir / "report.html"] = annual_page(res, path, study).encode()
    files[out_dir / "annual.json"] = (json.dumps(record(res, study), indent=1, default=json_default) + "\n").encode()
    for p, data in files.items():
        atomic_write(p, data)
    return list(files)


def annual_note(res) -> list[str]:
    """Closing lines: hours, time, each zone's headline metrics, each control's choice."""
    t, c = res.timings_s, res.cpu_s
    lines = [f"annual: {len(res.rows)} hours ({int(res.occupied.sum())} occupied, {int(res.daylight.sum())} with the sun up), "
             f"{res.chunks_total} chunks ({res.chunks_computed} computed); wall {t['total']:.1f} s, CPU {c['total']:.1f} s "
             f"(tracing {c['trace_in_chunks']:.1f} s, sun shadow rays {c['sun_shadow_rays']:.1f} s)"]  # fmt: skip
    for z, m in res.metrics.items():
        def g(k):
            return f"{m[k][0]:.1f} ± {m[k][1]:.1f}"

        lines.append(f"  {z}: sDA300/50% {g('sDA')}%, ASE1000/250h {g('ASE')}%, DA300 {g('DA')}%, UDI <100/useful/>2000 "
                     f"{m['UDI_fell_short'][0]:.0f}/{m['UDI_useful'][0]:.0f}/{m['UDI_exceeded'][0]:.0f}%, "
                     f"EN 17037 {'meets' if m['EN17037_pass'][0] else 'misses'} the minimum level ({g('EN17037_target')}% / "
                     f"{g('EN17037_minimum')}% of daylight hours), DF {m['DF'][0]:.2f} ± {m['DF'][1]:.2f}%")  # fmt: skip
    for ctl in res.controls:
        best = next(r for r in ctl["candidates"] if r["photosensor"] == ctl["chosen"])
        sep = "" if ctl["separable"] else f" (not separable from {ctl['runner_up']})"
        lines.append(f"  control {ctl['zone']} ({ctl['model']}, {ctl['target_lx']:g} lx): photosensor {ctl['chosen']}{sep}, "
                     f"relative energy {best['relative_energy']:.3f} ± {best['relative_energy_stderr']:.3f}, "
                     f"{best['hours_below']:.0f} ± {best['hours_below_stderr']:.0f} of {ctl['occupied_hours']} hours below target")  # fmt: skip
    return lines
