"""pxr's own diagnostics are summarised in the stage's one summary line, not printed on stderr.

OpenUSD prints a ``Warning: in _ReportErrors at line ... of stage.cpp -- ...``
line per unresolved reference (each unopened ``.mtlx`` among them: usd-core
has no MaterialX file format). The reader catches them while it opens and
reads the stage, and its summary line counts them with the first message.
"""

from __future__ import annotations

from pathlib import Path

import pytest

from simulator.commands.cli import main
from simulator.errors import UserError
from simulator.scene.usd import load_stage

STAGE = '''#usda 1.0
(
    metersPerUnit = 1
    upAxis = "Z"
)
def Material "Wood" (
    prepend references = @./wood.mtlx@</MaterialX/Materials/Wood>
)
{
}
def Material "Steel" (
    prepend references = @./steel.mtlx@</MaterialX/Materials/Steel>
)
{
}
def Xform "Props" (
    prepend references = @./props.usda@
)
{
}
def SphereLight "L"
{
    float inputs:intensity = 100
    double3 xformOp:translate = (0, 0, 2)
    uniform token[] xformOpOrder = ["xformOp:translate"]
}
'''


def _stage(tmp_path: Path) -> Path:
    (tmp_path / "wood.mtlx").write_text('<?xml version="1.0"?>\n<materialx version="1.38"></materialx>\n')
    p = tmp_path / "s.usda"
    p.write_text(STAGE)
    return p


def test_unopened_references_are_one_summary_line_and_nothing_raw_on_stderr(tmp_path, capfd):
    s = load_stage(_stage(tmp_path))
    err = capfd.readouterr().err
    assert "Warning:" not in err and "stage.cpp" not in err, err
    lines = [w for w in s.warnings if "composition error" in w]
    assert len(lines) == 1, s.warnings
    # wood.mtlx exists: the MaterialX reader opens it itself, so only the missing steel.mtlx and
    # props.usda are composition errors
    assert lines[0].startswith("s.usda: 2 composition errors (first: ") and ("steel.mtlx" in lines[0] or "props.usda" in lines[0])


def test_probesim_run_prints_one_summary_line(tmp_path, capfd):
    _stage(tmp_path)
    (tmp_path / "c.toml").write_text('stage = "s.usda"\n[simulation]\nsamples = 16\n[[sensor]]\nname = "a"\n'
                                     'kind = "irradiance"\nposition = [0, 0, 0]\nnormal = [0, 0, 1]\n')
    assert main(["run", str(tmp_path / "c.toml"), "-q"]) == 0
    err = capfd.readouterr().err.splitlines()
    assert not [line for line in err if line.startswith(("Warning:", "Coding Error:", "Runtime Error:"))], err
    assert len([line for line in err if "composition error" in line]) == 1, err


def test_other_pxr_diagnostics_are_counted_with_the_first(tmp_path, capfd):
    """A binding without MaterialBindingAPI makes pxr warn (it still honours it): counted, not printed."""
    p = tmp_path / "b.usda"
    p.write_text('''#usda 1.0
(
    metersPerUnit = 1
    upAxis = "Z"
)
def Mesh "T"
{
    int[] faceVertexCounts = [3]
    int[] faceVertexIndices = [0, 1, 2]
    point3f[] points = [(0, 0, 0), (1, 0, 0), (0, 1, 0)]
    rel material:binding = </M>
}
def Material "M"
{
    token outputs:surface.connect = </M/S.outputs:surface>
    def Shader "S"
    {
        uniform token info:id = "UsdPreviewSurface"
        color3f inputs:diffuseColor = (0.4, 0.4, 0.4)
        token outputs:surface
    }
}
''')
    s = load_stage(p)
    assert "MaterialBindingAPI" not in capfd.readouterr().err
    assert s.geometry.albedo.tolist() == [pytest.approx(0.4)]
    (line,) = [w for w in s.warnings if "pxr diagnostic" in w]
    assert line.startswith("b.usda: 1 pxr diagnostic (first: Found material bindings on prim at path (/T)"), line


def test_a_read_that_fails_leaves_nothing_on_stderr_but_its_error(tmp_path, capfd):
    """An error inside the scope (a negative light intensity) drops what pxr said: one line is all."""
    p = _stage(tmp_path)
    p.write_text(STAGE.replace("float inputs:intensity = 100", "float inputs:intensity = -1"))
    with pytest.raises(UserError):
        load_stage(p)
    assert "Warning:" not in capfd.readouterr().err
