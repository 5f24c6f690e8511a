"""The command line: bad input is one line and exit 2 with nothing written;
good input writes a reproducible CSV with the documented columns."""

from __future__ import annotations

import csv
import os
import shutil
from pathlib import Path

import pytest

from simulator.commands.cli import main
from simulator.io.results import COLUMNS

ROOT = Path(__file__).resolve().parents[1]

POINT_STAGE = (ROOT / "stages" / "point.usda").read_text()


def _config(tmp_path: Path, stage: str = "stage.usda", sensor: str | None = None) -> Path:
    sensor = sensor or 'kind = "irradiance"\nposition = [0, 0, 0]\nnormal = [0, 0, 1]'
    cfg = tmp_path / "run.toml"
    cfg.write_text(f'stage = "{stage}"\n[simulation]\nsamples = 64\n[[sensor]]\n{sensor}\n[output]\ncsv = "out/run.csv"\n')
    return cfg


def _assert_user_error(capsys, argv, needle: str, tmp_path: Path):
    code = main(argv)
    err = capsys.readouterr().err.strip()
    assert code == 2
    assert err.count("\n") == 0, err  # one line, no traceback
    assert err.startswith("probesim: error:") and needle in err, err
    assert not (tmp_path / "out").exists() or not any((tmp_path / "out").iterdir())


def test_missing_stage(tmp_path, capsys):
    """A config naming a stage that does not exist: the error names the key and the path."""
    cfg = _config(tmp_path, stage="nowhere.usda")
    _assert_user_error(capsys, ["run", str(cfg)], "nowhere.usda", tmp_path)


def test_stage_that_is_not_usd(tmp_path, capsys):
    """A file that is not USD is reported with its path, not a pxr traceback."""
    (tmp_path / "stage.usda").write_text("this is not a USD layer\n")
    _assert_user_error(capsys, ["run", str(_config(tmp_path))], "stage.usda", tmp_path)


def test_unknown_sensor_kind(tmp_path, capsys):
    (tmp_path / "stage.usda").write_text(POINT_STAGE)
    cfg = _config(tmp_path, sensor='kind = "thermometer"\nposition = [0, 0, 0]\nnormal = [0, 0, 1]')
    _assert_user_error(capsys, ["run", str(cfg)], "sensor[0].kind", tmp_path)


def test_zero_length_normal(tmp_path, capsys):
    (tmp_path / "stage.usda").write_text(POINT_STAGE)
    cfg = _config(tmp_path, sensor='kind = "irradiance"\nposition = [0, 0, 0]\nnormal = [0, 0, 0]')
    _assert_user_error(capsys, ["run", str(cfg)], "sensor[0].normal", tmp_path)


def test_nan_in_transform(tmp_path, capsys):
    """A NaN translate on the light: the error names the prim."""
    (tmp_path / "stage.usda").write_text(POINT_STAGE.replace("(0, 0, 3)", "(nan, 0, 3)"))
    _assert_user_error(capsys, ["run", str(_config(tmp_path))], "/World/Point", tmp_path)


def test_negative_intensity(tmp_path, capsys):
    (tmp_path / "stage.usda").write_text(POINT_STAGE.replace("inputs:intensity = 400", "inputs:intensity = -400"))
    _assert_user_error(capsys, ["run", str(_config(tmp_path))], "intensity", tmp_path)


def test_bad_flag_value(tmp_path, capsys):
    (tmp_path / "stage.usda").write_text(POINT_STAGE)
    _assert_user_error(capsys, ["run", str(_config(tmp_path)), "--samples", "0"], "--samples", tmp_path)


def test_cuda_requested_without_cuda(tmp_path, capsys):
    from simulator.engine.driver import cuda_available

    if cuda_available():
        pytest.skip("this machine has CUDA")
    (tmp_path / "stage.usda").write_text(POINT_STAGE)
    _assert_user_error(capsys, ["run", str(_config(tmp_path)), "--device", "cuda"], "cuda", tmp_path)


def test_same_seed_same_bytes_and_columns(tmp_path, capsys):
    """Two runs with one seed write byte-identical CSVs (timing columns aside),
    with the documented header, and leave no temporary files."""
    shutil.copy(ROOT / "stages" / "rect.usda", tmp_path / "stage.usda")
    cfg = _config(
        tmp_path,
        sensor='kind = "irradiance"\nposition = [0, 0, 0]\nnormal = [0, 0, 1]\n'
        '[[sensor]]\nkind = "radiance"\nposition = [0, 0, 0]\ndirection = [0, 0, 1]\nhalf_angle_deg = 3.0',
    )
    out = tmp_path / "out" / "run.csv"
    assert main(["run", str(cfg), "-q", "--seed", "7"]) == 0
    first = list(csv.DictReader(out.open()))
    assert main(["run", str(cfg), "-q", "--seed", "7"]) == 0
    second = list(csv.DictReader(out.open()))
    # the columns of the kinds present (docs/DESIGN.md §The CSV's columns, per kind): no flux, probe or target_met
    assert tuple(first[0].keys()) == (
        "sensor", "kind", "x", "y", "z", "dx", "dy", "dz", "irradiance_W_m2", "irradiance_stderr_W_m2", "illuminance_lx",
        "illuminance_stderr_lx", "radiance_W_m2_sr", "radiance_stderr_W_m2_sr", "luminance_cd_m2",
        "luminance_stderr_cd_m2", "samples", "seconds", "method")
    for a, b in zip(first, second):
        a.pop("seconds"), b.pop("seconds")
        assert a == b
    irr, rad = first
    assert irr["radiance_W_m2_sr"] == "" and rad["irradiance_W_m2"] == ""  # not 0: does not apply
    assert main(["run", str(cfg), "-q", "--seed", "7", "--csv-columns", "full"]) == 0
    full = list(csv.DictReader(out.open()))
    assert tuple(full[0].keys()) == COLUMNS and full[0]["flux_W"] == "" and full[0]["target_met"] == ""
    for a, b in zip(first, full):  # the same cells, by name
        assert all(b[k] == v for k, v in a.items() if k != "seconds")
    assert rad["irradiance_W_m2"] == "" and float(rad["luminance_cd_m2"]) == pytest.approx(1000.0)
    assert sorted(p.name for p in out.parent.iterdir()) == ["run.csv", "run.run.json"]
    umask = os.umask(0)
    os.umask(umask)
    assert out.stat().st_mode & 0o777 == 0o666 & ~umask  # not mkstemp's private 0600
    assert first[0]["method"] == "analytic"  # the plan: nothing blocks the light, a closed form
    # with a Monte Carlo method the seed matters
    assert main(["run", str(cfg), "-q", "--seed", "7", "--method", "light"]) == 0
    mc7 = list(csv.DictReader(out.open()))
    assert main(["run", str(cfg), "-q", "--seed", "8", "--method", "light"]) == 0
    mc8 = list(csv.DictReader(out.open()))
    assert mc8[0]["irradiance_W_m2"] != mc7[0]["irradiance_W_m2"]


def test_output_that_cannot_be_written(tmp_path, capsys):
    """An output path under a regular file cannot be created: one line naming
    the path and why, exit 2, no traceback, said before any tracing."""
    (tmp_path / "stage.usda").write_text(POINT_STAGE)
    (tmp_path / "afile").write_text("not a folder")
    code = main(["run", str(_config(tmp_path)), "-q", "-o", str(tmp_path / "afile" / "x.csv")])
    err = capsys.readouterr().err.strip()
    assert code == 2 and err.count("\n") == 0
    assert err == f"probesim: error: {tmp_path / 'afile'}: cannot make the output folder: a file of that name is in the way"
