"""The report's luminaire schedule: each light's emitted lumens from the stage's emission, against closed forms.

Φ = π·A·L for a one-sided Lambertian rect or disc of area A and luminance L, 4π²r²·L for a sphere light,
4π·I for an isotropic point light, 2π(1 − cos θc)·I for a point light cut to a cone of half-angle θc, and
π·(2πrℓ)·L for a cylinder (radiometry of Lambertian emitters: e.g. McCluney, Introduction to Radiometry and
Photometry, §2; the cone is the solid angle of a spherical cap)."""

import math
from pathlib import Path

import numpy as np
import pytest

from simulator.scene.model import Light, LightKind, LightShaping
from simulator.study.report.luminaires import emitted, luminaire_schedule

ROOT = Path(__file__).resolve().parents[1]


def _light(kind, emission=(1.0, 1000.0), **kw):
    return Light(name=f"/L/{kind.name}", kind=kind, position=np.zeros(3), frame=np.eye(3), emission=emission, **kw)


def test_unshaped_lights_emit_their_closed_forms():
    L, I = 4000.0, 250.0
    assert emitted(_light(LightKind.RECT, (1.0, L), width=1.2, height=0.3))[1] == pytest.approx(math.pi * 0.36 * L, rel=1e-12)
    assert emitted(_light(LightKind.DISK, (1.0, L), radius=0.1))[1] == pytest.approx(math.pi * math.pi * 0.01 * L, rel=1e-12)
    assert emitted(_light(LightKind.SPHERE, (1.0, L), radius=0.05))[1] == pytest.approx(4 * math.pi**2 * 0.0025 * L, rel=1e-12)
    assert emitted(_light(LightKind.POINT, (1.0, I)))[1] == pytest.approx(4 * math.pi * I, rel=1e-12)
    assert emitted(_light(LightKind.CYLINDER, (1.0, L), radius=0.013, length=1.2))[1] == pytest.approx(
        math.pi * 2 * math.pi * 0.013 * 1.2 * L, rel=1e-12)  # fmt: skip
    w, lm = emitted(_light(LightKind.RECT, (2.5, 1000.0), width=1.0, height=1.0))
    assert w == pytest.approx(math.pi * 2.5, rel=1e-12) and lm == pytest.approx(math.pi * 1000.0, rel=1e-12)
    assert all(math.isnan(x) for x in emitted(_light(LightKind.DOME)))


def test_a_shaped_point_light_emits_its_cone_and_an_unshaped_shaping_keeps_a_panels_lumens():
    I, cone = 1000.0, math.radians(30.0)
    lm = emitted(_light(LightKind.POINT, (1.0, I), shaping=LightShaping(cone_angle_rad=cone)))[1]
    truth = 2 * math.pi * (1 - math.cos(cone)) * I
    # a hard cone's edge is a break of the Gauss-Legendre segments: exact to rounding
    assert lm == pytest.approx(truth, rel=1e-9)
    # a rect light with the default shaping (cone 90°, no focus) is still Lambertian: π·A·L
    lm = emitted(_light(LightKind.RECT, (1.0, 4000.0), width=0.6, height=0.6, shaping=LightShaping()))[1]
    assert lm == pytest.approx(math.pi * 0.36 * 4000.0, rel=1e-9)


def test_the_office_schedule_lists_its_six_panels():
    """stages/office.usda: two rows of three 1.2 × 0.3 m panels at 4000 cd/m², π·0.36·4000 = 4,524 lm each."""
    from simulator.scene.usd import load_stage

    rows = luminaire_schedule(load_stage(ROOT / "stages" / "office.usda"))
    assert len(rows) == 1
    r = rows[0]
    assert r.count == 6 and r.kind.startswith("rectangular panel 1.20 × 0.30 m") and r.ies == ""
    assert r.lumens == pytest.approx(math.pi * 1.2 * 0.3 * 4000.0, rel=1e-9)
