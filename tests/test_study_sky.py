"""A study whose sky is split into Tregenza patches: CIE skies as recombinations of daylight coefficients."""

import importlib.util
import math
from pathlib import Path

import numpy as np
import pytest

from simulator.errors import UserError
from simulator.study.trace.groups import patch_names
from simulator.study.runner import run_study
from simulator.study.schema import load_study
from simulator.study.inputs import sky_patches as sp

_spec = importlib.util.spec_from_file_location("_study_tiny", Path(__file__).with_name("test_study_resume.py"))
_tiny = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(_tiny)

SKY = _tiny.TINY.replace('name = "sky"\nlights = ["/Office/Sky"]', 'name = "sky"\nlights = ["/Office/Sky"]\nsky = "tregenza"').replace(
    'method = "light"', 'method = "path"') + '''
[[scenario]]
name = "cie_overcast"
levels = { sky = 1.0 }
sky = { group = "sky", cie = "overcast", horizontal_lx = 10000 }
[[scenario]]
name = "cie_clear"
levels = { sky = 0.5 }
sky = { group = "sky", cie = 12, sun = { azimuth_deg = 250, elevation_deg = 30 } }
'''


def _study(tmp_path, text=SKY):
    p = tmp_path / "sky_study.toml"
    p.write_text(text)
    return load_study(p)


def test_cie_skies_are_recombinations_of_one_trace(tmp_path):
    """The split sky is traced once for the uniform sky (levels sky = 1), the CIE overcast and the CIE
    clear sky (no sun group lit, so no second trace): the three sky scenarios are one trace group
    with the corridor row (the ``overcast`` scenario lights both). Each sky scenario's patch levels
    are L_p/L_dome times the group's level: the overcast sky scaled to 10 klx unobstructed
    horizontal illuminance, Σ_p d_p ∫_p cosθ dω·L_dome = 10000 lx (1e-9), and the clear sky at
    level 0.5 has as much horizontal light as half the authored dome, Σ_p d_p ∫cos = π/2 (1e-9).
    Readings are finite and positive on the work plane, with a finite standard error."""
    study, p = _study(tmp_path)
    res = run_study(study, p, tmp_path / "out", reference_run=False, mode="inprocess")
    names = [s.name for s in res.scenarios]
    assert len(res.trace_groups) == 1
    proj = np.array([sp.patch_projected_solid_angle(k) for k in range(145)])
    names_p = patch_names("sky")
    ov = res.scenarios[names.index("cie_overcast")]
    d = np.array([ov.levels[n] for n in names_p[:145]])
    from simulator.scene.usd import load_stage

    dome = next(l for l in load_stage(_tiny.STAGE, light_units="photometric").lights if l.name == "/Office/Sky")
    assert abs(float(d @ proj) * dome.emission[1] / 10000.0 - 1.0) < 1e-9
    assert ov.levels["sky/ground"] == 0.0
    cl = res.scenarios[names.index("cie_clear")]
    assert abs(float(np.array([cl.levels[n] for n in names_p[:145]]) @ proj) / (math.pi / 2) - 1.0) < 1e-9
    assert "CIE sky type 12" in cl.notes[0] and "azimuth 250.0" in cl.notes[0]
    wp = np.array([i for i, c in enumerate(res.candidates) if c.set_name == "wp"])
    for j in (names.index("cie_overcast"), names.index("cie_clear")):
        assert np.all(res.mean[j, wp, 1] > 0) and np.all(np.isfinite(res.stderr[j, wp, 1]))


def test_the_uniform_sky_on_a_split_group_agrees_with_the_unsplit_study(tmp_path):
    """``levels = { sky = 1.0, corridor_row = 0.5 }`` on the split sky (every patch and the ground at 1)
    and on the plain sky group read the same light from the same samples: the trace key and so the
    chunk seeds are the same, and the tallies change no sample. So the two studies' readings agree
    to float32 rounding of the per-slot sums (1e-5 relative) and their standard errors (batch means
    against per-sample co-moments, 2 batches of 32 samples here) are both finite and positive."""
    study, p = _study(tmp_path)
    split = run_study(study, p, tmp_path / "a", reference_run=False, mode="inprocess")
    plain_text = SKY.replace('\nsky = "tregenza"', "").split("[[scenario]]\nname = \"cie_overcast\"")[0]
    study2, p2 = _study(tmp_path, plain_text)
    plain = run_study(study2, p2, tmp_path / "b", reference_run=False, mode="inprocess")
    j1 = [s.name for s in split.scenarios].index("overcast")
    j2 = [s.name for s in plain.scenarios].index("overcast")
    m1, m2 = split.mean[j1, :, 1], plain.mean[j2, :, 1]
    assert np.all(np.abs(m1 - m2) <= 1e-5 * np.abs(m2))
    assert np.all(np.isfinite(split.stderr[j1]) & (split.stderr[j1] > 0)) and np.all(plain.stderr[j2] > 0)


@pytest.mark.parametrize("old, new, message", [
    ('sky = { group = "sky", cie = "overcast"', 'sky = { group = "corridor_row", cie = "overcast"',
     "scenario[2].sky.group: no [[group]] named 'corridor_row' with sky = \"tregenza\""),
    ('lights = ["/Office/Sky"]\nsky = "tregenza"', 'lights = ["/Office/Sky", "/Office/Sun"]\nsky = "tregenza"',
     "must hold exactly one DomeLight"),
    ("cie = 12", "cie = 16", "scenario[3].sky.cie"),
])  # fmt: skip
def test_sky_mistakes_are_one_line(tmp_path, old, new, message):
    assert old in SKY
    with pytest.raises(UserError, match=None) as e:
        study, p = _study(tmp_path, SKY.replace(old, new, 1))
        run_study(study, p, tmp_path / "out", reference_run=False, mode="inprocess")
    assert message in str(e.value) and "\n" not in str(e.value)


def test_the_bundled_daylight_study_is_one_trace():
    """configs/studies/office_daylight.toml: 8 scenarios (CIE overcast, two clear skies with the sun
    from pvlib for Munich on 21 March at 09:00 and 16:00, the overcast sky with the rows dimmed, the
    authored dome) over a split sky and the rows, all in one trace group (the skies' suns shape the
    sky only). The morning sun is in the east (azimuth 90°–150°) and the afternoon one in the west
    (210°–270°), both above the horizon."""
    pytest.importorskip("pvlib")
    from simulator.scene.usd import load_stage
    from simulator.study.inputs.scenarios import check_split_groups, expand_scenarios, resolve_groups, trace_groups_of

    study, path = load_study(Path(__file__).resolve().parent.parent / "configs" / "studies" / "office_daylight.toml")
    scene = load_stage(path.parent / study.stage, light_units="photometric", radiometric_spectrum="E")
    groups, _ = resolve_groups(scene, study.group, str(path))
    assert check_split_groups(scene, study.group, groups, str(path)) == ("sky",)
    scen = expand_scenarios(study.scenario, list(groups), str(path), scene=scene, groups=groups)
    assert len(scen) == 8 and len(trace_groups_of(scen, scene, groups, str(path))) == 1
    import re

    az = {s.name: float(re.search(r"azimuth ([0-9.]+)", s.notes[0]).group(1)) for s in scen if s.name.startswith("clear")}
    assert 90 < az["clear_morning"] < 150 and 210 < az["clear_afternoon"] < 270


@pytest.mark.parametrize("old, new, key", [
    ("samples = 64", "samples = 1", "simulation.samples"),
    ("samples = 64", "samples = 64\nrel_error = 0.05\nmax_samples = 32", "simulation.max_samples"),
])  # fmt: skip
def test_a_patch_sky_needs_two_batches_for_its_errors(tmp_path, old, new, key):
    """A sky split into patches estimates its covariance from batch means over
    B − 1 degrees of freedom: one sample per sensor (a fixed budget under two
    blocks is cut into smaller batches, but one sample is one batch), or an
    adaptive run capped at one block of 32, leaves every error of the year
    undefined, so the study is refused in one line naming the key, and
    nothing is written."""
    assert old in SKY
    with pytest.raises(UserError) as e:
        study, p = _study(tmp_path, SKY.replace(old, new, 1))
        run_study(study, p, tmp_path / "out", reference_run=False, mode="inprocess")
    assert f"{key}: a sky split into patches" in str(e.value) and "\n" not in str(e.value)
    assert not (tmp_path / "out").exists()


def test_the_schemas_block_is_the_engines():
    """The schema's batch size names the engine's kernel block (a batch of the patches' covariance)."""
    from simulator.engine.driver import BLOCK
    from simulator.study.schema import SAMPLES_PER_BLOCK

    assert SAMPLES_PER_BLOCK == BLOCK
