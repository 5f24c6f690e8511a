"""The ray tally of image-source connections: counted where they cast a ray, not where they are settled before.

Every path vertex on a stage with a pane or a mirror tries each flat mirror plane's image of
each point and distant light (``kernels.mirrors.image_source``). Most tries end before any ray:
the light lies on the mirror's other side (a sun outside a window, seen from the room), so its
reflection cannot reach the vertex. The tally (``count_rays``: what the split, roulette and hybrid
pilots weigh as each strategy's cost, and ``probesim bench``'s rays) counts a try only once it
casts a ray. On the glazed office the tries settled before any ray had been 4.2 of the 11.5 rays
tallied per indirect path (docs/DESIGN.md §The glazed office: where its cost came from).

The stage (stages/glazing.usda): a zero-angle sun of E⊥ = 1000 lx at the zenith over a clear
pane of ior 1.52 (z = 1 m), nothing else but a datasheet pane beside it in the same plane and
a presence mesh, nothing below. Closed forms (docs/REFERENCES.md §Thin slab): at normal
incidence r = ((n − 1)/(n + 1))², the clear slab transmits T = (1 − r)/(1 + r) = 0.9183 and
reflects R = 2r/(1 + r) = 0.0817.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from simulator.engine.driver import Engine, load_kernels
from simulator.scene.model import Sensor, SensorKind
from simulator.scene.usd import load_stage

ROOT = Path(__file__).resolve().parents[1]
N_GLASS = 1.52
E_SUN_LX = 1000.0
SAMPLES = 256


def _slab_normal(n: float) -> tuple[float, float]:
    """(T, R) of a clear thin slab at normal incidence (docs/REFERENCES.md §Thin slab)."""
    r = ((n - 1.0) / (n + 1.0)) ** 2
    return (1.0 - r) / (1.0 + r), 2.0 * r / (1.0 + r)


@pytest.fixture(scope="module")
def engine():
    load_kernels("cpu")
    scene = load_stage(ROOT / "stages" / "glazing.usda")
    up, down = np.array([0.0, 0.0, 1.0]), np.array([0.0, 0.0, -1.0])
    sensors = [
        Sensor("under_clear", SensorKind.IRRADIANCE, np.array([-10.0, 0.0, 0.0]), up),
        Sensor("over_clear", SensorKind.IRRADIANCE, np.array([-10.0, 0.0, 2.0]), down),
    ]
    return Engine(scene, sensors, threads=1)


#: a path ray within ~4° of the horizon reaches the presence mesh 10–20 m away and makes a vertex there
#: (probability cos²(86°) ≈ 0.5% per sample for a cosine-drawn ray), whose own light sample is one more
#: shadow ray: at most 2% of the samples (a 4σ-wide margin at 256 samples)
GRAZING = 0.02


#: the most the presence mesh (x 5..15 m, z = 1 m) adds to a down-facing receiver 1 m above its
#: plane at x = −10 m: its exitance is at most its coverage 0.3 × E⊥, seen with the view factor of a
#: half-plane from a point facing it, ½(1 − d/√(d² + h²)) = 0.0011 at d = 15 m, h = 1 m: 0.33 lx
MESH_LX = 0.3 * E_SUN_LX * 0.5 * (1.0 - 15.0 / np.sqrt(15.0**2 + 1.0))


def _shadow_rays_per_sample(eng: Engine, sensor: int) -> float:
    r = eng.run("path", samples=SAMPLES, seed=5, sensor_ids=np.array([sensor]), count_rays=2)
    return eng.rays_traced / float(r.samples[sensor])


def test_an_image_settled_before_any_ray_is_not_tallied(engine):
    """Under the pane, facing the sun: each sample casts one shadow ray (the sun through the pane,
    reading E⊥·T = 918.3 lx) and tries the sun's image in the panes' plane, which the sun lights from
    the other side: no ray, none tallied. So 1 shadow ray per sample (it was 2; a few more from grazing
    paths, :data:`GRAZING`), and the
    reading is the slab's closed form (a delta sun: no noise, float32 rounding only, 1e-4)."""
    t, _ = _slab_normal(N_GLASS)
    assert 1.0 <= _shadow_rays_per_sample(engine, 0) <= 1.0 + GRAZING
    r = engine.run("path", samples=SAMPLES, seed=5, sensor_ids=np.array([0]))
    assert r.mean[0, 1] == pytest.approx(E_SUN_LX * t, rel=1e-4)


def test_an_image_that_casts_a_ray_is_tallied(engine):
    """Over the pane, facing down toward it: the sun lies behind the receiver (no light sample to
    trace) and its image in the pane is reached: one ray per sample, tallied (a few more from grazing
    paths, :data:`GRAZING`), reading E⊥·R = 81.7 lx (the slab's reflectance at normal incidence) within
    4σ, plus at most :data:`MESH_LX` from the presence mesh those grazing paths meet."""
    _, refl = _slab_normal(N_GLASS)
    assert 1.0 <= _shadow_rays_per_sample(engine, 1) <= 1.0 + GRAZING
    r = engine.run("path", samples=SAMPLES, seed=5, sensor_ids=np.array([1]))
    dev = r.mean[1, 1] - E_SUN_LX * refl
    tol = 4.0 * r.stderr[1, 1] + 1e-4 * E_SUN_LX * refl  # 4σ and float32 rounding
    assert -tol <= dev <= MESH_LX + tol


def test_the_tally_splits_path_and_shadow_rays(engine):
    """Counting every ray (mode 1) keeps the shadow rays apart (``Engine.shadow_rays_traced``): the same
    samples counted for shadow rays alone (mode 2) give the same number exactly, since counting draws no
    random number; and the path rays, the rest, are at least one per sample (the first direction)."""
    for sensor in (0, 1):
        ids = np.array([sensor])
        r = engine.run("path", samples=SAMPLES, seed=5, sensor_ids=ids, count_rays=True)
        every, shadow = engine.rays_traced, engine.shadow_rays_traced
        engine.run("path", samples=SAMPLES, seed=5, sensor_ids=ids, count_rays=2)
        assert engine.rays_traced == engine.shadow_rays_traced == shadow
        assert every - shadow >= int(r.samples[sensor])
