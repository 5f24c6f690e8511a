"""One run, start to finish: config → stage → plan → engine → CSV and run record."""

from __future__ import annotations

import platform
import sys
import time
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from simulator import __version__
from simulator.config.loader import RunConfig
from simulator.engine.driver import EngineResult
from simulator.errors import UserError
from simulator.interrupts import StopFlag, sigint_deferred
from simulator.io.maps import grid_outputs, probe_outputs
from simulator.plan.cache import cached_plan
from simulator.plan.planner import Plan, make_plan, probe_method
from simulator.io.glare_maps import glare_readings
from simulator.io.results import Reading, probe_readings, readings_from, write_outputs
from simulator.scene.model import Scene, Sensor, SensorKind
from simulator.scene.light_flux import lights_record
from simulator.scene.sanity import sensor_warnings

__all__ = ["RunOutput", "load_scene", "cached_scene", "collect_sensors", "run"]


@dataclass
class RunOutput:
    rows: list[Reading]
    csv_path: Path | None  #: None: run with ``write=False``
    record_path: Path | None
    record: dict
    scene: Scene
    interrupted: bool = False  #: stopped by Ctrl-C: the files hold what was measured so far


def load_scene(cfg: RunConfig) -> Scene:
    from simulator.scene.usd import load_stage  # the stage reader: the only code that imports pxr

    return load_stage(cfg.stage, light_units=cfg.light_units, radiometric_spectrum=cfg.radiometric_spectrum,
                      variants=cfg.variants, require_light=True,  # a run of a stage with no light is refused
                      time=getattr(cfg, "time", None))


def cached_scene(cfg: RunConfig) -> tuple[Scene, int | None]:
    """:func:`load_scene`, kept for the process's later runs of the same stage selection while none of
    the stage's files change (:mod:`simulator.scene.stage_cache`); ``(scene, token)``."""
    from simulator.scene import stage_cache

    return stage_cache.cached_stage(lambda: load_scene(cfg), cfg.stage, cfg.light_units, cfg.radiometric_spectrum,
                                    cfg.variants, getattr(cfg, "time", None))


def collect_sensors(cfg: RunConfig, scene: Scene) -> list[Sensor]:
    """Config sensors, then those authored in the stage; names must be unique."""
    sensors = list(cfg.sensors) + list(scene.sensors)
    if not sensors:
        raise UserError(
            f"{cfg.path}: no sensors: add [[sensor]] or [[grid]] tables, or author prims with "
            f"probesim:sensor:kind in {cfg.stage.name}"
        )
    seen: dict[str, str] = {}
    for s in sensors:
        if s.name in seen:
            raise UserError(f"{cfg.path}: sensor name {s.name!r} is used twice ({seen[s.name]} and {s.source})")
        seen[s.name] = s.source
    return sensors


def run_plan(engine, plan: Plan, sim, progress=None, stop: StopFlag | None = None) -> EngineResult:
    """Run each method's group of sensors and gather the readings in sensor
    order; ``methods`` says which method read each sensor.

    Closed-form readings count as meeting any error target (they are exact).
    Once ``stop`` is requested no further group is started; ``unfinished``
    marks the sensors of the stopped group left short and those of the
    groups never started (0 samples). Without ``stop``, Ctrl-C raises
    ``KeyboardInterrupt`` (after the current batch).
    """
    n = len(plan.sensors)
    groups = plan.groups()
    order = plan.run_order() if hasattr(plan, "run_order") else list(groups.items())
    out = EngineResult(
        method="+".join(groups), device=engine.device, mean=np.zeros((n, 2)), stderr=np.zeros((n, 2)),
        samples=np.zeros(n, np.int64), seconds=np.zeros(n), target_met=np.ones(n, bool) if sim.adaptive else None,
        non_finite=np.zeros(n, np.int64), wall_s=0.0, methods=[sp.method for sp in plan.sensors],
        unfinished=np.ones(n, bool),
    )  # fmt: skip
    names = [l.name for l in engine.scene.lights]
    engine.set_light_mask(plan.light_mask(names))
    engine.set_computed(plan.computed_mask(names))
    hero = getattr(engine, "hero_tables", None)
    if hero is not None:  # spectral transport: every response per sensor (NaN: not available)
        out.responses = [r.name for r in hero.responses]
        out.response_mean = np.full((n, len(hero.responses)), np.nan)
        out.response_stderr = np.full((n, len(hero.responses)), np.nan)
    for method, ids in order:
        if stop is not None and stop.requested:
            break
        r = engine.run(
            method, samples=sim.samples, seed=sim.seed, rel_error=sim.rel_error, abs_error=sim.abs_error,
            max_samples=sim.sample_cap, time_limit_s=sim.time_limit_s, max_depth=sim.max_depth,
            component=sim.component, progress=progress, sensor_ids=ids, confidence=sim.confidence, stop=stop,
            choose_first_batch=sim.choose_first_batch,
        )  # fmt: skip
        if r.method != method:  # a hybrid whose pilot found sampling it all cheaper (Engine._hybrid_choice)
            for i in ids.tolist():
                out.methods[i] = r.method
        out.unfinished[ids] = False if r.unfinished is None else r.unfinished[ids]
        out.mean[ids], out.stderr[ids], out.samples[ids] = r.mean[ids], r.stderr[ids], r.samples[ids]
        out.seconds[ids], out.non_finite[ids] = r.seconds[ids], r.non_finite[ids]
        if out.target_met is not None and r.target_met is not None:
            out.target_met[ids] = r.target_met[ids]
        out.wall_s += r.wall_s
        out.warnings += [w for w in r.warnings if w not in out.warnings]
        if hero is not None:
            _merge_responses(out, r, ids, hero, engine, sim, stop)
    out.interrupted = stop is not None and stop.requested
    return out


def _merge_responses(out: EngineResult, r: EngineResult, ids, hero, engine, sim, stop) -> None:
    """One method group's responses into the run's. Traced groups estimated them per sample. Closed-form
    groups (analytic, exact: light straight from emitters) take them from the emitters' one spectrum;
    with several spectra they are estimated by direct-light sampling (method ``light``, component
    ``direct``, the run's samples and seed) while the W and lm columns stay the closed form's."""
    from simulator.spectra.traced import closed_form_responses

    if r.response_mean is not None:
        out.response_mean[ids], out.response_stderr[ids] = r.response_mean[ids], r.response_stderr[ids]
        return
    m = closed_form_responses(hero, r.mean[ids])
    if m is not None:
        out.response_mean[ids], out.response_stderr[ids] = m, 0.0 * m
        return
    est = engine.run("light", samples=sim.samples, seed=sim.seed, component="direct", sensor_ids=ids, stop=stop)
    out.response_mean[ids], out.response_stderr[ids] = est.response_mean[ids], est.response_stderr[ids]
    w = (f"{r.method}: the response columns of its {len(ids)} sensor(s) are estimated by direct-light sampling "
         "(emitters of several spectra: a closed form per light is not kept)")
    out.warnings += [] if w in out.warnings else [w]


def _sha256(path: Path) -> str:
    from simulator.scene.stage_cache import file_sha256  # kept while the file is unchanged

    return file_sha256(path)


def _versions() -> dict:
    import numpy

    from simulator.engine.driver import warp_version
    from simulator.scene.stage_cache import usd_version  # without pxr where the stage came from disk

    return {
        "probesim": __version__,
        "python": platform.python_version(),
        "numpy": numpy.__version__,
        "warp": warp_version(),
        "usd": usd_version(),
    }



def config_engine(cfg, scene, sensors, device: str | None = None, threads: int | None = None, hero=None):
    """The engine a config's run reads its sensors with: on the config's device
    and threads unless given, tracing hero wavelengths where the scene's
    transport is not grey (``hero``: the tables, when the caller has them).
    Every command that reads a config (run, bench, chart) builds it here, so
    a coloured room is traced the same way by each."""
    from simulator.engine.driver import Engine
    from simulator.spectra.transport import choose_transport

    sim = cfg.simulation
    engine = Engine(scene, sensors, device=sim.device if device is None else device,
                    threads=sim.threads if threads is None else threads)  # fmt: skip
    if hero is None and choose_transport(scene)[0] != "grey":
        from simulator.spectra.traced import run_hero_tables

        hero = run_hero_tables(cfg, scene)
    if hero is not None:
        engine.set_hero_tables(hero)
    return engine


def _roulette_record(found: dict) -> dict:
    """The roulette pilot's finding (Engine.rr_pilot) for the run record."""
    return {"threshold": found["threshold"], "rule": found["rule"], "seconds": found["seconds"],
            "tried": [{"threshold": t, "relvar_mean": a, "relvar_max": b, "rays_per_sample": r}
                      for t, a, b, r in found["tried"]]}


def _batch_record(plan: dict) -> dict:
    """How an adaptive run's batches were sized (Engine.batch_plans) for the run record."""
    return {k: v for k, v in plan.items() if v is not None}


def run(cfg: RunConfig, progress=None, log=print, write: bool = True, sensors: list[Sensor] | None = None) -> RunOutput:
    """Run a validated config and write its CSV and run record.

    Parameters
    ----------
    cfg : RunConfig
    progress : callable, optional
        Receives :class:`simulator.engine.driver.Progress` after each batch.
    log : callable
        Where one-line notes (warnings, the chosen method) go.
    write : bool
        False: write nothing (no CSV, run record or maps); the output's rows
        and record are the same, its ``csv_path`` and ``record_path`` None
        and its record's ``maps`` empty.
    sensors : list of Sensor, optional
        The sensors to read instead of the config's and the stage's (a run over ``times`` reads
        every time's in one trace, :mod:`simulator.timecodes`).

    Notes
    -----
    The stage reading and the plan are kept for later calls in the same
    process while nothing they depend on changes (:func:`cached_scene`,
    :mod:`simulator.plan.cache`).

    Ctrl-C (or ``KeyboardInterrupt`` from ``progress``) while tracing stops
    the run after the current batch: the CSV and run record are written with
    what was measured (see :func:`_partial_rows`), no maps, and the output's
    ``interrupted`` is True. SIGINT stays deferred until the files are in
    place, so a second Ctrl-C cannot leave a file half-written.
    """
    from simulator.spectra.transport import choose_transport

    from simulator.sensor_models.readings import channel_responses, optics_twins

    if write:  # a folder that cannot hold the outputs is said before any work, not after the trace
        from simulator.io.atomic import check_folder

        check_folder(cfg.output.csv.parent)
    if getattr(cfg, "times", None) and sensors is None:  # one row per sensor and time code
        import sys

        from simulator.timecodes import run_times

        return run_times(cfg, sys.modules[__name__], progress, log, write)
    t0 = time.perf_counter()
    scene, token = cached_scene(cfg)
    sensors = collect_sensors(cfg, scene) if sensors is None else list(sensors)
    twins = optics_twins([s for s in sensors if s.spec.reader == "estimate"])  # modelled sensors read again
    spectrum = None  # the emitters' spectrum, for response columns (grey scenes: exact post hoc)
    hero = None  # spectral transport's tables (a colour can change a reading: hero wavelengths)
    if choose_transport(scene)[0] == "grey":
        if cfg.spectra is not None or twins:
            spectrum = _run_spectrum(cfg, scene, force=bool(twins))
    else:
        from simulator.spectra.traced import run_hero_tables

        hero = run_hero_tables(cfg, scene, extra=channel_responses(twins))
    misplaced = sensor_warnings(scene, sensors)  # sensors a stage would read a plausible wrong number at
    misplaced += _response_notes(cfg)
    # probes are read by their own kernel (simulator.engine.probes), glare views by simulator.engine.glare
    probes = [s for s in sensors if s.kind == SensorKind.PROBE]
    plain = [s for s in sensors if s.spec.reader == "estimate"]
    sim = cfg.simulation
    if sim.component != "total" and any(s.kind == SensorKind.GLARE for s in sensors):
        raise UserError(f"{cfg.path}: simulation.component: glare sensors need the total light, not {sim.component!r}")
    t_read = time.perf_counter()
    plan = cached_plan(lambda: make_plan(scene, plain, sim.method, sim.component), token, plain, sim.method, sim.component)
    if twins:
        from simulator.plan.planner import with_optics

        plan = with_optics(plan, scene, twins)
    if sim.rel_error is None and sim.samples == 1 and any(sp.method not in ("analytic", "exact") for sp in plan.sensors):
        misplaced.append("simulation.samples = 1: one sample per sensor gives no standard error (its stderr columns "
                         "read inf); draw 2 or more")  # fmt: skip
    reason = "per-sensor plan (see plan)" if sim.method == "auto" else "as requested"
    probes_method = None
    if probes or any(s.kind == SensorKind.GLARE for s in sensors):  # no closed form: one method for the run
        probes_method, why = probe_method(scene, sim.method, sim.component)
        reason += f"; probes and glare views: {why}"
    t_load = time.perf_counter()
    engine = config_engine(cfg, scene, plain + twins, hero=hero)
    for w in _scene_warnings(scene, engine) + ([] if hero is None else hero.notes) + misplaced:
        log(f"warning: {w}")
    t_setup = time.perf_counter()
    with sigint_deferred() as stop:  # Ctrl-C from here on: stop after the batch, write what was measured
        return _trace_and_write(cfg, scene, sensors, probes, plain, plan, probes_method, reason, engine, stop, progress, log,
                                (t0, t_read, t_load, t_setup), spectrum, write, misplaced, twins)  # fmt: skip


def _response_notes(cfg: RunConfig) -> list[str]:
    """What the config's custom responses leave out (a file short of 380–780 nm, a responsivity beyond
    it), as warning lines."""
    if cfg.spectra is None:
        return []
    return [n for r in cfg.spectra.responses for n in r.notes]


def _run_spectrum(cfg: RunConfig, scene: Scene, force: bool = False):
    """The emitters' spectrum for the config's responses (:func:`simulator.spectra.posthoc.run_spectrum`);
    ``force``: wanted whatever the config asks (sensor models weigh it by their channels).

    Raises
    ------
    UserError
        Before any tracing, one line naming the config: the lights' spectrum
        must be named in ``[spectra] lights``.
    """
    from simulator.spectra import posthoc

    settings = cfg.spectra
    if force and (settings is None or not settings.wanted):
        from types import SimpleNamespace

        settings = SimpleNamespace(wanted=True, responses=(), lights=None if settings is None else settings.lights)
    try:
        spectrum = posthoc.run_spectrum(settings, scene, cfg.light_units, cfg.radiometric_spectrum)
    except UserError as e:
        raise UserError(f"{cfg.path}: {'output.responses' if cfg.spectra is not None else 'sensor model'}: {e}") from None
    return spectrum if cfg.spectra is not None or not force else _ModelsOnly(spectrum)


class _ModelsOnly:
    """A grey run's emitter spectrum wanted by its sensor models only: no response columns from it."""

    def __init__(self, spectrum):
        self.spectrum = spectrum


def _model_columns(cfg, plain, twins, by_name, res, spectrum, engine, log) -> dict:
    """The sensor models' columns on their sensors' rows (:mod:`simulator.sensor_models.readings`) and the
    run record's ``sensor_models``."""
    from simulator.sensor_models.readings import add_model_columns, model_record

    n = len(plain)
    mean = res.mean[n:].copy()
    mean[res.samples[n:] == 0] = np.nan  # never read (interrupted)
    hero = getattr(engine, "hero_tables", None)
    if hero is None:
        spec = spectrum.spectrum if isinstance(spectrum, _ModelsOnly) else spectrum
        notes = add_model_columns(by_name, twins, mean, res.stderr[n:], cfg.simulation.seed, spectrum=spec)
    else:
        names = [r.name for r in hero.responses]
        notes = add_model_columns(by_name, twins, mean, res.stderr[n:], cfg.simulation.seed, responses=names,
                                  response_mean=res.response_mean[n:], response_stderr=res.response_stderr[n:],
                                  ideal_mean=res.response_mean[:n], ideal_index={s.name: i for i, s in enumerate(plain)})
    for note in notes:
        log(f"warning: {note}")
    return model_record(twins, notes)


def _run_glare(cfg, scene, sensors, views, method, engine, stop, progress) -> list:
    """The run's glare views (:func:`simulator.engine.glare.run_glare`), on engines like the run's own."""
    from simulator.engine.driver import Progress
    from simulator.engine.glare import run_glare

    sim = cfg.simulation
    hero = getattr(engine, "hero_tables", None)

    def report(done, total, samples, elapsed):
        if progress is not None:
            progress(Progress(done, total, samples, elapsed, None))

    return run_glare(
        scene, views, method, lambda sc, ss: config_engine(cfg, sc, ss, hero=hero), seed=sim.seed,
        stream_ids=[i for i, s in enumerate(sensors) if s.kind == SensorKind.GLARE], max_depth=sim.max_depth,
        time_limit_s=sim.time_limit_s, progress=report, stop=stop,
    )  # fmt: skip


def _traced_columns(cfg, plan, engine, plain, by_name, res, probes) -> tuple[dict, list[dict]]:
    """Response columns of a spectrally traced run's plain sensors, its record and its map channels."""
    from simulator.spectra.posthoc import response_channels
    from simulator.spectra.traced import add_traced_columns, traced_record

    hero = engine.hero_tables
    columns = add_traced_columns([by_name[s.name] for s in plain], hero, res.response_mean, res.response_stderr)
    record = traced_record(hero, columns, plan.transport, plan.channel_reason)
    if probes:
        record["notes"].append("probes are traced spectrally: their maps' R, G, B are each pixel's traced "
                               "colour; their response columns are not estimated")
    if cfg.spectra is not None:
        record.update(cfg.spectra.raw)
    from simulator.spectra.traced import writes_columns

    wanted = [r for r in hero.responses if writes_columns(r)]
    return record, response_channels(wanted)


def _time_record(scene: Scene) -> dict:
    """Which time the stage was read at: ``{"code": t}``, or, with none given, ``{"code": None, "read":
    "earliest", "animated_prims": n}`` (each attribute at its own first time sample)."""
    if scene.time_code is not None:
        return {"code": scene.time_code}
    return {"code": None, "read": "earliest time sample of each attribute", "animated_prims": len(scene.animated)}


def _scene_warnings(scene: Scene, engine) -> list[str]:
    """The stage's warnings as the run record keeps them (a spectral run's say its colours were traced)."""
    if getattr(engine, "hero_tables", None) is None:
        return list(scene.warnings)
    from simulator.spectra.traced import traced_warning

    return [traced_warning(w) for w in scene.warnings]


def _partial_rows(rows: list[Reading], unfinished: dict[str, bool], adaptive: bool) -> list[Reading]:
    """Rows of an interrupted run: ``target_met`` is False for each sensor
    the stop left unfinished; in a fixed-budget run the others say True (their
    requested samples drawn), in an adaptive run whether they met the target.
    A sensor never read (0 samples, no closed form) has empty value cells."""
    for r in rows:
        if unfinished[r.sensor.name]:
            r.target_met = False
            if r.samples == 0:
                r.values = {}
        elif not adaptive:
            r.target_met = True
    return rows


def _trace_and_write(cfg, scene, sensors, probes, plain, plan, probes_method, reason, engine, stop, progress, log, times,
                     spectrum=None, write=True, misplaced=(), twins=()) -> RunOutput:
    """The rest of :func:`run`: trace (until done or ``stop``), then write the files."""
    t0, t_read, t_load, t_setup = times
    sim = cfg.simulation
    res = run_plan(engine, plan, sim, progress, stop)
    probe_res = []
    if probes and not stop.requested:
        probe_res = engine.run_probes(
            probes, probes_method, samples=sim.samples, seed=sim.seed,
            stream_ids=[i for i, s in enumerate(sensors) if s.kind == SensorKind.PROBE], rel_error=sim.rel_error, abs_error=sim.abs_error,
            max_samples=sim.sample_cap, time_limit_s=sim.time_limit_s, max_depth=sim.max_depth,
            component=sim.component, progress=progress, confidence=sim.confidence, stop=stop,
        )  # fmt: skip
        for p in probe_res:
            res.warnings.extend(p.warnings)
    views = [s for s in sensors if s.kind == SensorKind.GLARE]
    glare_res = _run_glare(cfg, scene, sensors, views, probes_method, engine, stop, progress) if views and not stop.requested else []
    for g in glare_res:
        res.warnings.extend(g.warnings)
    # a stop that came after the last batch changed nothing: the run is complete
    interrupted = stop.requested and (bool(res.unfinished.any()) or len(probe_res) < len(probes)
                                      or any(p.interrupted for p in probe_res) or len(glare_res) < len(views)
                                      or any(g.interrupted for g in glare_res))
    for w in res.warnings:
        log(f"warning: {w}")
    by_name = {r.sensor.name: r for r in readings_from(plain, res.mean, res.stderr, res.samples, res.seconds, res.methods, res.target_met)}
    by_name.update({r.sensor.name: r for r in probe_readings(probe_res, probes_method)})
    by_name.update({r.sensor.name: r for r in glare_readings(glare_res, probes_method)})
    spectra_record, response_maps = None, []
    models_record = _model_columns(cfg, plain, twins, by_name, res, spectrum, engine, log) if twins else {}
    if isinstance(spectrum, _ModelsOnly):
        spectrum = None
    if spectrum is not None:  # response columns from the stated column (exact: the scene is grey)
        from simulator.spectra import posthoc

        spectra_record, response_maps = posthoc.finish_run(list(by_name.values()), scene, cfg.light_units, spectrum, cfg.spectra)
    elif res.responses is not None:  # traced spectrally: response columns from the same samples
        spectra_record, response_maps = _traced_columns(cfg, plan, engine, plain, by_name, res, probes)
    extra, probe_maps, n_finished = {}, {}, len(sensors)
    if interrupted:  # probes and glare views not reached: an empty row each
        by_name.update({s.name: Reading(s, {}, 0, 0.0, probes_method, None) for s in probes + views if s.name not in by_name})
        unfinished = dict(zip((s.name for s in plain), res.unfinished))
        unfinished.update({s.name: True for s in probes + views})
        unfinished.update({p.sensor.name: p.interrupted for p in probe_res})
        unfinished.update({g.sensor.name: g.interrupted for g in glare_res})
        rows = _partial_rows([by_name[s.name] for s in sensors], unfinished, res.target_met is not None)
        n_finished = sum(1 for u in unfinished.values() if not u)
    else:
        rows = [by_name[s.name] for s in sensors]
        if write:  # the maps: files only
            meta = {"seed": sim.seed, "method": "+".join(plan.groups()), "light_units": cfg.light_units, "stage": cfg.stage.name}
            extra = grid_outputs(cfg.output.csv, cfg.grids, rows, meta, responses=response_maps)
            probe_meta = {**meta, "method": probes_method, "taken": [g.name for g in cfg.grids]}
            if spectrum is not None:  # grey scene, one declared spectrum: the maps carry its colour
                from simulator.spectra.posthoc import rgb_per_luminance

                probe_meta["rgb"] = (spectrum.name, rgb_per_luminance(spectrum))
            probe_files, probe_maps = probe_outputs(cfg.output.csv, probe_res, probe_meta)
            extra.update(probe_files)
            if glare_res:
                from simulator.io.glare_maps import glare_outputs

                glare_files, glare_record = glare_outputs(cfg.output.csv, glare_res, {**meta, "method": probes_method})
                extra.update(glare_files)
    t_end = time.perf_counter()
    record = {
        "config_path": str(cfg.path),
        "config": cfg.raw,
        "overrides": getattr(cfg, "overrides", {}),
        "stage": {"path": str(cfg.stage), "sha256": _sha256(cfg.stage), "meters_per_unit": scene.meters_per_unit, "up_axis": scene.up_axis,
                  "variants": dict(cfg.variants), "time": _time_record(scene)},
        "seed": sim.seed,
        "samples_requested": sim.samples,
        "samples_total": int(res.samples.sum()) + sum(p.samples for p in probe_res) + sum(g.samples for g in glare_res),
        "interrupted": interrupted,
        "sensors_read": sum(1 for r in rows if r.values),
        "sensors_finished": n_finished,
        "method": {"requested": sim.method, "used": {m: len(ix) for m, ix in plan.groups().items()}, "probes": probes_method, "reason": reason},
        "plan": plan.to_record(),
        **({} if spectra_record is None else {"spectra": spectra_record}),
        **({"sensor_models": models_record} if models_record else {}),
        "component": sim.component,
        "device": res.device,
        "threads": engine.threads,
        "host": {"platform": platform.platform(), "machine": platform.machine(), "processor": platform.processor(), "python": sys.version.split()[0]},
        "versions": _versions(),
        "timings_s": {"load": t_read - t0, "plan": t_load - t_read, "setup": t_setup - t_load,
                      "trace": res.wall_s + sum(p.seconds for p in probe_res) + sum(g.seconds for g in glare_res),
                      "guide": engine.guide.seconds if engine.guide is not None else 0.0, "total": t_end - t0},
        **({} if engine.guide is None else {"guide": engine.guide.to_record()}),
        **({} if engine.guide is not None or not engine.guide_skipped else {"guide_skipped": engine.guide_skipped}),
        **({} if engine.rr_pilot is None else {"roulette": _roulette_record(engine.rr_pilot)}),
        **({} if engine.split_pilot is None else {"split": dict(engine.split_pilot)}),
        **({} if engine.pieces_pilot is None else {"emitter_pieces": dict(engine.pieces_pilot)}),
        **({} if getattr(engine, "hybrid_pilot", None) is None else {"hybrid": dict(engine.hybrid_pilot)}),
        "lights": lights_record(scene.lights),
        "sensors": len(sensors),
        "triangles": scene.geometry.n_triangles,
        "warnings": _scene_warnings(scene, engine) + list(misplaced) + list(res.warnings),
        "non_finite_samples": int(res.non_finite.sum()) + sum(p.non_finite for p in probe_res),
        "maps": sorted(p.name for p in extra),
        "probe_maps": probe_maps,
        **({"glare": {"method": probes_method, "views": len(glare_res), "file": cfg.output.csv.stem + ".glare.json"}}
           if glare_res else {}),
        "adaptive": None
        if res.target_met is None
        else {
            "rel_error": sim.rel_error,
            "abs_error": sim.abs_error,
            "confidence": sim.confidence,
            "max_samples": sim.sample_cap,
            "time_limit_s": sim.time_limit_s,
            "sensors_met": int(res.target_met.sum()) if not interrupted else sum(1 for r in rows if r.target_met),
            "batches": {m: _batch_record(p) for m, p in getattr(engine, "batch_plans", {}).items()},
        },
    }
    if not write:
        return RunOutput(rows, None, None, record, scene, interrupted)
    record_path = write_outputs(cfg.output.csv, rows, record, extra, encoded={"plan": plan.record_json()},
                                csv_columns=cfg.output.csv_columns)
    return RunOutput(rows, cfg.output.csv, record_path, record, scene, interrupted)
