"""Fixtures that several test files share, so that an expensive run is made once per pytest run, and
the test run's own cache folder (``PROBESIM_CACHE_PATH``).

- ``office_guided``: the office's 1,464 guided readings against the stored
  reference, checked by tests/test_guide.py (the guide), tests/test_split.py
  (the split) and tests/test_patch_pick.py (the per-patch light pick): the
  same engine configuration, so one run at the largest budget any of them
  used serves all three (it was three runs, at 512, 128 and 256 samples).
"""

from __future__ import annotations

import atexit
import csv
import os
import shutil
import tempfile
from dataclasses import dataclass
from pathlib import Path

import numpy as np
import pytest

CONFIGS = Path(__file__).resolve().parents[1] / "configs"

# What probesim keeps across processes (stage readings, Warp module hashes: simulator.cache_path) goes
# to a folder of the test run's own, removed at exit, never to the user's cache; the processes the
# tests start inherit it. Tests of those caches set a folder of their own.
_CACHE = tempfile.mkdtemp(prefix="probesim-test-cache-")
os.environ["PROBESIM_CACHE_PATH"] = _CACHE
atexit.register(shutil.rmtree, _CACHE, ignore_errors=True)


@dataclass(frozen=True)
class OfficeGuided:
    """One guided run of configs/office_bench.toml and what its engine reported.

    Attributes
    ----------
    scene, sensors, light_mask
        The stage, its 1,464 irradiance sensors (probes left out) and the auto plan's light mask.
    result : RunResult
        ``mean`` and ``stderr`` of shape (1464, 2): W/m² and lx.
    reference_lx, reference_stderr_lx : ndarray, shape (1464,)
        configs/references/office_bench.csv (pooled ``path`` runs) for the same sensors.
    guide_sampled : int
    guide_concentration : float
        The largest concentration of the pilot-learnt guide (≫ 4: the guide is used).
    split_k : int
        Indirect paths per sample the split rule chose.
    patch_pick : int
        ``SceneRec.n_patch_pick``: 1 where the light pick's factors are per surface patch.
    """

    scene: object
    sensors: list
    light_mask: object
    result: object
    reference_lx: np.ndarray
    reference_stderr_lx: np.ndarray
    guide_sampled: int
    guide_concentration: float
    split_k: int
    patch_pick: int


#: the shared run's budget and seed (the budget tests/test_guide.py has always used)
OFFICE_GUIDED_SAMPLES = 512
OFFICE_GUIDED_SEED = 2024


def office_sensors():
    """configs/office_bench.toml's scene and its irradiance sensors (probes left out)."""
    from simulator.config.loader import load_config
    from simulator.pipeline import collect_sensors, load_scene
    from simulator.scene.model import SensorKind

    cfg = load_config(CONFIGS / "office_bench.toml")
    scene = load_scene(cfg)
    return scene, [s for s in collect_sensors(cfg, scene) if s.kind != SensorKind.PROBE]


@pytest.fixture(scope="package")  # the tests folder: read once for every test file that asks
def office_guided() -> OfficeGuided:
    """The office read with ``guided`` (guide, split rule and per-patch pick as a run has them),
    the auto plan's light mask, 512 samples, seed 2024."""
    from simulator.engine.driver import Engine
    from simulator.plan.planner import make_plan

    scene, sensors = office_sensors()
    mask = make_plan(scene, sensors, "auto").light_mask([l.name for l in scene.lights])
    engine = Engine(scene, sensors)
    engine.set_light_mask(mask)
    result = engine.run("guided", samples=OFFICE_GUIDED_SAMPLES, seed=OFFICE_GUIDED_SEED)
    ref = {r["sensor"]: (float(r["illuminance_lx"]), float(r["illuminance_stderr_lx"]))
           for r in csv.DictReader((CONFIGS / "references" / "office_bench.csv").open())}  # fmt: skip
    return OfficeGuided(
        scene=scene,
        sensors=sensors,
        light_mask=mask,
        result=result,
        reference_lx=np.array([ref[s.name][0] for s in sensors]),
        reference_stderr_lx=np.array([ref[s.name][1] for s in sensors]),
        guide_sampled=int(engine.guide.sampled),
        guide_concentration=float(max(engine.guide.concentration)),
        split_k=int(engine.split_pilot["k"]),
        patch_pick=int(engine._dev.rec.n_patch_pick),
    )
