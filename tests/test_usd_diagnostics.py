"""pxr's own diagnostics are summarised in the stage's one summary line, not printed on stderr.

OpenUSD prints a ``Warning: in _ReportErrors at line ... of stage.cpp -- ...``
line per unresolved reference (each unopened ``.mtlx`` among them: usd-core
has no MaterialX file format). The reader catches them while it opens and
reads the stage, and its summary line counts them with the first message.
"""

from __future__ import annotations

from pathlib import Path

from pxr import Tf

from simulator.commands.cli import main
from simulator.scene.usd import load_stage
from simulator.scene.usd.diagnostics import PxrDiagnostics

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
    assert lines[0].startswith("s.usda: 3 composition errors (first: ") and "wood.mtlx" in lines[0]


def test_probesim_run_prints_one_summary_line(tmp_path, capfd):
    _stage(tmp_path)
    (tmp_path / "c.toml").write_text('stage = "s.usda"\n[simulation]\nsamples = 16\n[[sensor]]\nname = "a"\n'
                                     'kind = "irradiance"\nposition = [0, 0, 0]\nnormal = [0, 0, 1]\n')
    assert main(["run", str(tmp_path / "c.toml"), "-q"]) == 0
    err = capfd.readouterr().err.splitlines()
    assert not [line for line in err if line.startswith(("Warning:", "Coding Error:", "Runtime Error:"))], err
    assert len([line for line in err if "composition error" in line]) == 1, err


def test_other_pxr_diagnostics_are_counted_with_the_first(capfd):
    """A Tf warning posted inside the scope is held, handed over by collect(), and not printed."""
    with PxrDiagnostics() as caught:
        Tf.Warn("first thing pxr says")
        Tf.Warn("second thing")
        got = caught.collect()
        Tf.Warn("not collected: dropped with the scope")
    assert got == ["first thing pxr says", "second thing"]
    assert "thing" not in capfd.readouterr().err
