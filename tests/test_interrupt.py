"""Interrupted runs keep their work: Ctrl-C (KeyboardInterrupt) while tracing
writes the CSV and run record of what was measured so far.

The run is cut after its first Monte Carlo batch. Each reading holds whole
batches and every sample's random stream depends only on its index, so a
sensor cut at n samples must read bit for bit what an uninterrupted run of
n samples reads; closed-form readings are unaffected; sensors never reached
have 0 samples, empty value cells and ``target_met`` false.
"""

from __future__ import annotations

import csv
import json
import os
import pty
import re
import signal
import subprocess
import sys
import time
from dataclasses import replace
from pathlib import Path

import numpy as np
import pytest

from simulator.config.loader import load_config
from simulator.config.overrides import apply_overrides
from simulator.engine.adaptive import run_batches
from simulator.engine.driver import SAMPLES_PER_LAUNCH
from simulator.interrupts import StopFlag
from simulator.pipeline import run

ROOT = Path(__file__).resolve().parents[1]
#: dome.toml over a grey ground, plus a probe: planned as analytic (horizontal: it sees no ground),
#: sampled paths (tilted_60, vertical: they see the ground reflect), light (sky_meter), then the probe
PROBE = '\n[[sensor]]\nname = "probe"\nkind = "probe"\nposition = [0, 0, 1]\nresolution = [16, 8]\n'


def _config(tmp_path: Path, name: str = "dome.toml") -> Path:
    stage = (ROOT / "stages" / "dome.usda").read_text().replace("diffuseColor = (0, 0, 0)", "diffuseColor = (0.3, 0.3, 0.3)")
    (tmp_path / "grey_ground.usda").write_text(stage)
    text = (ROOT / "configs" / name).read_text().replace('"../stages/dome.usda"', f'"{tmp_path / "grey_ground.usda"}"')
    p = tmp_path / name
    p.write_text(text.replace("[output]", PROBE + "\n[output]"))
    return p


def _interrupt_after(n_calls: int):
    calls = []

    def progress(p):
        calls.append(p)
        if len(calls) == n_calls:
            raise KeyboardInterrupt

    return progress


def _rows(path: Path) -> dict[str, dict[str, str]]:
    with path.open(newline="") as f:
        return {r["sensor"]: r for r in csv.DictReader(f)}


def test_run_batches_stops_between_batches_and_leaves_unfinished_active():
    """A stop request keeps the whole batches drawn and marks the rest active."""
    drawn = []
    stop = StopFlag()

    def report(count, active, elapsed):
        raise KeyboardInterrupt

    active = np.ones(2, bool)
    count, _ = run_batches(lambda ids, first, n: drawn.append(n.copy()), active, np.array([100, 100]), 500,
                           block=32, report=report, stop=stop)  # fmt: skip
    assert stop.requested and len(drawn) == 1
    assert count.tolist() == [100, 100] and active.all()


def _sigint_self():
    os.kill(os.getpid(), signal.SIGINT)
    time.sleep(0.05)  # the handler runs in the main thread at its next bytecode; the step carries on


def test_sigint_inside_a_batch_takes_effect_after_it():
    """SIGINT during a step never cuts it: with a stop flag the loop ends
    after that batch; without one KeyboardInterrupt is raised after it. The
    process starts from Python's own handler, as under a terminal (a job
    started in the background inherits SIGINT ignored instead)."""
    previous = signal.signal(signal.SIGINT, signal.default_int_handler)
    try:
        _sigint_inside_a_batch()
    finally:
        signal.signal(signal.SIGINT, previous)


def _sigint_inside_a_batch():
    for stop in (StopFlag(), None):
        finished = []

        def step(ids, first, n):
            _sigint_self()
            finished.append(n.copy())  # reached: the signal did not raise inside the step

        active = np.ones(2, bool)
        if stop is None:
            with pytest.raises(KeyboardInterrupt):
                run_batches(step, active, np.array([100, 100]), 500, block=32)
        else:
            count, _ = run_batches(step, active, np.array([100, 100]), 500, block=32, stop=stop)
            assert stop.requested and count.tolist() == [100, 100] and active.all()
        assert len(finished) == 1
    assert signal.getsignal(signal.SIGINT) is signal.default_int_handler  # the handler is given back


def test_second_interrupt_during_the_write_is_deferred(tmp_path, monkeypatch):
    """Ctrl-C again while the files are written: they still come out whole."""
    import simulator.pipeline as pipeline

    write = pipeline.write_outputs

    def write_with_sigint(*args, **kwargs):
        _sigint_self()
        return write(*args, **kwargs)

    monkeypatch.setattr(pipeline, "write_outputs", write_with_sigint)
    cfg = apply_overrides(load_config(_config(tmp_path)), samples=3 * SAMPLES_PER_LAUNCH, csv=tmp_path / "w.csv")
    out = run(cfg, progress=_interrupt_after(1), log=lambda m: None)
    assert out.interrupted
    assert len(_rows(tmp_path / "w.csv")) == 5
    assert json.loads((tmp_path / "w.run.json").read_text())["interrupted"] is True
    assert not list(tmp_path.glob(".w*"))


@pytest.mark.parametrize("adaptive", [False, True], ids=["fixed", "adaptive"])
def test_interrupted_run_keeps_whole_batches_bit_identical(tmp_path, adaptive):
    """Cut after the first batch of paths: the closed-form sensor is complete, the
    sampled sensors hold their first batch (equal to an uninterrupted run of that
    many samples), the light-sampled meter and the probe were never reached."""
    cfg_path = _config(tmp_path)
    # fixed: a budget of several batches; adaptive: the first batch, and a target far out of its reach
    samples = 4096 if adaptive else 3 * SAMPLES_PER_LAUNCH
    rel = 1e-4 if adaptive else None
    cfg = apply_overrides(load_config(cfg_path), samples=samples, rel_error=rel, csv=tmp_path / "cut.csv")
    out = run(cfg, progress=_interrupt_after(1), log=lambda m: None)
    assert out.interrupted
    rows = {r.sensor.name: r for r in out.rows}
    reached = rows["tilted_60"].samples
    assert (reached == samples if adaptive else 0 < reached < samples) and rows["vertical"].samples == reached

    # the same sensors, uninterrupted, with the budget the cut run reached
    ref_cfg = apply_overrides(load_config(cfg_path), samples=reached, csv=tmp_path / "ref.csv")
    ref = {r.sensor.name: r for r in run(ref_cfg, log=lambda m: None).rows}
    for name in ("horizontal", "tilted_60", "vertical"):
        assert rows[name].values == ref[name].values, name  # bit for bit: the same whole batches
    assert rows["horizontal"].target_met is True
    assert rows["tilted_60"].target_met is False and rows["vertical"].target_met is False

    written = _rows(tmp_path / "cut.csv")
    assert list(written) == ["horizontal", "tilted_60", "vertical", "sky_meter", "probe"]
    for name in ("sky_meter", "probe"):  # never reached: no value, never 0
        r = written[name]
        assert r["samples"] == "0" and r["target_met"] == "false", name
        assert r["irradiance_W_m2"] == r["radiance_W_m2_sr"] == r["scalar_irradiance_W_m2"] == "", name
    assert written["tilted_60"]["target_met"] == "false" and written["horizontal"]["target_met"] == "true"
    assert float(written["tilted_60"]["irradiance_W_m2"]) == pytest.approx(ref["tilted_60"].values["irradiance_W_m2"], rel=1e-8)

    record = json.loads((tmp_path / "cut.run.json").read_text())
    assert record["interrupted"] is True and record["sensors"] == 5
    assert record["sensors_read"] == 3 and record["sensors_finished"] == 1
    assert record["samples_total"] == 2 * reached and record["maps"] == []
    if adaptive:
        assert record["adaptive"]["sensors_met"] == 1


def test_uninterrupted_fixed_run_leaves_target_met_empty(tmp_path):
    """A fixed-budget run that is not interrupted has no ``target_met`` (every
    sensor got its samples: the column is left out of the kinds' CSV, and empty
    in the full set) and records ``interrupted`` false."""
    cfg = apply_overrides(load_config(_config(tmp_path)), samples=4096, csv=tmp_path / "full.csv")
    out = run(cfg, log=lambda m: None)
    assert not out.interrupted
    assert all("target_met" not in r for r in _rows(tmp_path / "full.csv").values())
    cfg = replace(cfg, output=replace(cfg.output, csv=tmp_path / "all.csv", csv_columns="full"))
    run(cfg, log=lambda m: None)
    assert {r["target_met"] for r in _rows(tmp_path / "all.csv").values()} == {""}
    record = json.loads((tmp_path / "full.run.json").read_text())
    assert record["interrupted"] is False and record["sensors_finished"] == record["sensors"] == 5


def test_probe_cut_mid_run_reports_what_it_has(tmp_path):
    """An adaptive probe cut after its first batch keeps that batch's reading
    with ``target_met`` false."""
    text = (f'stage = "{ROOT / "stages" / "rect.usda"}"\n[simulation]\nsamples = 4096\nseed = 1\nrel_error = 1e-5\n'
            f'{PROBE}\n[output]\ncsv = "{tmp_path / "p.csv"}"\n')  # fmt: skip
    (tmp_path / "p.toml").write_text(text)
    out = run(load_config(tmp_path / "p.toml"), progress=_interrupt_after(1), log=lambda m: None)
    assert out.interrupted
    row = _rows(tmp_path / "p.csv")["probe"]
    assert int(row["samples"]) > 0 and row["target_met"] == "false"
    assert float(row["scalar_irradiance_stderr_W_m2"]) > 0
    # its first batch is the whole of a fixed run of the same samples: the same reading, bit for bit
    (tmp_path / "ref.toml").write_text(text.replace("rel_error = 1e-5\n", "").replace('p.csv"', 'ref.csv"'))
    ref = load_config(tmp_path / "ref.toml")
    (ref_row,) = [r for r in run(ref, log=lambda m: None).rows]
    assert ref_row.samples == int(row["samples"])
    assert out.rows[0].values == ref_row.values


def test_cli_sigint_writes_partial_results_and_exits_130(tmp_path):
    """``python -m simulator run`` sent SIGINT once its progress bar shows:
    exit status 130, one line on stderr, a complete CSV and run record."""
    cfg = _config(tmp_path)
    out_csv = tmp_path / "sig.csv"
    master, slave = pty.openpty()  # a terminal for stderr, so the progress bar is drawn
    proc = subprocess.Popen(
        [sys.executable, "-m", "simulator", "run", str(cfg), "-o", str(out_csv), "--samples", str(1 << 30), "-q"],
        cwd=ROOT, stdout=subprocess.PIPE, stderr=slave, env={**os.environ, "PYTHONUNBUFFERED": "1"},
    )  # fmt: skip
    os.close(slave)
    err = b""
    deadline = time.monotonic() + 120
    try:
        while b"tracing" not in err and time.monotonic() < deadline:
            err += os.read(master, 4096)
        assert b"tracing" in err, err
        proc.send_signal(signal.SIGINT)
        stdout, _ = proc.communicate(timeout=120)
        while True:
            try:
                chunk = os.read(master, 4096)
            except OSError:  # the child closed its end
                break
            if not chunk:
                break
            err += chunk
    finally:
        if proc.poll() is None:
            proc.kill()
        os.close(master)
    assert proc.returncode == 130, err
    assert stdout == b""
    text = err.decode().replace("\r\n", "\n")
    lines = [seg.strip() for line in text.split("\n") for seg in line.split("\r")[-1:]]
    lines = [line for line in lines if line and not line.startswith("tracing")]
    assert len(lines) == 1 and lines[0].startswith("interrupted: wrote partial results for "), lines
    assert re.fullmatch(rf"interrupted: wrote partial results for [1-5] of 5 sensors to {re.escape(str(out_csv))} \([1-5] finished\)", lines[0])
    rows = _rows(out_csv)
    assert list(rows) == ["horizontal", "tilted_60", "vertical", "sky_meter", "probe"]
    assert all(r["target_met"] == "false" for n, r in rows.items() if n != "horizontal")
    record = json.loads(out_csv.with_name("sig.run.json").read_text())
    assert record["interrupted"] is True and record["samples_total"] == sum(int(r["samples"]) for r in rows.values())
    assert not list(tmp_path.glob(".sig*"))  # no temporary file left behind
