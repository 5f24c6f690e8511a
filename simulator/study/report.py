"""A study's outputs: long CSV, summary CSV, heat maps per zone (PNG) and the JSON record.

The CSVs hold only numbers that follow from the study file and the stage
(readings, figures, the chosen set), so they are byte-identical whether the
chunks ran in this process, on a cluster, or over an interrupted run and
its resume; wall-clock figures, hosts and workers go to the JSON record.
"""

from __future__ import annotations

import csv
import io
import json
import math
import platform
from pathlib import Path

import numpy as np

from simulator.io.results import json_default, readings_from
from simulator.scene.model import SENSOR_SPECS
from simulator.study.chunks import atomic_write
from simulator.study.objectives import TARGET_FIGURES, calibrated_errors

__all__ = ["write_outputs", "long_columns", "summary_columns", "value_columns", "score_text", "MAX_PANELS"]

#: columns every readings row starts with; the value columns are ``run``'s
#: (:data:`simulator.io.results.COLUMNS`) for the kinds the study holds, then
#: ``samples``, ``method`` and one ``level_<group>`` column per light group
LONG_LEAD = ("scenario", "sensor", "candidates", "kind", "x", "y", "z", "dx", "dy", "dz")
LONG_TAIL = ("samples", "method")
SUMMARY_LEAD = ("zone", "scenario", "sensors", "unit", "min", "min_stderr", "mean", "mean_stderr", "max", "max_stderr",
                "u0", "u0_stderr", "min_max", "min_max_stderr")  # fmt: skip
SUMMARY_TAIL = ("chosen_set", "predictor", "predicted_mean", "prediction_rel_error")
#: most scenario panels in one zone's heat map
MAX_PANELS = 16


def _f(x) -> str:
    if x is None:
        return ""
    if isinstance(x, (float, np.floating)):
        return "nan" if math.isnan(x) else f"{float(x):.9g}"
    return str(x)


def value_columns(res) -> list[str]:
    """``run``'s value columns of the sensor kinds in the study, in kind order."""
    kinds = sorted({int(c.sensor.kind) for c in res.candidates})
    out: list[str] = []
    for k in kinds:
        for group in SENSOR_SPECS[k].columns:
            out += [c for c in group.columns if c not in out]
    return out


def group_names(res) -> list[str]:
    """The study's light groups, in file order."""
    return [g.name for g in res.study.group]


def long_columns(res) -> list[str]:
    return [*LONG_LEAD, *value_columns(res), *LONG_TAIL, *(f"level_{g}" for g in group_names(res))]


def long_csv(res) -> str:
    """One row per (scenario, candidate): ``run``'s columns and units, the pass's samples and method, the scenario's levels."""
    buf = io.StringIO()
    w = csv.writer(buf, lineterminator="\n")
    cols = value_columns(res)
    groups = group_names(res)
    w.writerow(long_columns(res))
    for j, sc in enumerate(res.scenarios):
        levels = [_f(float(sc.levels.get(g, 0.0))) for g in groups]
        rows = readings_from([c.sensor for c in res.candidates], res.mean[j], res.stderr[j], res.samples[j],
                             np.zeros(len(res.candidates)), res.methods[j], None)  # fmt: skip
        for c, r in zip(res.candidates, rows):
            s = c.sensor
            w.writerow([sc.name, s.name, c.set_name, s.spec.name, *(_f(float(v)) for v in s.position),
                        *(_f(float(v)) for v in s.normal), *(_f(r.values.get(k)) for k in cols), r.samples, r.method, *levels])  # fmt: skip
    return buf.getvalue()


def target_keys(res) -> list[str]:
    """Every target any zone sets, in ``TARGET_FIGURES`` order."""
    used = {k for z in res.study.zone for k in z.targets}
    return [k for k in TARGET_FIGURES if k in used]


def summary_columns(res) -> list[str]:
    per = [c for k in target_keys(res) for c in (f"{k}_required", f"{k}_verdict")]
    return [*SUMMARY_LEAD, *per, *SUMMARY_TAIL]


def placement_unit(objective: str) -> str:
    """How a placement score reads: a correlation, or a relative error in percent."""
    return "correlation" if objective == "correlation" else "%"


def score_value(objective: str, v: float) -> float:
    """A placement score (or gain) as reported: correlations as they are, relative errors × 100 (percent)."""
    return float(v) if objective == "correlation" else 100.0 * float(v)


def score_text(objective: str, v: float, se: float) -> str:
    """``0.9731 ± 0.0040`` for a correlation, ``4.21% ± 0.35%`` for a relative error."""
    if objective == "correlation":
        return f"{v:.4f} ± {se:.4f}"
    return f"{100 * v:.2f}% ± {100 * se:.2f}%"


PLACEMENT_COLUMNS = ("k", "sensor", "candidates", "x", "y", "z", "gain", "gain_stderr", "score", "score_stderr", "unit",
                     "runner_up", "lead", "lead_stderr", "separable")  # fmt: skip


def placement_csv(res) -> str:
    """The greedy picks, scores in percent for the relative-error objectives (a bare fraction misleads)."""
    pl = res.placement
    buf = io.StringIO()
    w = csv.writer(buf, lineterminator="\n")
    w.writerow(PLACEMENT_COLUMNS)
    by = {c.sensor.name: c for c in res.candidates}
    sv = lambda v: _f(score_value(pl.objective, v))  # noqa: E731
    for s in pl.steps:
        c = by[s.sensor]
        w.writerow([s.k, s.sensor, c.set_name, *(_f(float(v)) for v in c.position), sv(s.gain), sv(s.gain_se), sv(s.score),
                    sv(s.score_se), placement_unit(pl.objective), s.runner_up or "", sv(s.lead), sv(s.lead_se),
                    "yes" if s.separable else "no"])  # fmt: skip
    return buf.getvalue()


def areas_csv(res) -> str:
    """One row per (EN 12464-1 area, part, scenario): maintained figures, requirements and verdicts."""
    from simulator.study.areas import AREA_COLUMNS

    buf = io.StringIO()
    w = csv.writer(buf, lineterminator="\n")
    w.writerow(AREA_COLUMNS)
    unit = "lx" if res.study.light_units == "photometric" else "W/m2"
    mfs = {a.name: a.maintenance_factor for a in res.study.area}
    for r in res.areas:
        f = r.figures
        vals = ["", "", "", "", "", ""] if f is None else [_f(v) for v in (f.mean, f.mean_se, f.min, f.min_se, f.u0, f.u0_se)]
        m = ("", "") if r.modelling is None else (_f(r.modelling[0]), _f(r.modelling[1]))
        w.writerow([r.area, r.part, r.scenario, r.sensors, unit, _f(mfs[r.area]), *vals, _f(float(r.required_mean)),
                    _f(float(r.required_u0)), r.verdicts["mean"], r.verdicts["u0"], *m, r.modelling_verdict])  # fmt: skip
    return buf.getvalue()


def _predictions(res) -> dict:
    """(zone, scenario) -> (predictor, predicted zone mean, relative error) from the chosen set."""
    pl = res.placement
    if pl is None:
        return {}
    ch = 1 if res.study.light_units == "photometric" else 0
    index = {c.sensor.name: i for i, c in enumerate(res.candidates)}
    out = {}
    for z, sensor in pl.assignment.items():
        t = np.array([res.figures[(z, sc.name)].mean for sc in res.scenarios])
        r = res.mean[:, index[sensor], ch]
        _, rel = calibrated_errors(r[None, :], t)
        dr, dt = r - r.mean(), t - t.mean()
        sxx = float(np.sum(dr * dr))
        a = float(np.sum(dr * dt)) / sxx if sxx > 0 else 0.0
        pred = t.mean() + a * dr
        for j, sc in enumerate(res.scenarios):
            out[(z, sc.name)] = (sensor, pred[j], rel[0, j])
    return out


def summary_csv(res) -> str:
    """One row per (zone, scenario): the figures with their errors, then per target its required value and verdict."""
    buf = io.StringIO()
    w = csv.writer(buf, lineterminator="\n")
    w.writerow(summary_columns(res))
    preds = _predictions(res)
    chosen = ";".join(res.placement.chosen) if res.placement else ""
    unit = "lx" if res.study.light_units == "photometric" else "W/m2"
    keys = target_keys(res)
    for z in res.study.zone:
        for sc in res.scenarios:
            f = res.figures[(z.name, sc.name)]
            chk = res.checks[(z.name, sc.name)]
            per = [x for k in keys for x in ((_f(float(z.targets[k])), chk[k]) if k in z.targets else ("", ""))]
            p = preds.get((z.name, sc.name), ("", None, None))
            w.writerow([z.name, sc.name, len(res.zones[z.name]), unit, *(_f(getattr(f, a)) for a in
                        ("min", "min_se", "mean", "mean_se", "max", "max_se", "u0", "u0_se", "min_max", "min_max_se")),
                        *per, chosen, p[0], _f(p[1]), _f(p[2])])  # fmt: skip
    return buf.getvalue()


def _raster(xy: np.ndarray, v: np.ndarray):
    """``(image, extent)`` of values on a regular grid of points, or None when the points are not one."""
    xs, ys = np.unique(np.round(xy[:, 0], 6)), np.unique(np.round(xy[:, 1], 6))
    if len(xs) < 2 or len(ys) < 2:
        return None
    dx, dy = np.diff(xs), np.diff(ys)
    if np.ptp(dx) > 1e-6 or np.ptp(dy) > 1e-6:
        return None
    img = np.full((len(ys), len(xs)), np.nan)
    ix = np.searchsorted(xs, np.round(xy[:, 0], 6))
    iy = np.searchsorted(ys, np.round(xy[:, 1], 6))
    img[iy, ix] = v
    ext = (xs[0] - dx[0] / 2, xs[-1] + dx[0] / 2, ys[0] - dy[0] / 2, ys[-1] + dy[0] / 2)
    return img, ext


def zone_plan(res, zone: str):
    """The room's plan around a zone (:func:`simulator.study.outline.plan_of_zone`), or None
    (no stage scene kept, a zone that is not horizontal, no prims of its own)."""
    from simulator.study.outline import plan_of_zone

    scene = getattr(res, "scene", None)
    ids = res.zones[zone]
    cands = [res.candidates[i] for i in ids]
    def facing(sn):  # a cylinder's axis; a plane receiver's normal
        return sn.up if sn.spec.name in ("cylindrical", "semicylindrical") else sn.normal

    if scene is None or not all(abs(abs(float(facing(c.sensor)[2])) - 1.0) < 1e-6 for c in cands):
        return None
    prims = sorted({c.prim for c in cands if c.prim})
    if not prims:
        return None
    return plan_of_zone(scene, prims, float(np.median([c.position[2] for c in cands])))


def dropped_in_zone(res, zone: str) -> np.ndarray:
    """Positions (N, 3) of the zone's set's points dropped inside furniture, within the zone's region."""
    z = next(z for z in res.study.zone if z.name == zone)
    cs = next(s for s in res.sets if s.name == z.candidates)
    pts = [p for p in getattr(cs, "dropped_points", [])
           if z.region is None or (z.region[0] <= p[0] <= z.region[2] and z.region[1] <= p[1] <= z.region[3])]  # fmt: skip
    return np.array(pts).reshape(-1, 3)


def draw_plan(ax, plan) -> None:
    """The room's walls (dark grey), openings (blue) and furniture (brown) of a :class:`~simulator.study.outline.Plan`
    on a plan axis (x, y in metres); nothing when ``plan`` is None."""
    if plan is None:
        return
    for seg in plan.walls:
        ax.plot(seg[:, 0], seg[:, 1], color="0.25", lw=1.6, solid_capstyle="butt")
    for line in plan.openings:
        ax.plot(line[:, 0], line[:, 1], color="tab:blue", lw=2.2)
    for line in plan.furniture:
        ax.plot(line[:, 0], line[:, 1], color="saddlebrown", lw=0.8)


def heat_map_png(res, zone: str) -> bytes:
    """PNG of one zone's readings, a panel per scenario (up to :data:`MAX_PANELS`).

    Each panel has its own colour scale (``[output] heat_map_scale =
    "per_scenario"``, the default: an evening at 50 lx and a sunny
    afternoon at 5,000 lx both show their pattern) or all share one
    logarithmic scale (``"log"``); world x and y in metres on the axes; the
    room's walls (dark grey), openings (blue) and furniture (brown) of
    :func:`zone_plan`; the chosen sensors (red ×) and the points dropped
    inside furniture (grey +)."""
    from matplotlib.colors import LogNorm, Normalize
    from matplotlib.figure import Figure

    ch = 1 if res.study.light_units == "photometric" else 0
    ids = res.zones[zone]
    xy = np.array([res.candidates[i].position[:2] for i in ids])
    scen = res.scenarios[:MAX_PANELS]
    vals = res.mean[: len(scen), ids, ch]
    log = getattr(res.study.output, "heat_map_scale", "per_scenario") == "log"
    ncol = min(4, len(scen))
    nrow = math.ceil(len(scen) / ncol)
    fig = Figure(figsize=(3.0 * ncol + (1.2 if log else 0.3), 2.5 * nrow + 1.0), dpi=80)
    fig.subplots_adjust(left=0.06, right=0.86 if log else 0.95, bottom=0.1, top=1.0 - 0.95 / (2.5 * nrow + 1.0), wspace=0.55, hspace=0.75)
    axes = fig.subplots(nrow, ncol, squeeze=False)
    pos_vals = vals[vals > 0]
    shared = None
    if log and pos_vals.size:
        shared = LogNorm(vmin=float(pos_vals.min()), vmax=float(pos_vals.max()) if pos_vals.max() > pos_vals.min() else float(pos_vals.min()) * 10)
    chosen = [] if res.placement is None else res.placement.chosen
    index = {c.sensor.name: c for c in res.candidates}
    plan = zone_plan(res, zone)
    dropped = dropped_in_zone(res, zone)
    lo, hi = xy.min(axis=0), xy.max(axis=0)
    unit = "lx" if ch == 1 else "W/m²"
    im = None
    for k, ax in enumerate(axes.flat):
        if k >= len(scen):
            ax.set_visible(False)
            continue
        v = vals[k]
        if shared is not None:
            norm = shared
        else:
            vmax = float(v.max()) if v.size and v.max() > 0 else 1.0
            norm = Normalize(vmin=min(0.0, float(v.min())), vmax=vmax)
        r = _raster(xy, v)
        if r is not None:
            im = ax.imshow(np.where(r[0] > 0, r[0], np.nan) if shared is not None else r[0], origin="lower", extent=r[1],
                           cmap="viridis", norm=norm, interpolation="nearest")  # fmt: skip
        else:
            im = ax.scatter(xy[:, 0], xy[:, 1], c=v, cmap="viridis", norm=norm, marker="s", s=30, linewidths=0)
        draw_plan(ax, plan)
        if len(dropped):
            ax.plot(dropped[:, 0], dropped[:, 1], "+", color="0.5", markersize=5, mew=1)
        for name in chosen:
            p = index[name].position
            if lo[0] - 1 <= p[0] <= hi[0] + 1 and lo[1] - 1 <= p[1] <= hi[1] + 1:
                ax.plot(p[0], p[1], marker="x", color="red", markersize=7, mew=2)
        f = res.figures[(zone, scen[k].name)]
        ax.set_title(f"{scen[k].name}\nmean {f.mean:.0f} {unit}, U0 {f.u0:.2f}", fontsize=6)
        ax.tick_params(labelsize=6)
        ax.set_xlabel("x (m)", fontsize=6)
        ax.set_ylabel("y (m)", fontsize=6)
        ax.set_aspect("equal", adjustable="datalim")
        if shared is None:
            cb = fig.colorbar(im, ax=ax, fraction=0.046, pad=0.04)
            cb.ax.tick_params(labelsize=5)
    if shared is not None and im is not None:
        cax = fig.add_axes((0.89, 0.15, 0.02, 0.65))
        fig.colorbar(im, cax=cax).set_label(f"illuminance ({unit}, log scale)", fontsize=7)
    more = f" (first {MAX_PANELS} of {len(res.scenarios)} scenarios)" if len(res.scenarios) > MAX_PANELS else ""
    scale = "one log scale" if shared is not None else f"each panel its own scale ({unit})"
    key = "x chosen sensors" + (", + dropped inside furniture" if len(dropped) else "")
    if plan is not None:
        key += "; walls grey, openings blue, furniture brown"
    fig.suptitle(f"zone {zone}{more}; {scale}\n{key}", fontsize=7)
    buf = io.BytesIO()
    fig.savefig(buf, format="png", metadata={"Software": None})
    return buf.getvalue()


def record(res, versions: dict) -> dict:
    pl = res.placement
    return {
        "study_path": str(res.path),
        "study": res.study.model_dump(mode="json"),
        "candidates": {s.name: {"kind": s.kind, "points": len(s.candidates), "dropped_inside": s.dropped_inside,
                                "grids": {p: {"n_u": g.n_u, "n_v": g.n_v, "pitch_u_m": g.pitch_u_m, "pitch_v_m": g.pitch_v_m,
                                              "relevant_d_m": g.relevant_d_m, "max_spacing_m": g.max_spacing_m}
                                          for p, g in s.grids.items()}} for s in res.sets},  # fmt: skip
        "scenarios": [{"name": s.name, "levels": {g: v for g, v in s.levels.items() if "/" not in g},  # no sky patches
                       "sun_az_el_deg": s.sun, "variants": dict(s.variants), "notes": list(s.notes),
                       "trace_group": s.trace_key} for s in res.scenarios],  # fmt: skip
        "trace_groups": [{"key": t.key, "light_groups": t.groups, "scenarios": len(t.scenarios)} for t in res.trace_groups],
        "zones": {z: len(ix) for z, ix in res.zones.items()},
        "chunks": {"total": res.chunks_total, "computed": res.chunks_computed, "loaded": res.chunks_loaded,
                   "wall_s": res.chunk_wall_s},  # fmt: skip
        "compute": {"mode": res.mode, "workers": res.workers, "sensor_block": res.sensor_block},
        "timings_s": res.timings_s,
        "cost": cost(res),
        "reference_run": res.reference,
        "group_covariance": "full: the light groups of a trace group are tallied on the same paths in one pass"
                            + ("; a sky split into patches: from batch means (each kernel thread's 32 samples a batch)"
                               if any(g.sky is not None for g in res.study.group) else ""),
        "placement": None if pl is None else {
            "objective": pl.objective, "zones": pl.zones, "candidates": pl.candidates, "scenarios": pl.scenarios,
            "evaluations": pl.evaluations, "replicates": pl.replicates, "assignment": pl.assignment, "baseline_score": pl.baseline,
            "score_unit": "correlation" if pl.objective == "correlation" else "fraction (x 100 in placement.csv, report.html and the closing note: percent)",
            "steps": [{"k": s.k, "sensor": s.sensor, "gain": s.gain, "gain_stderr": s.gain_se, "score": s.score,
                       "score_stderr": s.score_se, "runner_up": s.runner_up, "lead": s.lead, "lead_stderr": s.lead_se,
                       "separable": s.separable} for s in pl.steps],
        },  # fmt: skip
        "warnings": res.warnings,
        "host": {"platform": platform.platform(), "machine": platform.machine()},
        "versions": versions,
        "files": res.files,
    }


def cost(res) -> dict:
    """Tracing cost per scenario against one ordinary run of one scenario."""
    n = max(len(res.scenarios), 1)
    per = res.timings_s.get("trace_in_chunks", 0.0) / n
    ref = (res.reference or {}).get("wall_s")
    ref_cpu = (res.reference or {}).get("cpu_s")
    by_tg = {}
    for tg in res.trace_groups:
        s = sum(v for k, v in res.chunk_trace_s.items() if k[0] == tg.key)
        c = sum(v for k, v in res.chunk_trace_cpu_s.items() if k[0] == tg.key)
        by_tg[tg.key] = {"scenarios": len(tg.scenarios), "light_groups_traced": len(tg.groups), "trace_s": s,
                         "over_single_run": (s / ref) if ref else None, "trace_cpu_s": c,
                         "cpu_over_single_run": (c / ref_cpu) if ref_cpu else None}  # fmt: skip
    r = res.reference or {}
    samples = (r["trace_group_samples"] / r["samples"]) if r.get("samples") else None
    key0 = res.trace_groups[0].key if res.trace_groups else None
    per_sample = (by_tg[key0]["trace_s"] / ref / samples) if (samples and ref and key0 in by_tg) else None
    cpu0 = by_tg[key0]["cpu_over_single_run"] if key0 in by_tg else None
    per_sample_cpu = (cpu0 / samples) if (samples and cpu0) else None
    return {"trace_s_per_scenario": per, "single_run_s": ref, "single_run_cpu_s": ref_cpu, "per_scenario_over_single_run": (per / ref) if ref else None,
            "study_trace_over_single_run": (res.timings_s.get("trace_in_chunks", 0.0) / ref) if ref else None,
            "trace_groups": by_tg, "first_trace_group_samples_over_single_run": samples,
            "first_trace_group_time_per_sample_over_single_run": per_sample,
            "first_trace_group_cpu_per_sample_over_single_run": per_sample_cpu,
            "note": "all light groups of a trace group are traced in one pass (each sample's light tallied per group), "
                    "so a trace group costs about one single run whatever its number of groups and dimming scenarios; "
                    "an adaptive pass stops a sensor when all its scenarios meet the target, so it draws the samples "
                    "of its hardest scenario; the single run is that of the first trace group's scenario, with the most "
                    "groups lit, asking the most samples; kernel loading is left out of both"}  # fmt: skip


def write_outputs(res, versions: dict) -> list[Path]:
    """Write the CSVs, heat maps, report page and record into ``res.out_dir``; returns the paths."""
    import simulator.study.annual_report  # noqa: F401  (registers the annual section; shown when res.annual is set)
    from simulator.study.html_report import report_html

    d = res.out_dir
    files = {d / "readings.csv": long_csv(res).encode(), d / "summary.csv": summary_csv(res).encode()}
    if res.placement is not None:
        files[d / "placement.csv"] = placement_csv(res).encode()
    if getattr(res, "areas", None):
        files[d / "areas.csv"] = areas_csv(res).encode()
    res.heat_map_cache = {}
    for z in res.study.zone:
        png = heat_map_png(res, z.name)
        res.heat_map_cache[z.name] = png
        files[d / f"heatmap_{_safe(z.name)}.png"] = png
    files[d / "report.html"] = report_html(res).encode()
    res.files = sorted(p.name for p in files) + ["study.json"]
    files[d / "study.json"] = (json.dumps(record(res, versions), indent=1, default=json_default) + "\n").encode()
    for p, data in files.items():
        atomic_write(p, data)
    return list(files)


def _safe(name: str) -> str:
    return "".join(ch if ch.isalnum() or ch in "-_." else "_" for ch in name)
