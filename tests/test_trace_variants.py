"""Trace variants: the kernels compiled without the surface model for all-matte stages.

The estimator and probe kernels exist twice (``kernels.estimators.make_trace``,
``kernels.probe.make_probe_kernel``): with the surface model (panes, cut-outs,
glossy faces) and without it. The engine picks one from ``SceneRec.surfaces``.
The full variant still tests ``scene.surfaces`` at run time, so on an all-matte
stage it takes the same branches, makes the same draws and does the same
float operations in the same order as the matte one: the readings must agree
to the last bit (no tolerance), for every sensor kind, method and the probe
kernel. Which variant a stage gets is read from the engine.
"""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

from simulator.engine import kernel_modules as KM
from simulator.engine.driver import Engine
from simulator.kernels import estimators as K
from simulator.kernels import probe as KP
from simulator.scene.model import Sensor, SensorKind
from simulator.scene.usd import load_stage

ROOT = Path(__file__).resolve().parents[1]


def quickstart_sensors() -> list[Sensor]:
    """One sensor of every kind the estimator kernel reads, in the quickstart room (5 × 4 m)."""
    p = np.array([2.5, 2.0, 0.8])
    z, x = np.array([0.0, 0.0, 1.0]), np.array([1.0, 0.0, 0.0])
    return [
        Sensor("irr", SensorKind.IRRADIANCE, p, z),
        Sensor("rad", SensorKind.RADIANCE, np.array([1.0, 1.0, 1.6]), np.array([0.4, 0.3, -0.8]) / np.sqrt(0.89),
               half_angle=0.03),
        Sensor("patch", SensorKind.PATCH, np.array([2.5, 3.99, 1.6]), np.array([0.0, -1.0, 0.0]), up=z, size=(1.0, 1.0)),
        Sensor("cyl", SensorKind.CYLINDRICAL, p, x, up=z),
        Sensor("semi", SensorKind.SEMICYLINDRICAL, p, x, up=z),
    ]


@pytest.fixture(scope="module")
def quickstart():
    return load_stage(ROOT / "stages" / "quickstart.usda")


def test_all_matte_stage_gets_the_matte_kernels(quickstart):
    engine = Engine(quickstart, quickstart_sensors()[:1])
    assert engine.scene_rec.surfaces == 0
    assert engine.trace_variant is K.make_trace(False) and not engine.trace_variant.surfaces
    assert KP.probe_kernel_for(engine.scene_rec.surfaces) is KP.make_probe_kernel(False)


@pytest.mark.parametrize("name", ["glazing", "cutout", "mirror_reflector"])
def test_stage_with_surfaces_gets_the_full_kernels(name):
    """A pane (glazing), a cut-out (cutout) or glossy metal (mirror_reflector): the surface model compiled in."""
    scene = load_stage(ROOT / "stages" / f"{name}.usda")
    engine = Engine(scene, [Sensor("s", SensorKind.IRRADIANCE, np.zeros(3), np.array([0.0, 0.0, 1.0]))])
    assert engine.scene_rec.surfaces == 1
    assert engine.trace_variant is K.make_trace(True) and engine.trace_variant.surfaces
    assert KP.probe_kernel_for(engine.scene_rec.surfaces) is KP.make_probe_kernel(True)


def test_variants_are_built_once_and_apart():
    """A variant's module holds its estimator, piece-table and probe kernels once the engine's way of
    loading it (``kernel_modules.trace_module``) has built it; the two variants are distinct, and asking
    for one again returns the same kernels (Warp's cache then serves them)."""
    for flag in (False, True):
        module = KM.trace_module(flag).module
        t = K.trace_for(int(flag))
        assert K.make_trace(flag) is t and t.surfaces == flag
        assert KP.probe_kernel_for(int(flag)) is KP.make_probe_kernel(flag)
        assert {k.key for k in module._get_live_kernels()} == {
            t.estimate_kernel.key, t.piece_table_kernel.key, KP.make_probe_kernel(flag).key}
    assert K.trace_for(0).estimate_kernel is not K.trace_for(1).estimate_kernel
    assert KP.make_probe_kernel(False) is not KP.make_probe_kernel(True)


def _full_kernels(monkeypatch):
    """Make every engine launch the full variant, whatever the stage."""
    full = K.trace_for(1)
    monkeypatch.setattr(K, "trace_for", lambda surfaces: full)
    monkeypatch.setattr(KP, "probe_kernel_for", lambda surfaces: KP.make_probe_kernel(True))


@pytest.mark.parametrize("method", ["path", "guided", "mis"])
def test_full_kernels_give_the_same_bits_on_a_matte_stage(quickstart, monkeypatch, method):
    """Every sensor kind, with the guide (guided) and with MIS: mean and standard error bit for bit."""
    sensors = quickstart_sensors()
    matte = Engine(quickstart, sensors).run(method, samples=48, seed=11)
    assert not Engine(quickstart, sensors).trace_variant.surfaces
    _full_kernels(monkeypatch)
    engine = Engine(quickstart, sensors)
    assert engine.trace_variant.surfaces
    full = engine.run(method, samples=48, seed=11)
    assert np.all(matte.mean > 0.0)  # every sensor read light: the comparison is not of zeros
    np.testing.assert_array_equal(full.mean, matte.mean)
    np.testing.assert_array_equal(full.stderr, matte.stderr)


def test_full_probe_kernel_gives_the_same_bits_on_a_matte_stage(quickstart, monkeypatch):
    probe = [Sensor("p", SensorKind.PROBE, np.array([2.5, 2.0, 1.6]), np.array([0.0, 0.0, 1.0]), resolution=(8, 4))]
    (matte,) = Engine(quickstart, []).run_probes(probe, "path", samples=256, seed=3)
    _full_kernels(monkeypatch)
    (full,) = Engine(quickstart, []).run_probes(probe, "path", samples=256, seed=3)
    assert np.all(matte.integrals[0] > 0.0)
    np.testing.assert_array_equal(full.radiance, matte.radiance)
    np.testing.assert_array_equal(full.integrals, matte.integrals)
    np.testing.assert_array_equal(full.delta, matte.delta)


ORDER = """
import sys
from simulator.engine import kernel_modules as KM
for flag in sys.argv[1:]:
    KM.trace_module(flag == "1")
print(KM.trace_module(False).module.get_module_hash(1).hex())
"""


def test_a_variants_hash_does_not_depend_on_the_other():
    """Each variant is built on first use: the all-matte module's hash (what finds its object file in
    Warp's cache) is the same whether the full variant was built before it, after it or not at all."""
    env = dict(os.environ, PYTHONPATH=os.pathsep.join([str(ROOT), os.environ.get("PYTHONPATH", "")]))
    hashes = {subprocess.run([sys.executable, "-c", ORDER, *order], env=env, capture_output=True, text=True,
                             check=True).stdout.strip() for order in (["0"], ["1", "0"], ["0", "1"])}  # fmt: skip
    assert len(hashes) == 1


def test_asking_for_a_variants_module_again_keeps_its_hash():
    """The engine asks for its variant's module at each load (the trace, then a probe's): its options are
    set once, so asking again does not make Warp hash the module again."""
    module = KM.trace_module(False).module
    module.get_module_hash(1)
    hasher = module.hashers[1]
    assert KM.trace_module(False).module.hashers.get(1) is hasher
