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

from simulator.io.results import json_default
from simulator.scene.model import SensorKind
from simulator.study.chunks import atomic_write
from simulator.study.objectives import TARGET_FIGURES, calibrated_errors

__all__ = ["write_outputs", "LONG_COLUMNS", "SUMMARY_COLUMNS", "MAX_PANELS"]

LONG_COLUMNS = ("scenario", "sensor", "candidates", "kind", "x_m", "y_m", "z_m", "photometric", "photometric_stderr",
                "photometric_unit", "radiometric", "radiometric_stderr", "radiometric_unit")  # fmt: skip
SUMMARY_COLUMNS = ("zone", "scenario", "sensors", "unit", "min", "min_stderr", "mean", "mean_stderr", "max", "max_stderr",
                   "u0", "u0_stderr", "min_max", "min_max_stderr", "targets", "chosen_set", "predictor", "predicted_mean",
                   "prediction_rel_error")  # fmt: skip
#: most scenario panels in one zone's heat map
MAX_PANELS = 16

_UNITS = {SensorKind.IRRADIANCE: ("lx", "W/m2"), SensorKind.RADIANCE: ("cd/m2", "W/(m2 sr)")}


def _f(x) -> str:
    if x is None:
        return ""
    if isinstance(x, (float, np.floating)):
        return "nan" if math.isnan(x) else f"{float(x):.9g}"
    return str(x)


def long_csv(res) -> str:
    buf = io.StringIO()
    w = csv.writer(buf, lineterminator="\n")
    w.writerow(LONG_COLUMNS)
    for j, sc in enumerate(res.scenarios):
        for i, c in enumerate(res.candidates):
            s = c.sensor
            up, ur = _UNITS[s.kind]
            kind = "photosensor" if s.kind == SensorKind.RADIANCE else "irradiance"
            w.writerow([sc.name, s.name, c.set_name, kind, *(_f(v) for v in s.position), _f(res.mean[j, i, 1]), _f(res.stderr[j, i, 1]),
                        up, _f(res.mean[j, i, 0]), _f(res.stderr[j, i, 0]), ur])  # fmt: skip
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
    buf = io.StringIO()
    w = csv.writer(buf, lineterminator="\n")
    w.writerow(SUMMARY_COLUMNS)
    preds = _predictions(res)
    chosen = ";".join(res.placement.chosen) if res.placement else ""
    unit = "lx" if res.study.light_units == "photometric" else "W/m2"
    for z in res.study.zone:
        for sc in res.scenarios:
            f = res.figures[(z.name, sc.name)]
            chk = res.checks[(z.name, sc.name)]
            targets = ";".join(
                f"{k}{'>=' if TARGET_FIGURES[k][1] == 'min' else '<='}{v:g}:{chk[k]}" for k, v in z.targets.items()
            )  # fmt: skip
            p = preds.get((z.name, sc.name), ("", None, None))
            w.writerow([z.name, sc.name, len(res.zones[z.name]), unit, *(_f(getattr(f, a)) for a in
                        ("min", "min_se", "mean", "mean_se", "max", "max_se", "u0", "u0_se", "min_max", "min_max_se")),
                        targets, chosen, p[0], _f(p[1]), _f(p[2])])  # fmt: skip
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


def heat_map_png(res, zone: str) -> bytes:
    """PNG of one zone's readings, a panel per scenario (up to :data:`MAX_PANELS`),
    world x and y in metres on the axes, the chosen sensors marked (×)."""
    from matplotlib.figure import Figure

    ch = 1 if res.study.light_units == "photometric" else 0
    ids = res.zones[zone]
    xy = np.array([res.candidates[i].position[:2] for i in ids])
    scen = res.scenarios[:MAX_PANELS]
    vals = res.mean[: len(scen), ids, ch]
    ncol = min(4, len(scen))
    nrow = math.ceil(len(scen) / ncol)
    fig = Figure(figsize=(2.6 * ncol + 1.2, 2.3 * nrow + 0.5), dpi=80)
    fig.subplots_adjust(left=0.06, right=0.86, bottom=0.08, top=0.9, wspace=0.35, hspace=0.6)
    axes = fig.subplots(nrow, ncol, squeeze=False)
    vmax = float(vals.max()) if vals.size and vals.max() > 0 else 1.0
    chosen = [] if res.placement is None else res.placement.chosen
    index = {c.sensor.name: c for c in res.candidates}
    lo, hi = xy.min(axis=0), xy.max(axis=0)
    im = None
    for k, ax in enumerate(axes.flat):
        if k >= len(scen):
            ax.set_visible(False)
            continue
        r = _raster(xy, vals[k])
        if r is not None:
            im = ax.imshow(r[0], origin="lower", extent=r[1], cmap="viridis", vmin=0.0, vmax=vmax, interpolation="nearest")
        else:
            im = ax.scatter(xy[:, 0], xy[:, 1], c=vals[k], cmap="viridis", vmin=0.0, vmax=vmax, marker="s", s=30, linewidths=0)
        for name in chosen:
            p = index[name].position
            if lo[0] - 1 <= p[0] <= hi[0] + 1 and lo[1] - 1 <= p[1] <= hi[1] + 1:
                ax.plot(p[0], p[1], marker="x", color="red", markersize=7, mew=2)
        f = res.figures[(zone, scen[k].name)]
        ax.set_title(f"{scen[k].name}\nmean {f.mean:.0f}, U0 {f.u0:.2f}", fontsize=6)
        ax.tick_params(labelsize=6)
        ax.set_xlabel("x (m)", fontsize=6)
        ax.set_ylabel("y (m)", fontsize=6)
    unit = "lx" if ch == 1 else "W/m²"
    cax = fig.add_axes((0.89, 0.15, 0.02, 0.7))
    fig.colorbar(im, cax=cax).set_label(f"illuminance ({unit})", fontsize=7)
    more = f" (first {MAX_PANELS} of {len(res.scenarios)} scenarios)" if len(res.scenarios) > MAX_PANELS else ""
    fig.suptitle(f"zone {zone}{more}; x = chosen sensors", fontsize=8)
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
        "compute": {"mode": res.mode, "workers": res.workers},
        "timings_s": res.timings_s,
        "cost": cost(res),
        "reference_run": res.reference,
        "group_covariance": "full: the light groups of a trace group are tallied on the same paths in one pass"
                            + ("; a sky split into patches: from batch means (each kernel thread's 32 samples a batch)"
                               if any(g.sky is not None for g in res.study.group) else ""),
        "placement": None if pl is None else {
            "objective": pl.objective, "zones": pl.zones, "candidates": pl.candidates, "scenarios": pl.scenarios,
            "evaluations": pl.evaluations, "replicates": pl.replicates, "assignment": pl.assignment, "baseline_score": pl.baseline,
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
    """Write the CSVs, heat maps and record into ``res.out_dir``; returns the paths."""
    d = res.out_dir
    files = {d / "readings.csv": long_csv(res).encode(), d / "summary.csv": summary_csv(res).encode()}
    for z in res.study.zone:
        files[d / f"heatmap_{_safe(z.name)}.png"] = heat_map_png(res, z.name)
    res.files = sorted(p.name for p in files) + ["study.json"]
    files[d / "study.json"] = (json.dumps(record(res, versions), indent=1, default=json_default) + "\n").encode()
    for p, data in files.items():
        atomic_write(p, data)
    return list(files)


def _safe(name: str) -> str:
    return "".join(ch if ch.isalnum() or ch in "-_." else "_" for ch in name)
