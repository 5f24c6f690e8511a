"""The annual outputs: hourly series (hour × sensor), zone metrics, control figures, and the JSON record.

``annual_hourly.csv`` and ``annual_hourly_stderr.csv``: one row per analysed
hour (its end and centre, local standard time; the sun; the hour's diffuse,
direct-normal and built global horizontal illuminance; whether occupied),
then one column per sensor (lux; cd/m² for a photosensor cone); with
``[shading]`` then ``state_<variant set>``, the state the rule chose that
hour, and with glare views ``<view>:ev_lx`` and ``<view>:dgp`` (or
``:dgps``) per view (the stderr file: their standard errors). The sensor
columns hold the chosen states' readings.

``annual_metrics.csv``: per zone the metrics of
:data:`simulator.study.annual.metrics.METRICS`, then the rows beyond them
(:data:`EXTRA_METRICS`): with ``[shading]`` per zone ``DA_open`` and
``sDA_open`` (the shades in their first state all year) and
``ASE_operated``, the window group's ``hours_<state>``; per glare view the
rows of :data:`simulator.study.annual.glare.GLARE_METRICS` (and
``GA_open``), its name in the ``zone`` column.

The CSVs hold only numbers that follow from the study file, the stage and
the weather file, so they are byte-identical across in-process, cluster and
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
from simulator.io.atomic import write_atomic
from simulator.study.annual.metrics import METRICS

__all__ = ["write_annual_outputs", "annual_note", "HOUR_COLUMNS", "EXTRA_METRICS"]

HOUR_COLUMNS = ("hour_end", "hour_centre", "sun_azimuth_deg", "sun_elevation_deg", "diffuse_horizontal_lx", "direct_normal_lx",
                "global_horizontal_lx", "occupied")  # fmt: skip


def _f(x) -> str:
    x = float(x)
    return "nan" if math.isnan(x) else f"{x:.6g}"


#: the definitions of a year with [shading] where they differ from a plain year's (METRICS)
SHADED_DEFINITIONS = {
    "sDA": "share of sensors with DA >= 50% (LM-83-12, with operable shading: the shades as the rule operated them)",
    "ASE": "share of sensors with direct sun >= ase_lx for more than ase_hours occupied hours (shades in their first state)",
}

#: rows of annual_metrics.csv beyond a plain year's: key -> (unit, definition)
EXTRA_METRICS = {
    "DA_open": ("%", "DA with the shades in their first state all year (no operation)"),
    "sDA_open": ("%", "sDA with the shades in their first state all year (LM-83-12 sDA without operable shading)"),
    "ASE_operated": ("%", "ASE with the shades as the rule operated them"),
    "hours": ("h", "occupied hours in this state"),
    "GA_open": ("%", "glare autonomy with the shades in their first state all year"),
}


def extra_definition(key: str) -> tuple[str, str]:
    """(unit, definition) of an extra row's metric key."""
    from simulator.study.annual.glare import GLARE_METRICS

    if key.startswith("hours_") and key not in GLARE_METRICS:
        return EXTRA_METRICS["hours"][0], f"occupied hours with the shades {key[6:]!r} (the rule's choice)"
    return {**GLARE_METRICS, **EXTRA_METRICS}[key]


def hourly_csv(res, values: np.ndarray, stderr: bool = False) -> str:
    buf = io.StringIO()
    w = csv.writer(buf, lineterminator="\n")
    head = HOUR_COLUMNS + tuple(c.sensor.name for c in res.sensors)
    sh, g = getattr(res, "shading", None), getattr(res, "glare", None)
    if sh is not None:
        head += (f"state_{sh.variant_set}",)
    if g is not None:
        head += tuple(f"{v}:{c}" for v in g.views for c in ("ev_lx", g.index_name))
    w.writerow(head)
    wt = res.weather
    for k, r in enumerate(res.rows):
        row = [wt.end[r].isoformat(), wt.centre[r].isoformat(), _f(wt.sun_azimuth_deg[r]), _f(wt.sun_elevation_deg[r]),
               _f(res.skies.dhi_lx[k]), _f(res.skies.dni_lx[k]), _f(res.skies.global_lx[k]), int(res.occupied[k]),
               *(_f(v) for v in values[k])]  # fmt: skip
        if sh is not None:
            row.append(res.states[int(res.state[k])])
        if g is not None:
            ev, ix = (g.ev_se, g.index_se) if stderr else (g.ev, g.index)
            for v in range(len(g.views)):
                row += [_f(ev[k, v]), _f(ix[k, v])]
        w.writerow(row)
    return buf.getvalue()


def metrics_csv(res) -> str:
    buf = io.StringIO()
    w = csv.writer(buf, lineterminator="\n")
    w.writerow(("zone", "metric", "value", "stderr", "unit", "definition"))
    shaded = getattr(res, "shading", None) is not None
    for z, m in res.metrics.items():
        for k, (unit, what) in METRICS.items():
            v, se = m[k]
            if shaded and k in SHADED_DEFINITIONS:
                what = SHADED_DEFINITIONS[k]
            w.writerow((z, k, _f(v), _f(se), unit, what))
    for (z, k), (v, se) in getattr(res, "extra", {}).items():
        unit, what = extra_definition(k)
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
        "traces": res.traces,
        **({"shading": {**res.shading.model_dump(mode="json"), "hours": {k[1][6:]: {"value": v, "stderr": se} for k, (v, se)
                                                                         in res.extra.items() if k[0] == res.shading.variant_set}}}
           if getattr(res, "shading", None) is not None else {}),
        **({"glare": {"index": res.glare.index_name, "views": {n: {k[1]: {"value": v, "stderr": se} for k, (v, se) in res.extra.items()
                                                                 if k[0] == n} for n in res.glare.views},
                      "method": "imageless: sky, ground, shades and sun seen directly are the sources (host rays on a 256 x 256 "
                                "half map), E_v adds the interreflected light traced once per state at each eye"}}
           if getattr(res, "glare", None) is not None else {}),
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
        out_dir / "annual_hourly_stderr.csv": hourly_csv(res, res.stderr, stderr=True).encode(),
        out_dir / "annual_metrics.csv": metrics_csv(res).encode(),
    }
    if res.controls:
        files[out_dir / "annual_control.csv"] = control_csv(res).encode()
    if path is not None:
        from simulator.study.annual.report import annual_page

        files[out_dir / "report.html"] = annual_page(res, path, study).encode()
    files[out_dir / "annual.json"] = (json.dumps(record(res, study), indent=1, default=json_default) + "\n").encode()
    for p, data in files.items():
        write_atomic(p, data, durable=True)
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
    x = getattr(res, "extra", {})
    sh = getattr(res, "shading", None)
    if sh is not None:
        hrs = ", ".join(f"{st} {x[(sh.variant_set, f'hours_{st}')][0]:.0f} ± {x[(sh.variant_set, f'hours_{st}')][1]:.0f} h"
                        for st in res.states)  # fmt: skip
        lines.append(f"  shading {sh.variant_set} ({sh.rule}): {hrs} of {int(res.occupied.sum())} occupied hours")
        for z in res.metrics:
            lines.append(f"  {z}: sDA300/50% {res.metrics[z]['sDA'][0]:.1f} ± {res.metrics[z]['sDA'][1]:.1f}% with operable shading, "
                         f"{x[(z, 'sDA_open')][0]:.1f} ± {x[(z, 'sDA_open')][1]:.1f}% without; ASE with the shades operated "
                         f"{x[(z, 'ASE_operated')][0]:.1f}%")  # fmt: skip
    g = getattr(res, "glare", None)
    if g is not None:
        from simulator.study.annual.glare import EN17037_LEVELS

        level = {code: name for code, name, _ in EN17037_LEVELS}
        for v in g.views:
            ga, h35, h40, h45, en = (x[(v, k)] for k in ("GA", "hours_above_0.35", "hours_above_0.40", "hours_above_0.45", "EN17037_glare"))
            opened = f" ({x[(v, 'GA_open')][0]:.1f}% with the shades open)" if (v, "GA_open") in x else ""
            lines.append(f"  glare {v} ({g.index_name.upper()}): glare autonomy {ga[0]:.1f} ± {ga[1]:.1f}%{opened}, hours above "
                         f"0.35/0.40/0.45 {h35[0]:.0f}/{h40[0]:.0f}/{h45[0]:.0f}, EN 17037 protection from glare "
                         f"{level.get(int(en[0]), 'not met')}")  # fmt: skip
    for ctl in res.controls:
        best = next(r for r in ctl["candidates"] if r["photosensor"] == ctl["chosen"])
        sep = "" if ctl["separable"] else f" (not separable from {ctl['runner_up']})"
        lines.append(f"  control {ctl['zone']} ({ctl['model']}, {ctl['target_lx']:g} lx): photosensor {ctl['chosen']}{sep}, "
                     f"relative energy {best['relative_energy']:.3f} ± {best['relative_energy_stderr']:.3f}, "
                     f"{best['hours_below']:.0f} ± {best['hours_below_stderr']:.0f} of {ctl['occupied_hours']} hours below target")  # fmt: skip
    return lines
