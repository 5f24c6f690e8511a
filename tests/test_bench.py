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
