"""The same bytes whatever the thread count: guided runs and the bundled studies.

A guided run learns its surface guide from a pilot whose tallies are float32
sums; a float sum depends on its order, so the pilot keeps them per block of
consecutive kernel threads (``engine.guide.pilot_chunks``, a function of the
pilot's size alone), each block on one CPU worker in index order, and adds
the blocks in order in float64. These tests hold the engine to that: the
guide's tables, a guided config's CSV (the wall-clock ``seconds`` column
aside, as tests/test_cli.py compares runs) and the bundled studies' CSVs in
all three compute modes (in this process, a two-worker LocalCluster with one
tracing thread per chunk, and a scheduler's cluster) are byte-identical.
"""

from __future__ import annotations

import csv
import dataclasses
import os
from pathlib import Path

import pytest

from simulator.config.loader import load_config
from simulator.config.overrides import apply_overrides
from simulator.engine.driver import Engine
from simulator.engine.guide import PILOT_BLOCKS, pilot_chunks
from simulator.pipeline import collect_sensors, load_scene, run
from simulator.scene.model import SensorKind
from simulator.study.trace.distributed import QUIET_CLUSTER

ROOT = Path(__file__).resolve().parent.parent
CONFIGS = ROOT / "configs"
SKIP_CLUSTER = pytest.mark.skipif(os.environ.get("PROBESIM_SKIP_CLUSTER") == "1", reason="PROBESIM_SKIP_CLUSTER=1")


def _office(grids=("middle", "north_wall")):
    """configs/office_bench.toml cut to two of its grids (96 sensors): the plan reads them
    with ``guided`` and the pilot finds the light concentrated (the guide is used). The
    loader has already made each grid's cells sensors (named ``grid[i,j]``), so the cut
    takes both the grids and their cells."""
    cfg = load_config(CONFIGS / "office_bench.toml")
    keep = [g for g in cfg.grids if g.name in grids]
    cells = tuple(f"{g.name}[" for g in keep)
    return dataclasses.replace(cfg, grids=keep, sensors=[s for s in cfg.sensors if s.name.startswith(cells)])


def test_pilot_blocks_depend_on_its_size_alone():
    """Every kernel thread is in one block, blocks are whole chunks but the last,
    there are at most PILOT_BLOCKS, and nothing else enters."""
    for n in (1, 7, 8, 9, 512, 513, 1464, 100_000):
        chunk, blocks = pilot_chunks(n)
        assert blocks <= PILOT_BLOCKS and (blocks - 1) * chunk < n <= blocks * chunk


def test_the_guide_is_the_same_at_1_2_and_3_threads():
    """The pilot's tables (patch ids, CDF, density) on the device are the same bytes
    whatever the CPU thread count, and the guide is used (so they matter)."""
    cfg = _office()
    scene = load_scene(cfg)
    sensors = [s for s in collect_sensors(cfg, scene) if s.kind != SensorKind.PROBE]
    tables = []
    for threads in (1, 2, 3):
        eng = Engine(scene, sensors, threads=threads)
        info = eng.ensure_guide(seed=5)
        g = eng._dev.rec.guide
        assert info.sampled > 0 and max(info.concentration) > 4
        tables.append(tuple(a.numpy().tobytes() for a in (g.ids, g.cdf, g.row_start, g.density)))
    assert tables[0] == tables[1] == tables[2]


def _csv_without_seconds(path: Path) -> list[list[str]]:
    rows = list(csv.reader(path.open()))
    k = rows[0].index("seconds")
    return [r[:k] + r[k + 1 :] for r in rows]


def test_a_guided_config_writes_the_same_csv_at_1_and_2_threads(tmp_path):
    """The office's guided readings are the same bytes at 1 and 2 threads, the
    seconds column aside (before the pilot tallied per worker, they differed
    by up to 0.1%); so are they with the lamps' direct light computed
    (``exact+guided``, whose pilot weighs rays and modelled costs, not seconds)."""
    out = []
    for threads in (1, 2):
        # 96 sensors × 192 samples: more in all than the guide's pilot (16,384), so the run builds its guide
        cfg = apply_overrides(_office(), samples=192, csv=tmp_path / f"t{threads}.csv")
        cfg = dataclasses.replace(cfg, simulation=dataclasses.replace(cfg.simulation, threads=threads))
        res = run(cfg, log=lambda *a: None)
        assert res.record["guide"]["sampled"] > 0
        out.append(_csv_without_seconds(tmp_path / f"t{threads}.csv"))
    assert {r[out[0][0].index("method")] for r in out[0][1:]} & {"guided", "exact+guided"}
    assert out[0] == out[1]


# --------------------------------------------------------------------------- the bundled studies


def _reduced_study(name: str):
    """A bundled study at a fixed budget of 16 samples per sensor, its candidates 2 m
    apart, in blocks of 8 sensors (several chunks per trace group)."""
    from simulator.study.schema import load_study

    study, path = load_study(CONFIGS / "studies" / f"{name}.toml")
    cands = [c.model_copy(update={"spacing_m": 2.0}) for c in study.candidates]
    study = study.model_copy(update={
        "simulation": study.simulation.model_copy(update={"samples": 16, "rel_error": None}),
        "compute": study.compute.model_copy(update={"sensor_block": 8}),
        "candidates": cands,
        "placement": study.placement.model_copy(update={"replicates": 20}),
    })  # fmt: skip
    return study, path


def _study_csvs(name: str, out: Path, **kw):
    """The study's readings.csv and summary.csv as ``write_outputs`` writes them (the same functions,
    kept in memory: the heat maps and report.html that it also draws are pictures of these numbers,
    and drawing them took two thirds of this test's time)."""
    from simulator.study.report.outputs import long_csv, summary_csv
    from simulator.study.runner import run_study

    study, path = _reduced_study(name)
    res = run_study(study, path, out, reference_run=False, **kw)
    return res, long_csv(res).encode(), summary_csv(res).encode()


@pytest.fixture(scope="module")
def scheduler():
    """A two-worker cluster of this machine, reached by its address as a remote one is."""
    pytest.importorskip("distributed")
    from distributed import LocalCluster

    cluster = LocalCluster(n_workers=2, threads_per_worker=1, processes=True, **QUIET_CLUSTER)
    try:
        yield cluster.scheduler_address
    finally:
        cluster.close()


@SKIP_CLUSTER
@pytest.mark.parametrize("name", ["office_study", "office_daylight"])
def test_bundled_studies_are_the_same_bytes_in_all_three_compute_modes(tmp_path, name, scheduler):
    """configs/studies/*.toml (reduced: see _reduced_study) in this process
    (all cores per chunk), on a two-worker LocalCluster (one tracing thread
    per chunk) and on a scheduler's cluster: readings.csv and summary.csv
    are byte-identical."""
    if name == "office_daylight":
        pytest.importorskip("pvlib")
    a, long_a, summ_a = _study_csvs(name, tmp_path / "inprocess", mode="inprocess")
    b, long_b, summ_b = _study_csvs(name, tmp_path / "local", mode="local", workers=2)
    c, long_c, summ_c = _study_csvs(name, tmp_path / "scheduler", scheduler=scheduler)
    assert (a.mode, b.mode, c.mode) == ("inprocess", "local", "scheduler")
    assert a.chunks_total > len(a.trace_groups)  # several chunks per trace group
    assert long_a == long_b == long_c and summ_a == summ_b == summ_c
