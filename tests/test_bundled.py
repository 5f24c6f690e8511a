"""The bundled stages and configs: found from anywhere, complete in a build,
and copied out by ``probesim example`` into a folder that runs on its own."""

from __future__ import annotations

import csv
import subprocess
import sys
import tomllib
from pathlib import Path

import pytest

from simulator import bundled
from simulator.commands.cli import main
from simulator.commands.example import copy_example, example_files, list_examples
from simulator.config import load_config
from simulator.errors import UserError

ROOT = Path(__file__).resolve().parents[1]
CONFIGS = sorted(p.stem for p in (ROOT / "configs").glob("*.toml"))
STUDIES = sorted(p.stem for p in (ROOT / "configs" / "studies").glob("*.toml"))


def test_checkout_data_is_found_from_any_working_directory(tmp_path, monkeypatch):
    """In a checkout the data is the checkout's own folders, whatever the
    working directory (here an empty temporary one, and one with a decoy
    ``configs/`` that must not be used)."""
    monkeypatch.chdir(tmp_path)
    (tmp_path / "configs").mkdir()
    assert bundled.data_root() == ROOT
    assert bundled.configs_dir() == ROOT / "configs"
    assert bundled.configs_dir("stability") == ROOT / "configs" / "stability"
    assert bundled.stages_dir() == ROOT / "stages"
    assert bundled.example_names() == CONFIGS + STUDIES


def test_installed_copy_wins_and_missing_data_is_one_line(tmp_path, monkeypatch):
    """An installed copy (``simulator/_data``) is preferred; with neither it
    nor a checkout the error is a UserError naming both places."""
    inst = tmp_path / "_data"
    (inst / "configs").mkdir(parents=True)
    (inst / "stages").mkdir()
    monkeypatch.setattr(bundled, "_INSTALLED", inst)
    assert bundled.data_root() == inst
    monkeypatch.setattr(bundled, "_INSTALLED", tmp_path / "none")
    monkeypatch.setattr(bundled, "_CHECKOUT", tmp_path / "nothing")
    with pytest.raises(UserError, match="missing from this installation"):
        bundled.configs_dir(command="verify")


def test_every_config_stage_lies_in_the_bundled_stages():
    """Each bundled config's relative stage path resolves inside ``stages/``,
    so it resolves the same way in the installed copy (folders side by side)."""
    stages = (ROOT / "stages").resolve()
    for cfg in sorted((ROOT / "configs").rglob("*.toml")):
        stage = (cfg.parent / tomllib.loads(cfg.read_text())["stage"]).resolve()
        assert stage.is_file() and stage.is_relative_to(stages), cfg


def test_build_step_copies_the_data_into_the_package(tmp_path):
    """``setup.py build_py`` (the step a wheel is built from) puts stages,
    textures and configs in ``simulator/_data``; a package imported from that
    build finds them there, from another working directory."""
    lib = tmp_path / "lib"
    subprocess.run([sys.executable, "setup.py", "-q", "build_py", "--build-lib", str(lib)],
                   cwd=ROOT, check=True, capture_output=True)  # fmt: skip
    data = lib / "simulator" / "_data"
    for rel in ("configs/quickstart.toml", "configs/stability/leak.toml", "stages/quickstart.usda",
                "stages/stability/leak.usda", "stages/textures/cie_overcast_64x32.exr"):
        assert (data / rel).read_bytes() == (ROOT / rel).read_bytes(), rel
    probe = ("import simulator.bundled as b; from simulator.commands.example import example_files; "
             "print(b.data_root()); print(sorted(example_files('cie_overcast')[1].values())[-1])")
    out = subprocess.run([sys.executable, "-c", probe], cwd=tmp_path, env={"PYTHONPATH": str(lib)},
                         check=True, capture_output=True, text=True).stdout.split("\n")  # fmt: skip
    assert Path(out[0]) == data.resolve()
    assert out[1] == "stages/textures/cie_overcast_64x32.exr"


@pytest.mark.parametrize("name", CONFIGS)
def test_every_example_copies_to_a_config_that_loads(tmp_path, name):
    """Each example's copy loads as a config whose stage and output lie inside
    the folder, and every file its stage names (asset paths) was copied."""
    written = copy_example(name, tmp_path / "ex")
    cfg = load_config(written[0])
    assert cfg.stage.is_relative_to(tmp_path / "ex") and cfg.stage.is_file()
    assert cfg.output.csv.is_relative_to(tmp_path / "ex")
    _, files = example_files(name)
    assert sorted(written[1:]) == sorted(tmp_path / "ex" / rel for rel in files.values())


def test_example_command_runs_from_elsewhere(tmp_path, monkeypatch, capsys):
    """``probesim example point DIR`` then ``probesim run DIR/point.toml`` from
    another directory: the point source of 100 cd, 3 m above the ``below``
    receiver, gives E = I/d² = 100/9 lx (exact: a delta light)."""
    monkeypatch.chdir(tmp_path)
    assert main(["example", "point", "copy"]) == 0
    assert "probesim run copy/point.toml" in capsys.readouterr().out
    (tmp_path / "elsewhere").mkdir()
    monkeypatch.chdir(tmp_path / "elsewhere")
    assert main(["run", str(tmp_path / "copy" / "point.toml"), "-q"]) == 0
    rows = {r["sensor"]: r for r in csv.DictReader((tmp_path / "copy" / "out" / "point.csv").open())}
    assert float(rows["below"]["illuminance_lx"]) == pytest.approx(100.0 / 9.0, rel=1e-6)
    capsys.readouterr()
    assert main(["example", "--list"]) == 0
    listed = capsys.readouterr().out.splitlines()
    assert [line.split()[0] for line in listed] == CONFIGS + STUDIES
    assert dict(list_examples())["floor_grid"] == "rect.usda"
    kinds = {line.split()[0]: line.split(None, 2)[2] for line in listed}
    assert kinds["point"] == "run"
    assert (kinds["office_study"], kinds["office_daylight"], kinds["office_annual"]) == (
        "study: placement", "study: daylight", "study: annual")


@pytest.mark.parametrize("name", STUDIES)
def test_every_study_copies_to_a_study_that_loads(tmp_path, name, capsys):
    """A bundled study file copies out (``probesim example office_study DIR``) to a study whose stage,
    weather file and output folder lie inside DIR, and the command says to run it with ``probesim study``."""
    from simulator.study.schema import load_study

    dest = tmp_path / "ex"
    assert main(["example", name, str(dest)]) == 0
    assert f"probesim study {dest / (name + '.toml')}" in capsys.readouterr().out
    study, path = load_study(dest / f"{name}.toml")
    assert (path.parent / study.stage).resolve().is_relative_to(dest)
    assert (path.parent / study.output.dir).resolve().is_relative_to(dest)
    if study.annual is not None:
        weather = (path.parent / study.annual.weather).resolve()
        assert weather.is_file() and weather.is_relative_to(dest)
        assert weather.read_bytes() == (ROOT / "stages" / "weather" / weather.name).read_bytes()


def test_two_examples_sharing_a_stage_go_in_one_folder(tmp_path):
    """disk and disk_perpendicular share disk.usda: the identical file is kept."""
    copy_example("disk", tmp_path)
    copy_example("disk_perpendicular", tmp_path)
    assert (tmp_path / "stages" / "disk.usda").read_bytes() == (ROOT / "stages" / "disk.usda").read_bytes()


@pytest.mark.parametrize("argv, needle", [
    (["example", "nope", "DIR"], "no bundled example 'nope'"),
    (["example", "point"], "give an example's NAME and the DIR"),
    (["example", "point", "DIR"], "DIR/point.toml already exists"),
])  # fmt: skip
def test_example_mistakes_are_one_line_and_write_nothing(tmp_path, monkeypatch, capsys, argv, needle):
    """Unknown name, no folder, or a different non-empty file in the way:
    one line, exit 2, and the folder is left as it was."""
    monkeypatch.chdir(tmp_path)
    (tmp_path / "DIR").mkdir()
    (tmp_path / "DIR" / "point.toml").write_text("# mine\n")
    before = sorted(p.relative_to(tmp_path) for p in tmp_path.rglob("*"))
    assert main(argv) == 2
    err = capsys.readouterr().err.strip()
    assert err.count("\n") == 0 and err.startswith("probesim: error: example:") and needle in err, err
    assert sorted(p.relative_to(tmp_path) for p in tmp_path.rglob("*")) == before
    assert (tmp_path / "DIR" / "point.toml").read_text() == "# mine\n"
