"""What a person reads of a run: the CSV's columns per sensor kind, and the console table in the run's units.

The column sets are documented in docs/DESIGN.md §The CSV's columns, per kind:
``[output] csv_columns = "kinds"`` (the default) keeps the columns of the
kinds a run holds, so a run of one kind leaves no cell empty; ``"full"`` is
the 32-column layout of :data:`simulator.io.results.COLUMNS`.
"""

from __future__ import annotations

import csv
import io

import numpy as np
import pytest

from simulator.commands.cli import main
from simulator.io.results import COLUMNS, Reading, _csv_text, csv_columns, format_table, readings_from
from simulator.scene.model import Sensor, SensorKind

FIXED = ("sensor", "kind", "x", "y", "z")
TAIL = ("samples", "seconds", "method")
DIRECTION = ("dx", "dy", "dz")
IRR = ("irradiance_W_m2", "irradiance_stderr_W_m2", "illuminance_lx", "illuminance_stderr_lx")
RAD = ("radiance_W_m2_sr", "radiance_stderr_W_m2_sr", "luminance_cd_m2", "luminance_stderr_cd_m2")
FLUX = ("flux_W", "flux_stderr_W", "luminous_flux_lm", "luminous_flux_stderr_lm")


def _sensor(kind: SensorKind, name: str) -> Sensor:
    extra = {"size": (0.5, 0.4), "up": np.array([0.0, 1.0, 0.0])} if kind == SensorKind.PATCH else {}
    return Sensor(name, kind, np.zeros(3), np.array([0.0, 0.0, 1.0]), **extra)


def _rows(kinds, target_met=None) -> list[Reading]:
    """Rows of estimated sensors with made-up means (W, lm) = (2, 1366) and stderrs (0.02, 13.66)."""
    sensors = [_sensor(k, f"s{i}") for i, k in enumerate(kinds)]
    n = len(sensors)
    mean = np.tile([2.0, 1366.0], (n, 1))
    return readings_from(sensors, mean, mean * 0.01, [64] * n, [0.1] * n, "light", target_met)


def _table(text: str) -> list[dict]:
    return list(csv.DictReader(io.StringIO(text)))


@pytest.mark.parametrize("kind,values", [
    (SensorKind.IRRADIANCE, IRR),
    (SensorKind.RADIANCE, RAD),
    (SensorKind.PATCH, IRR + FLUX),
])
def test_a_run_of_one_kind_has_its_columns_and_no_empty_cell(kind, values):
    rows = _rows([kind, kind])
    assert csv_columns(rows, "kinds") == FIXED + DIRECTION + values + TAIL
    for row in _table(_csv_text(rows, "kinds")):
        assert all(cell != "" for cell in row.values()), row


def test_target_met_only_where_a_row_has_one_and_full_set_unchanged():
    """An adaptive run's rows carry target_met; the full set is COLUMNS whatever the kinds."""
    rows = _rows([SensorKind.IRRADIANCE], target_met=[True])
    assert csv_columns(rows, "kinds") == FIXED + DIRECTION + IRR + TAIL + ("target_met",)
    assert _table(_csv_text(rows, "kinds"))[0]["target_met"] == "true"
    plain = _rows([SensorKind.IRRADIANCE])
    assert csv_columns(plain, "full") == COLUMNS and len(COLUMNS) == 32
    full, kinds = _table(_csv_text(plain, "full"))[0], _table(_csv_text(plain, "kinds"))[0]
    assert all(full[k] == v for k, v in kinds.items())  # the same cells, by name
    assert sum(1 for v in full.values() if v == "") == 32 - 15  # what the kinds' set leaves out


def test_mixed_kinds_keep_each_kinds_columns_in_the_full_order():
    rows = _rows([SensorKind.RADIANCE, SensorKind.IRRADIANCE])
    assert csv_columns(rows, "kinds") == FIXED + DIRECTION + IRR + RAD + TAIL


def test_console_table_leads_with_the_runs_own_units():
    """Photometric run: lx first (1366 lx ± 13.7, 1.00%), W/m² second; radiometric run the other way round."""
    rows = _rows([SensorKind.IRRADIANCE, SensorKind.RADIANCE, SensorKind.PATCH])
    photo = format_table(rows, photometric_first=True).splitlines()
    assert "radiometric" in photo[0]
    assert photo[1].split()[2:5] == ["1366", "lx", "13.7"] and photo[1].split()[6:8] == ["2", "W/m²"]
    assert photo[2].split()[2:4] == ["1366", "cd/m²"] and "W/m²/sr" in photo[2]
    assert photo[3].split()[2:4] == [f"{1366 * 0.2:.4g}", "lm"]  # a patch's headline: its flux, 0.5 × 0.4 m²
    radio = format_table(rows).splitlines()
    assert "photometric" in radio[0]
    assert radio[1].split()[2:4] == ["2", "W/m²"] and radio[1].split()[6:8] == ["1366", "lx"]


def test_csv_columns_key_and_flag(tmp_path, capsys):
    """``[output] csv_columns`` takes "kinds" or "full" (else one line naming the key); ``--csv-columns full``
    overrides it; the quickstart's console table leads with lx."""
    import shutil
    from pathlib import Path

    root = Path(__file__).resolve().parents[1]
    shutil.copy(root / "stages" / "point.usda", tmp_path / "point.usda")
    body = ('stage = "point.usda"\n[[sensor]]\nname = "below"\nkind = "irradiance"\nposition = [0, 0, 0]\n'
            'normal = [0, 0, 1]\n[output]\ncsv = "o.csv"\n')
    (tmp_path / "c.toml").write_text(body + 'csv_columns = "some"\n')
    assert main(["run", str(tmp_path / "c.toml"), "-q"]) == 2
    err = capsys.readouterr().err.strip()
    assert "\n" not in err and "output.csv_columns" in err and "kinds" in err, err
    (tmp_path / "c.toml").write_text(body + 'csv_columns = "full"\n')
    assert main(["run", str(tmp_path / "c.toml"), "-q"]) == 0
    assert tuple(_table((tmp_path / "o.csv").read_text())[0]) == COLUMNS
    (tmp_path / "c.toml").write_text(body)
    capsys.readouterr()
    assert main(["run", str(tmp_path / "c.toml")]) == 0
    assert tuple(_table((tmp_path / "o.csv").read_text())[0]) == FIXED + DIRECTION + IRR + TAIL
    table = capsys.readouterr().out.splitlines()
    assert table[1].split()[2:4] == [f"{100 / 9:.4g}", "lx"], table  # 100 cd, 3 m above: E = I/d²
    assert main(["run", str(tmp_path / "c.toml"), "-q", "--csv-columns", "full"]) == 0
    assert tuple(_table((tmp_path / "o.csv").read_text())[0]) == COLUMNS
