"""``probesim study``: user mistakes are one line and exit 2 with nothing written; a run prints its closing note."""

import importlib.util
from pathlib import Path

import pytest

from simulator.commands.cli import main

_spec = importlib.util.spec_from_file_location("_study_tiny", Path(__file__).with_name("test_study_resume.py"))
_tiny = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(_tiny)
TINY = _tiny.TINY


def _write(tmp_path, text):
    p = tmp_path / "s_study.toml"
    p.write_text(text)
    return p


@pytest.mark.parametrize("old, new, message", [
    ("height_m = 0.8", "heigt_m = 0.8", "candidates[0].heigt_m: unknown key (did you mean 'height_m'?"),
    ('lights = ["/Office/Sky"]', 'lights = ["/Office/Skye"]', "group[2].lights[0]: no light matches '/Office/Skye'"),
    ("corridor_row = 0.5 }", "corridr_row = 0.5 }", "scenario[1].levels.corridr_row: no [[group]] of that name (did you mean 'corridor_row'?)"),
    ("corridor_row = 0.5 }", "corridor_row = 0.5 }\nvariants = { reflectance = \"shiny\" }", "variants"),
    ('candidates = "wp"', 'candidates = "wp"\nregion = [7, 0, 8, 1]', "zone[0].region: no 'wp' candidate lies inside it"),
    ("k = 2", "k = 0", "placement.k: Input should be greater than or equal to 1"),
    ("[compute]", "[compute]\nscheduler = \"localhost\"", "compute.scheduler: expected an address"),
    ('lights = ["/Office/Lights/CorridorRow"]', 'collection = "/Office/Lights.collection:corridorSide"',
     "group[1].collection: no collection '/Office/Lights.collection:corridorSide' in the stage office.usda "
     "(collections: /Office/Lights.collection:windowSide, /Office/Lights.collection:rowEnds)"),
    ('name = "sky"\nlights = ["/Office/Sky"]', 'name = "sky"', "group[2]: give lights (prim paths or patterns) or a collection"),
])  # fmt: skip
def test_mistakes_are_one_line_and_write_nothing(tmp_path, capsys, old, new, message):
    assert old in TINY
    p = _write(tmp_path, TINY.replace(old, new, 1))
    out = tmp_path / "out"
    assert main(["study", str(p), "--out", str(out)]) == 2
    err = capsys.readouterr().err.strip()
    assert err.count("\n") == 0 and err.startswith("probesim: error: ") and str(p) in err
    assert message in err
    assert not out.exists()


def test_missing_file_and_bad_scheduler(tmp_path, capsys):
    assert main(["study", str(tmp_path / "none.toml")]) == 2
    assert "study file not found" in capsys.readouterr().err
    p = _write(tmp_path, TINY)
    assert main(["study", str(p), "--scheduler", "nowhere"]) == 2
    assert "--scheduler: expected an address" in capsys.readouterr().err


def test_a_study_prints_its_closing_note_and_writes_its_outputs(tmp_path, capsys):
    p = _write(tmp_path, TINY.replace("[compute]", "[compute]\nmode = \"inprocess\""))
    out = tmp_path / "o"
    assert main(["study", str(p), "--out", str(out)]) == 0
    text = capsys.readouterr().out
    for word in ("18 candidates", "3 scenarios", "4 chunks", "wall time", "per scenario", "single run", "within 4 sigma", "k=1", "k=2", "score"):
        assert word in text, word
    for f in ("readings.csv", "summary.csv", "heatmap_all.png", "study.json", "manifest.json"):
        assert (out / f).is_file(), f
    import json

    rec = json.loads((out / "study.json").read_text())
    assert rec["chunks"]["total"] == 4 and rec["reference_run"]["sensors_within_4_sigma"] == 18
    assert len(rec["placement"]["steps"]) == 2


def test_samples_seed_and_output_flags_override_the_study_file(tmp_path, capsys):
    """``probesim study S -o DIR --samples N --seed K`` traces with those settings (the study record keeps
    the study as run) and writes into DIR, as ``probesim run``'s flags do."""
    import json

    p = _write(tmp_path, TINY.replace("[compute]", "[compute]\nmode = \"inprocess\""))
    out = tmp_path / "flags"
    assert main(["study", str(p), "-o", str(out), "--samples", "32", "--seed", "5"]) == 0
    capsys.readouterr()
    rec = json.loads((out / "study.json").read_text())
    assert rec["study"]["simulation"]["samples"] == 32 and rec["study"]["seed"] == 5


def test_rel_error_flag_makes_the_study_adaptive_and_bad_flags_are_one_line(tmp_path, capsys):
    """``--rel-error`` sets ``[simulation] rel_error``; a flag outside its key's range is refused in
    one line naming the flag, before anything is written."""
    from simulator.commands.study import flag_overrides
    from simulator.study.schema import load_study

    p = _write(tmp_path, TINY)
    study, _ = load_study(p, flag_overrides(samples=16, seed=2, rel_error=0.1))
    assert (study.simulation.samples, study.seed, study.simulation.rel_error) == (16, 2, 0.1)
    for argv, needle in ((["--samples", "0"], "--samples: Input should be greater than or equal to 1"),
                         (["--rel-error", "2"], "--rel-error: Input should be less than 1"),
                         (["--seed", "-1"], "--seed: Input should be greater than or equal to 0")):
        out = tmp_path / "bad"
        assert main(["study", str(p), "-o", str(out), *argv]) == 2
        err = capsys.readouterr().err.strip()
        assert err.count("\n") == 0 and str(p) in err and needle in err, err
        assert not out.exists()


def test_progress_shows_chunks_and_time_left_on_a_terminal():
    import io

    from simulator.commands.study import ChunkProgress

    class Tty(io.StringIO):
        def isatty(self):
            return True

    s = Tty()
    bar = ChunkProgress(s)
    bar(0, 4, 0.0)
    bar(1, 4, 2.0)
    bar.close()
    text = s.getvalue()
    assert "chunks [" in text and "1/4" in text and "~6 s left" in text and text.endswith("\n")
    quiet = io.StringIO()  # not a terminal: nothing drawn (the closing note is the summary)
    ChunkProgress(quiet)(1, 4, 2.0)
    assert quiet.getvalue() == ""
