"""`probesim bench` runs end to end and labels what it cannot measure."""

from pathlib import Path

from simulator.commands.bench import format_bench, run_bench

CONFIGS = Path(__file__).resolve().parents[1] / "configs"


def test_bench_rows_for_each_estimator():
    """On the point-light stage: analytic applies (nothing occludes), light/mis/
    path/guided are measured with positive rates, and bsdf is reported blind (a
    point light cannot be hit by a sampled direction) instead of a meaningless time."""
    rows, info = run_bench([CONFIGS / "point.toml"], samples=64, cap=1 << 12, log=lambda *_: None)
    by = {r.method: r for r in rows}
    assert set(by) == {"analytic", "light", "bsdf", "mis", "path", "guided"}
    assert by["bsdf"].samples_per_s is None and "blind" in by["bsdf"].note
    for m in ("light", "mis", "path", "guided"):
        assert by[m].samples_per_s > 0 and by[m].rays_per_s > 0 and by[m].reached
    # one shadow ray per sample for a lone point light under `light`
    assert abs(by["light"].rays_per_s / by["light"].samples_per_s - 1.0) < 1e-9
    assert info["device"] == "cpu"
    assert "blind" in format_bench(rows)


def test_bench_samples_obey_the_schema_rule(monkeypatch, capsys, tmp_path):
    """``probesim bench --samples`` is checked by ``[simulation] samples``' own rule
    (``config.overrides.check_flags``, the schema), not a check of its own: the
    same one line and exit 2 as ``probesim run --samples``, for 0 and −3."""
    from simulator.commands.cli import main
    from simulator.config import overrides

    seen = []
    real = overrides.check_flags
    monkeypatch.setattr(overrides, "check_flags", lambda **kw: (seen.append(kw), real(**kw))[1])
    for bad in ("0", "-3"):
        assert main(["bench", str(CONFIGS / "point.toml"), "--samples", bad]) == 2
        bench_err = capsys.readouterr().err.strip()
        assert main(["run", str(CONFIGS / "point.toml"), "--samples", bad, "-q", "-o", str(tmp_path / "x.csv")]) == 2
        run_err = capsys.readouterr().err.strip()
        assert bench_err == run_err == f"probesim: error: --samples: must be >= 1, got {bad}"
    assert seen == [{"samples": 0}, {"samples": -3}]
