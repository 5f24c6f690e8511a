"""A study end to end: stage → candidates → scenarios → chunks (resumed, distributed) → figures → placement → outputs."""

from __future__ import annotations

import time
from dataclasses import dataclass, field, replace
from pathlib import Path
from typing import Callable

import numpy as np

from simulator.errors import UserError
from simulator.study.inputs.candidates import build_candidates, candidate_warnings
from simulator.study.inputs.heads import combine_heads, head_factors
from simulator.study.trace.chunks import ChunkStore, StudyInterrupted, chunk_scene, make_chunks, readings_of, stale_chunks_note
from simulator.study.trace.distributed import choose_mode, run_chunks
from simulator.study.trace.groups import derive_seed, group_scene
from simulator.study.figures.objectives import compliance, zone_figures
from simulator.study.figures.placement import place_sensors
from simulator.study.inputs.scenarios import check_split_groups, dark_scenarios, expand_scenarios, resolve_groups, trace_groups_of
from simulator.study.schema import Study

__all__ = ["StudyResult", "run_study", "zone_members"]


@dataclass
class StudyResult:
    study: Study
    path: Path
    out_dir: Path
    candidates: list  #: Candidate, study order
    sets: list  #: CandidateSet
    scenarios: list  #: Scenario
    trace_groups: list
    mean: np.ndarray  #: (J, S, 2) readings per scenario and sensor
    stderr: np.ndarray  #: (J, S, 2)
    samples: np.ndarray  #: (J, S) samples per sensor of the pass each scenario was recombined from
    methods: list  #: (J) lists of S method names
    zones: dict  #: zone name -> indices into candidates
    figures: dict  #: (zone, scenario) -> ZoneFigures
    checks: dict  #: (zone, scenario) -> {target: pass|fail|unsure}
    placement: object | None
    chunks_total: int = 0
    chunks_computed: int = 0
    chunks_loaded: int = 0
    mode: str = "inprocess"
    workers: int = 1
    sensor_block: int = 0  #: sensors per chunk used
    timings_s: dict = field(default_factory=dict)
    chunk_wall_s: dict = field(default_factory=dict)
    chunk_trace_s: dict = field(default_factory=dict)  #: (trace key, block) -> seconds tracing
    chunk_trace_cpu_s: dict = field(default_factory=dict)  #: (trace key, block) -> CPU seconds tracing
    reference: dict | None = None
    warnings: list = field(default_factory=list)
    files: list = field(default_factory=list)
    areas: list = field(default_factory=list)  #: simulator.study.figures.areas.AreaRow, EN 12464-1 areas
    ugr: list = field(default_factory=list)  #: simulator.study.figures.ugr.UgrRow, the areas' observers
    glare: list = field(default_factory=list)  #: simulator.study.figures.glare_views.GlareViewRow, the stage's glare prims
    scene: object | None = None  #: the stage as read (geometry for the heat maps' plans); not in any output file
    sensor_models: dict = field(default_factory=dict)  #: modelled candidates: each model's sets, spectra and F per group


def zone_members(study: Study, sets, candidates, label: str = "") -> dict[str, np.ndarray]:
    """Candidate indices per zone (its set, inside its region)."""
    index = {c.sensor.name: i for i, c in enumerate(candidates)}
    out = {}
    for k, z in enumerate(study.zone):
        cs = next(s for s in sets if s.name == z.candidates)
        ids = []
        for c in cs.candidates:
            x, y = c.position[0], c.position[1]
            if z.region is None or (z.region[0] <= x <= z.region[2] and z.region[1] <= y <= z.region[3]):
                ids.append(index[c.sensor.name])
        if not ids:
            raise UserError(f"{label}: zone[{k}].region: no {z.candidates!r} candidate lies inside it")
        out[z.name] = np.asarray(ids)
    return out


def _sim_dict(study: Study) -> dict:
    d = study.simulation.model_dump()
    d.pop("threads")
    d["seed"] = 0  # replaced per group
    return d


def _reference_run(study: Study, scene, candidates, groups, scenario, seed: int, threads: int) -> dict:
    """One ordinary run of ``scenario`` (all its lights at their levels in one trace) for the cost and agreement check."""
    from simulator.config.loader import SimulationConfig
    from simulator.engine.driver import Engine, load_kernels
    from simulator.pipeline import run_plan
    from simulator.plan.planner import make_plan

    lights = []
    for l in scene.lights:
        g = next((g for g, ls in groups.items() if l.name in ls), None)
        lv = scenario.levels.get(g, 0.0) if g else 0.0
        if lv > 0:
            lights.append(replace(l, emission=(l.emission[0] * lv, l.emission[1] * lv)))
    sc = replace(group_scene(scene, []), lights=lights)
    sensors = [c.sensor for c in candidates]
    sim = SimulationConfig(**{**_sim_dict(study), "seed": seed})
    load_kernels(sim.device, sc)  # left out of the time, as the chunks leave it out
    t0, c0 = time.perf_counter(), time.process_time()
    eng = Engine(sc, sensors, device=sim.device, threads=threads)
    res = run_plan(eng, make_plan(sc, sensors, sim.method, sim.component), sim)
    return {"scenario": scenario.name, "wall_s": time.perf_counter() - t0, "cpu_s": time.process_time() - c0, "mean": res.mean,
            "stderr": res.stderr, "samples": res.samples}  # fmt: skip


def _reference_scenario(first: list, specs: list, results: dict, adaptive: bool):
    """The scenario of the first trace group that one ordinary run stands for in the cost figure.

    Among the scenarios with the most light groups lit (a run of one of them
    traces the lights the pass traces, so a sample costs the same), the one
    whose own target asks the most samples, by the pass's statistics
    (Σ_s n_s·max_c(σ_sc/|E_sc|)², n_s the pass's samples): an adaptive pass
    stops a sensor once its hardest scenario meets the target. Fixed budget,
    or a tie: the first of them.
    """
    lit = [sum(v > 0 for g, v in sc.levels.items() if "/" not in g) for sc in first]  # groups, not a sky's patches
    cands = [j for j, n in enumerate(lit) if n == max(lit)]
    if not adaptive or not specs or len(cands) == 1:
        return first[cands[0]]
    need = np.zeros(len(cands))
    for s in specs:
        gr = readings_of(results[s.id])
        n = gr.samples[0].astype(np.float64)
        for k, j in enumerate(cands):
            m, se = gr.combine(first[j].levels)
            with np.errstate(divide="ignore", invalid="ignore"):
                r2 = np.where(np.abs(m) > 0, (se / np.abs(m)) ** 2, 0.0).max(axis=1)
            need[k] += float(np.sum(n * r2))
    return first[cands[int(np.argmax(need))]]


def _ugr_plan(study: Study, scene, sets, groups: dict, tgs: list, stage: Path, label: str) -> dict | None:
    """The observers of the areas with a UGR limit and the chunks of their indirect illuminance
    (:mod:`simulator.study.figures.ugr`): each trace group's lamp groups, ``component = "indirect"``."""
    from simulator.study.figures.ugr import lamp_groups, observer_sensors, observers_of

    if not any(a.ugr_limit is not None for a in study.area):
        return None
    observers = observers_of(study, sets, label)
    lamps = lamp_groups(scene, groups)
    if not lamps:
        raise UserError(f"{label}: area: a UGR check needs a [[group]] of lamps (no DomeLight or DistantLight in it)")
    utgs = [replace(tg, key="ugr;" + tg.key, groups=[g for g in tg.groups if g in lamps]) for tg in tgs]
    sim = {**_sim_dict(study), "component": "indirect"}
    if sim["method"] in ("light", "bsdf", "mis"):  # direct-light estimators cannot read reflected light
        sim["method"] = "path"
    specs = make_chunks([t for t in utgs if t.groups], observer_sensors(observers), groups, stage, study.light_units, sim,
                        study.seed, max(1, len(observers)))  # fmt: skip
    return {"observers": observers, "lamps": lamps, "specs": specs}


def _ugr(study: Study, scene, scenarios: list, groups: dict, plan: dict, results: dict, warnings: list) -> list:
    """Every observer's UGR in every scenario (:func:`simulator.study.figures.ugr.ugr_rows`)."""
    from simulator.study.figures.ugr import luminaire_terms, ugr_rows

    observers, lamps = plan["observers"], plan["lamps"]
    ch = 1 if study.light_units == "photometric" else 0
    e = np.zeros((len(scenarios), len(observers)))
    e_se = np.zeros_like(e)
    for j, sc in enumerate(scenarios):
        for s in plan["specs"]:
            if s.trace_key == "ugr;" + sc.trace_key:
                m, se = readings_of(results[s.id]).combine({g: v for g, v in sc.levels.items() if g in lamps})
                ids = np.asarray(s.sensor_ids)
                e[j, ids], e_se[j, ids] = m[:, ch], se[:, ch]
    group_of = {n: g for g in lamps for n in groups[g]}
    lights = [l for l in scene.lights if l.name in group_of]
    terms, skipped = [], set()
    for o in observers:
        t, sk = luminaire_terms(scene, lights, o)
        terms.append(t)
        skipped |= set(sk)
    if skipped:
        warnings.append(f"UGR leaves out lamps with no size (point lights): {', '.join(sorted(skipped))}")
    return ugr_rows(study, observers, scenarios, e, e_se, terms, lambda sc, name: float(sc.levels.get(group_of[name], 0.0)))


def run_study(study: Study, path: Path, out_dir: Path, *, scheduler: str | None = None, log: Callable[[str], None] = print,
              on_chunk: Callable[[int, int, float], None] | None = None, stop_after: int | None = None,
              mode: str | None = None, workers: int | None = None, reference_run: bool = True) -> StudyResult:  # fmt: skip
    """Run (or resume) a validated study and return its numbers (outputs are written by :mod:`simulator.study.report.outputs`).

    Parameters
    ----------
    on_chunk : callable, optional
        ``on_chunk(done, total, elapsed_s)`` after each chunk, for a progress display.
    stop_after : int, optional
        Test hook: raise :class:`StudyInterrupted` after this many chunks were computed and stored.
    mode, workers : optional
        Override ``[compute] mode`` and ``workers``.
    reference_run : bool
        Also trace one scenario as an ordinary run, all its lights in one
        trace (of the first trace group's scenarios with the most groups
        lit, the one that asks the most samples, see
        :func:`_reference_scenario`); its time and its
        agreement with the recombination go to the closing note and the
        JSON record, not the CSVs.
    """
    label = str(path)
    t0 = time.perf_counter()
    stage = (path.parent / study.stage).resolve() if not Path(study.stage).is_absolute() else Path(study.stage)
    from simulator.scene.usd import load_stage

    base = load_stage(stage, light_units=study.light_units, radiometric_spectrum="E")
    warnings = list(base.warnings)
    sets = build_candidates(base, study.candidates, label)
    candidates = [c for s in sets for c in s.candidates]
    sensors = [c.sensor for c in candidates]
    warnings += candidate_warnings(base, study.candidates, sets, label)
    groups, unassigned = resolve_groups(base, study.group, label)
    if unassigned:
        warnings.append(f"lights in no [[group]] stay off in every scenario: {', '.join(unassigned)}")
    if (base.geometry.emission > 0).any():
        warnings.append("emissive surfaces are in no light group and are left out of every scenario")
    sky_split = check_split_groups(base, study.group, groups, label)
    heads = head_factors(study, base, candidates, groups, label)  # None: no candidate names a sensor model
    if heads is not None:
        warnings += heads.notes
    scenarios = expand_scenarios(study.scenario, list(groups), label, scene=base, groups=groups)
    tgs = trace_groups_of(scenarios, base, groups, label)
    warnings += dark_scenarios(scenarios, base, groups)
    for tg in tgs:  # variant names are checked by the reader: fail before any chunk runs
        if tg.variants:
            try:
                load_stage(stage, light_units=study.light_units, radiometric_spectrum="E", variants=tg.variants)
            except UserError as exc:
                raise UserError(f"{label}: scenario {tg.scenarios[0].name!r}: variants: {exc}") from None
    zones = zone_members(study, sets, candidates, label)
    t_setup = time.perf_counter()

    block = study.compute.sensor_block
    if block == "auto":  # from the study's size alone, so chunks (and bytes) are the same in every mode
        from simulator.study.trace.blocks import auto_block

        block = auto_block(len(sensors), study.simulation.samples)
    specs = make_chunks(tgs, sensors, groups, stage, study.light_units, _sim_dict(study), study.seed, block, sky_split)
    ugr_plan = _ugr_plan(study, base, sets, groups, tgs, stage, label)
    if ugr_plan is not None:
        specs = specs + ugr_plan["specs"]
    store = ChunkStore(out_dir)
    if (stale := store.drop_other_code()) > 0:
        warnings.append(stale_chunks_note(out_dir, stale))
    results: dict[str, dict] = {}
    for s in specs:
        r = store.load(s.id)
        if r is not None:
            results[s.id] = r
    loaded = len(results)
    todo = [s for s in specs if s.id not in results]
    if study.simulation.threads:
        todo = [replace(s, threads=study.simulation.threads) for s in todo]
    sched = scheduler or study.compute.scheduler
    used_mode, n_workers = choose_mode(mode or study.compute.mode, sched, len(todo), workers if workers is not None else study.compute.workers)
    done = loaded
    computed = 0
    t_chunks = time.perf_counter()
    if on_chunk:
        on_chunk(done, len(specs), 0.0)
    for res in run_chunks(todo, used_mode, n_workers, sched, study.compute.retries, log=log):
        store.save(res)
        results[res["id"]] = res
        done += 1
        computed += 1
        if on_chunk:
            on_chunk(done, len(specs), time.perf_counter() - t_chunks)
        if stop_after is not None and computed >= stop_after:
            raise StudyInterrupted(f"stopped after {computed} chunks")
    t_traced = time.perf_counter()

    # recombine: scenario j reads sensor s from the chunk of its trace group and block
    n_j, n_s = len(scenarios), len(sensors)
    mean = np.zeros((n_j, n_s, 2))
    stderr = np.zeros((n_j, n_s, 2))
    samples = np.zeros((n_j, n_s), np.int64)
    methods = [[""] * n_s for _ in range(n_j)]
    by_tg: dict[str, list] = {}
    for s in specs:
        by_tg.setdefault(s.trace_key, []).append(s)
    ch = 1 if study.light_units == "photometric" else 0
    for j, sc in enumerate(scenarios):
        for s in by_tg.get(sc.trace_key, []):
            gr = readings_of(results[s.id])
            m, e = gr.combine(sc.levels)
            if heads is not None:  # modelled candidates: each light group through the head's spectral response
                combine_heads(gr, sc.levels, s.sensor_ids, heads, ch, m, e)
            ids = np.asarray(s.sensor_ids)
            mean[j, ids], stderr[j, ids] = m, e
            samples[j, ids] = np.asarray(results[s.id]["samples"])[0]
            for i, name in zip(s.sensor_ids, gr.methods):
                methods[j][i] = name

    figures, checks = {}, {}
    for z in study.zone:
        ids = zones[z.name]
        for j, sc in enumerate(scenarios):
            f = zone_figures(mean[j, ids, ch], stderr[j, ids, ch])
            figures[(z.name, sc.name)] = f
            checks[(z.name, sc.name)] = compliance(f, dict(z.targets))

    from simulator.study.figures.areas import area_rows

    areas = area_rows(study, sets, candidates, scenarios, mean, stderr, label)
    ugr = _ugr(study, base, scenarios, groups, ugr_plan, results, warnings) if ugr_plan is not None else []
    from simulator.study.figures.glare_views import study_glare, views_of

    views = views_of(base)
    glare = study_glare(study, stage, views, tgs, groups, tuple(sky_split), log) if views and scenarios else []
    placement = None
    if study.placement is not None:
        pl = study.placement
        pool = [i for i, c in enumerate(candidates) if c.set_name in pl.candidates]
        znames = [z.name for z in study.zone] if pl.target == "each_zone" else [pl.target]
        t = np.array([[figures[(z, sc.name)].mean for sc in scenarios] for z in znames])
        t_se = np.array([[figures[(z, sc.name)].mean_se for sc in scenarios] for z in znames])
        r = mean[:, pool, ch].T
        r_se = stderr[:, pool, ch].T
        placement = place_sensors([candidates[i].sensor.name for i in pool], r, r_se, t, t_se, znames,
                                  min(pl.k, len(pool)), pl.objective, pl.replicates, derive_seed(study.seed, "placement"))  # fmt: skip
    t_analysis = time.perf_counter()

    reference = None
    if reference_run and scenarios:
        first = tgs[0].scenarios
        sc0 = _reference_scenario(first, by_tg.get(first[0].trace_key, []), results, study.simulation.rel_error is not None)
        j0 = scenarios.index(sc0)
        spec0 = next(s for s in specs if s.trace_key == sc0.trace_key)
        ref = _reference_run(study, chunk_scene(spec0), candidates, groups, sc0, derive_seed(study.seed, "reference"), study.simulation.threads)
        m0, e0 = mean[j0], stderr[j0]
        if any("/" in g for g in sc0.levels):  # a sky of patches: the run traces the uniform dome, so compare with that recombination
            plain = {g: v for g, v in sc0.levels.items() if "/" not in g}
            m0, e0 = np.zeros_like(m0), np.zeros_like(e0)
            for s in by_tg.get(sc0.trace_key, []):
                ids = np.asarray(s.sensor_ids)
                m0[ids], e0[ids] = readings_of(results[s.id]).combine(plain)
        sig = np.sqrt(ref["stderr"][:, ch] ** 2 + e0[:, ch] ** 2)
        dev = np.abs(ref["mean"][:, ch] - m0[:, ch])
        ok = dev <= 4 * sig + 1e-9 * np.abs(ref["mean"][:, ch])
        pass_samples = sum(int(results[s.id]["samples"][0].sum()) for s in by_tg.get(sc0.trace_key, []))
        reference = {"scenario": sc0.name, "wall_s": ref["wall_s"], "cpu_s": ref["cpu_s"], "sensors_within_4_sigma": int(ok.sum()), "sensors": n_s,
                     "samples": int(ref["samples"].sum()), "trace_group_samples": pass_samples,
                     "largest_deviation_sigma": float(np.max(np.where(sig > 0, dev / np.where(sig > 0, sig, 1), 0.0)))}  # fmt: skip
    t_end = time.perf_counter()
    trace_s = sum(float(np.sum(results[s.id]["trace_s"])) for s in specs)
    return StudyResult(
        study=study, path=path, out_dir=out_dir, candidates=candidates, sets=sets, scenarios=scenarios, trace_groups=tgs,
        mean=mean, stderr=stderr, samples=samples, methods=methods, zones=zones, figures=figures, checks=checks, placement=placement, chunks_total=len(specs),
        chunks_computed=computed, chunks_loaded=loaded, mode=used_mode, workers=n_workers, sensor_block=int(block),
        timings_s={"setup": t_setup - t0, "chunks": t_traced - t_chunks, "trace_in_chunks": trace_s,
                   "analysis": t_analysis - t_traced, "reference_run": t_end - t_analysis, "total": t_end - t0},
        chunk_wall_s={s.id: float(results[s.id].get("wall_s", 0.0)) for s in specs}, reference=reference, warnings=warnings, scene=base, areas=areas, ugr=ugr, glare=glare,
        sensor_models={} if heads is None else heads.record(candidates),
        chunk_trace_s={(s.trace_key, s.block): float(np.sum(results[s.id]["trace_s"])) for s in specs},
        chunk_trace_cpu_s={(s.trace_key, s.block): float(results[s.id].get("trace_cpu_s", 0.0)) for s in specs},
    )  # fmt: skip
