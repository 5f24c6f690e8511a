"""A grid too large for the machine is refused before a cell is built, with the memory it would need."""

from __future__ import annotations

import subprocess
import sys
import textwrap
from pathlib import Path

import pytest

from simulator.config import capacity
from simulator.config.capacity import SENSOR_BYTES, format_bytes, memory_needed_bytes, too_many_sensors
from simulator.config.loader import load_config
from simulator.errors import UserError

ROOT = Path(__file__).resolve().parent.parent


def _config(tmp_path: Path, size: str, spacing: str) -> Path:
    p = tmp_path / "grid.toml"
    p.write_text(textwrap.dedent(f"""\
        stage = "{(ROOT / 'stages' / 'point.usda').as_posix()}"
        [[sensor]]
        name = "one"
        kind = "irradiance"
        position = [0, 0, 0]
        normal = [0, 0, 1]
        [[grid]]
        name = "small"
        position = [0, 0, 0]
        normal = [0, 0, 1]
        size = [1, 1]
        up = [0, 1, 0]
        spacing = 0.5
        [[grid]]
        name = "floor"
        position = [0, 0, 0]
        normal = [0, 0, 1]
        size = {size}
        up = [0, 1, 0]
        spacing = {spacing}
        [output]
        csv = "{(tmp_path / 'out.csv').as_posix()}"
        """))
    return p


def test_the_estimate_is_sensors_times_the_measured_bytes():
    """need = n × SENSOR_BYTES; a run fits exactly up to the memory and no further."""
    assert memory_needed_bytes(1000) == 1000 * SENSOR_BYTES
    n = 12_345
    assert too_many_sensors(n, memory=n * SENSOR_BYTES) is None
    why = too_many_sensors(n + 1, memory=n * SENSOR_BYTES)
    assert why is not None and "12,346 sensors" in why and format_bytes((n + 1) * SENSOR_BYTES) in why
    assert format_bytes(4.4e12) == "4 TiB" and format_bytes(1536) == "1.5 KiB" and format_bytes(10) == "10 B"


def test_a_grid_past_the_memory_is_refused_naming_it(tmp_path, monkeypatch):
    """200 × 200 cells + 4 + 1 sensors against a machine of 100 MiB (memory faked):
    40,005 × 4,500 B = 172 MiB is refused, naming the larger grid's spacing and
    the estimate; 100 × 100 (10,005 sensors, 42.9 MiB) loads."""
    monkeypatch.setattr(capacity, "physical_memory_bytes", lambda: 100 * 2**20)
    with pytest.raises(UserError) as e:
        load_config(_config(tmp_path, "[20, 20]", "0.1"))
    msg = str(e.value)
    assert "grid[1].spacing" in msg and "200 x 200 cells" in msg and "40,005 sensors" in msg
    assert f"about {format_bytes(40_005 * SENSOR_BYTES)}" in msg and "100 MiB" in msg and "\n" not in msg
    cfg = load_config(_config(tmp_path, "[10, 10]", "0.1"))
    assert len(cfg.sensors) == 10_005


def test_billions_of_cells_exit_2_at_once(tmp_path):
    """A 0.01 mm grid over 100 m × 100 m (10¹³ cells, ~41 PiB by the estimate) on
    any machine: ``probesim run`` exits 2 with one line naming the key and the
    memory, writes nothing, and does not try (its address space capped at 2 GiB,
    a 60 s limit)."""
    cfg = _config(tmp_path, "[100, 100]", "1e-5")
    cap = "import resource; resource.setrlimit(resource.RLIMIT_AS, (2 << 30, 2 << 30)); "
    code = cap + f"import sys; from simulator.commands.cli import main; sys.exit(main(['run', {str(cfg)!r}, '-q']))"
    p = subprocess.run([sys.executable, "-c", code], cwd=ROOT, capture_output=True, text=True, timeout=60,
                       env={"PYTHONPATH": str(ROOT), "PATH": "/usr/bin:/bin"})  # fmt: skip
    err = p.stderr.strip()
    assert p.returncode == 2, err[-500:]
    assert err.count("\n") == 0 and "Traceback" not in err
    assert "grid[1].spacing" in err and "10,000,000 x 10,000,000 cells" in err and "PiB of memory" in err
    assert not (tmp_path / "out.csv").exists()


def test_a_study_candidate_grid_past_the_memory_is_refused(tmp_path):
    """A study's ``spacing_m`` of 1 µm on the office floor (~10¹³ candidates)
    is refused naming the candidate set's key and prim, before any is built."""
    from simulator.study.runner import run_study
    from simulator.study.schema import load_study

    p = tmp_path / "s.toml"
    p.write_text(textwrap.dedent(f"""\
        stage = "{(ROOT / 'stages' / 'office.usda').as_posix()}"
        [[candidates]]
        name = "wp"
        on = ["/Office/Room/Floor"]
        height_m = 0.8
        spacing_m = 1e-6
        [[group]]
        name = "sky"
        lights = ["/Office/Sky"]
        [[scenario]]
        name = "day"
        levels = {{ sky = 1.0 }}
        [[zone]]
        name = "all"
        candidates = "wp"
        targets = {{ mean = 300 }}
        """))
    study, path = load_study(p)
    with pytest.raises(UserError) as e:
        run_study(study, path, tmp_path / "out", reference_run=False, mode="inprocess")
    msg = str(e.value)
    assert "candidates[0].spacing_m" in msg and "/Office/Room/Floor" in msg and "PiB of memory" in msg and "\n" not in msg
