"""Where a study's chunks run: ``--local``/``--workers``/``--scheduler`` (tcp and tls) give byte-identical
outputs, and the automatic block size holds a study's cost within 1.3 runs by the pilots' model."""

import importlib.util
import os
import subprocess
from pathlib import Path

import pytest

from simulator.commands.cli import main
from simulator.study.trace.distributed import QUIET_CLUSTER

_spec = importlib.util.spec_from_file_location("_study_tiny", Path(__file__).with_name("test_study_resume.py"))
_tiny = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(_tiny)
TINY = _tiny.TINY

pytestmark = pytest.mark.skipif(os.environ.get("PROBESIM_SKIP_CLUSTER") == "1", reason="PROBESIM_SKIP_CLUSTER=1")


def _study(tmp_path) -> Path:
    p = tmp_path / "c_study.toml"
    p.write_text(TINY)
    return p


@pytest.mark.parametrize("args, message", [
    (["--local", "--scheduler", "tcp://127.0.0.1:1"], "not both"),
    (["--workers", "2", "--scheduler", "tcp://127.0.0.1:1"], "not both"),
    (["--workers", "0"], "--workers: expected a number of workers >= 1"),
    (["--scheduler", "127.0.0.1:8786"], "--scheduler: expected an address"),
])  # fmt: skip
def test_bad_compute_flags_are_one_line(tmp_path, capsys, args, message):
    out = tmp_path / "o"
    assert main(["study", str(_study(tmp_path)), "--out", str(out), *args]) == 2
    err = capsys.readouterr().err.strip()
    assert err.count("\n") == 0 and message in err and not out.exists()


def test_local_and_workers_choose_a_local_cluster(tmp_path, monkeypatch):
    import simulator.study.runner as runner

    seen = {}

    def fake(study, path, out_dir, **kw):
        seen.update(kw)
        raise KeyboardInterrupt  # stop before any chunk: only the arguments are under test

    monkeypatch.setattr(runner, "run_study", fake)
    assert main(["study", str(_study(tmp_path)), "--out", str(tmp_path / "o"), "--workers", "3"]) == 130
    assert (seen["mode"], seen["workers"]) == ("local", 3)
    assert main(["study", str(_study(tmp_path)), "--out", str(tmp_path / "o"), "--local"]) == 130
    assert (seen["mode"], seen["workers"]) == ("local", None)
    assert main(["study", str(_study(tmp_path)), "--out", str(tmp_path / "o")]) == 130
    assert (seen["mode"], seen["workers"]) == (None, None)  # the file's [compute]


def _csvs(out: Path) -> tuple[bytes, bytes]:
    return (out / "readings.csv").read_bytes(), (out / "summary.csv").read_bytes()


def _self_signed(d: Path) -> tuple[Path, Path]:
    cert, key = d / "cert.pem", d / "key.pem"
    r = subprocess.run(["openssl", "req", "-x509", "-newkey", "rsa:2048", "-nodes", "-days", "1", "-subj", "/CN=localhost",
                        "-keyout", str(key), "-out", str(cert)], capture_output=True, timeout=60)  # fmt: skip
    if r.returncode != 0:
        pytest.skip("openssl could not make a certificate")
    return cert, key


@pytest.mark.parametrize("protocol", ["tcp", "tls"])
def test_a_scheduler_gives_byte_identical_outputs(tmp_path, capsys, protocol):
    distributed = pytest.importorskip("distributed")
    import dask

    p = _study(tmp_path)
    assert main(["study", str(p), "--out", str(tmp_path / "inproc")]) == 0  # 2 cores here: auto is in process
    settings = {}
    if protocol == "tls":
        import shutil

        if shutil.which("openssl") is None:
            pytest.skip("no openssl to make a certificate")
        cert, key = _self_signed(tmp_path)
        settings = {f"distributed.comm.tls.{k}": str(v) for k, v in {
            "ca-file": cert, "scheduler.cert": cert, "scheduler.key": key, "worker.cert": cert, "worker.key": key,
            "client.cert": cert, "client.key": key}.items()}  # fmt: skip
    with dask.config.set(settings):
        sec = distributed.Security(require_encryption=True) if protocol == "tls" else None
        kw = {"security": sec} if sec else {}
        with distributed.LocalCluster(n_workers=1, threads_per_worker=1, processes=False, protocol=f"{protocol}://",
                                      **QUIET_CLUSTER, **kw) as cluster:  # fmt: skip
            addr = cluster.scheduler_address
            assert addr.startswith(f"{protocol}://")
            assert main(["study", str(p), "--out", str(tmp_path / "sched"), "--scheduler", addr]) == 0
    assert "on scheduler dask" in capsys.readouterr().out
    assert _csvs(tmp_path / "inproc") == _csvs(tmp_path / "sched")


def test_a_tls_scheduler_without_settings_is_one_line(tmp_path, capsys):
    pytest.importorskip("distributed")
    import dask

    with dask.config.set({"distributed.comm.tls.ca-file": None, "distributed.comm.tls.client.cert": None}):
        out = tmp_path / "o"
        assert main(["study", str(_study(tmp_path)), "--out", str(out), "--scheduler", "tls://127.0.0.1:1"]) == 2
    err = capsys.readouterr().err.strip()
    assert err.count("\n") == 0 and "distributed.comm.tls.ca-file" in err and "DASK_DISTRIBUTED__COMM__TLS__CA_FILE" in err
    assert not (out / "readings.csv").exists()


def test_auto_block_keeps_the_modelled_cost_within_budget():
    """The pilots' model (simulator.study.trace.blocks): each chunk pays at least 16,384 + 256 pilot paths; the
    most chunks whose modelled cost is ≤ 1.2 runs."""
    from simulator.study.trace.blocks import BUDGET, MAX_BLOCK, auto_block, pass_cost

    for s, n in [(18, 64), (54, 128), (300, 256), (1500, 1024), (5000, 256), (20000, 4096)]:
        b = auto_block(s, n)
        assert 1 <= b <= min(s, MAX_BLOCK)
        ratio = pass_cost(s, n, b) / pass_cost(s, n, s)
        assert ratio <= BUDGET + 1e-12
        if b < min(s, MAX_BLOCK):  # the smallest such block: one sensor fewer breaks the budget
            assert b == 1 or pass_cost(s, n, b - 1) / pass_cost(s, n, s) > BUDGET
    # a small study is one chunk: the guide's 16,384-path pilot is more than its readings
    assert auto_block(54, 128) == 54
    # hand computation, 1500 sensors at 1024 samples in blocks of 69: 22 chunks (21 of 69, one of 51)
    one = max(32 * 1500, 16384) + 256 + 1040 * 1500
    cost = 21 * (16384 + 256 + 1040 * 69) + (16384 + 256 + 1040 * 51)
    assert auto_block(1500, 1024) == 69 and pass_cost(1500, 1024, 68) > 1.2 * one and pass_cost(1500, 1024, 69) == cost and cost / one <= 1.2


def test_a_worker_that_cannot_import_probesim_is_one_line(monkeypatch):
    """A dask worker without probesim (or without a package a chunk needs) fails its task with an
    ImportError; the study says so in one line naming the scheduler, not with the worker's traceback."""
    import distributed

    from simulator.errors import UserError
    from simulator.study.trace import distributed as dist
    from simulator.study.trace.chunks import ChunkSpec

    def no_probesim(spec):
        raise ModuleNotFoundError("No module named 'simulator'")

    monkeypatch.setattr(dist, "compute_chunk", no_probesim)
    spec = ChunkSpec("c0ffee", "key", 0, "stage.usda", "photometric", (), None, (), (), (), {}, 1)
    with distributed.LocalCluster(n_workers=1, threads_per_worker=1, processes=False, **QUIET_CLUSTER) as cluster:
        addr = cluster.scheduler_address
        with pytest.raises(UserError) as err:
            list(dist.run_chunks([spec], "scheduler", 1, addr, 0))
    assert str(err.value) == (f"dask scheduler {addr}: a worker cannot import what a chunk needs (No module named "
                              "'simulator'): install the study's probesim, the same build, on every worker")  # fmt: skip
