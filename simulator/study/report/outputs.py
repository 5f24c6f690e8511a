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
from simulator.io.atomic import write_atomic
from simulator.study.report.heat_maps import heat_map_png, zone_plan_pngs
from simulator.study.figures.scores import placement_unit, score_value, target_keys
from simulator.study.figures.objectives import calibrated_errors

__all__ = ["write_outputs", "long_columns", "summary_columns", "value_columns"]

#: columns every readings row starts with; the value columns are ``run``'s
#: (:data:`simulator.io.results.COLUMNS`) for the kinds the study holds, then
#: ``samples``, ``method`` and one ``level_<group>`` column per light group
LONG_LEAD = ("scenario", "sensor", "candidates", "kind", "x", "y", "z", "dx", "dy", "dz")
LONG_TAIL = ("samples", "method")
SUMMARY_LEAD = ("zone", "scenario", "sensors", "unit", "min", "min_stderr", "mean", "mean_stderr", "max", "max_stderr",
                "u0", "u0_stderr", "min_max", "min_max_stderr")  # fmt: skip
SUMMARY_TAIL = ("chosen_set", "predictor", "predicted_mean", "prediction_rel_error")
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


def summary_columns(res) -> list[str]:
    per = [c for k in target_keys(res) for c in (f"{k}_required", f"{k}_verdict")]
    return [*SUMMARY_LEAD, *per, *SUMMARY_TAIL]


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
    from simulator.study.figures.areas import AREA_COLUMNS

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
        **({"sensor_models": res.sensor_models} if getattr(res, "sensor_models", None) else {}),
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
    import simulator.study.annual.report  # noqa: F401  (registers the annual section; shown when res.annual is set)
    from simulator.study.report.ugr_report import ugr_csv  # (registers the UGR section; shown when res.ugr is set)
    from simulator.study.report.glare_report import glare_files  # (registers the glare section; shown when res.glare is set)
    from simulator.study.report.page import report_html

    d = res.out_dir
    files = {d / "readings.csv": long_csv(res).encode(), d / "summary.csv": summary_csv(res).encode()}
    if res.placement is not None:
        files[d / "placement.csv"] = placement_csv(res).encode()
    if getattr(res, "areas", None):
        files[d / "areas.csv"] = areas_csv(res).encode()
    if getattr(res, "ugr", None):
        files[d / "ugr.csv"] = ugr_csv(res).encode()
    if getattr(res, "glare", None):
        files.update(glare_files(res))
    res.plan_cache = {}  # zone -> its plans (PNG), drawn once for the files and report.html
    for z in res.study.zone:
        pngs = zone_plan_pngs(res, z.name)
        res.plan_cache[z.name] = pngs
        files[d / f"heatmap_{_safe(z.name)}.png"] = heat_map_png(res, z.name, pngs)
    files[d / "report.html"] = report_html(res).encode()
    res.files = sorted(p.name for p in files) + ["study.json"]
    files[d / "study.json"] = (json.dumps(record(res, versions), indent=1, default=json_default) + "\n").encode()
    for p, data in files.items():
        write_atomic(p, data, durable=True)
    return list(files)


def _safe(name: str) -> str:
    return "".join(ch if ch.isalnum() or ch in "-_." else "_" for ch in name)
