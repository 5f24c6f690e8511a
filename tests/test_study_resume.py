"""A study is deterministic: interrupted and resumed, or run on a two-worker LocalCluster, its CSVs are byte-identical."""

import os
from pathlib import Path

import pytest

from simulator.study.trace.chunks import StudyInterrupted
from simulator.study.report.outputs import long_csv, summary_csv
from simulator.study.runner import run_study
from simulator.study.schema import load_study

STAGE = Path(__file__).resolve().parent.parent / "stages" / "office.usda"

TINY = f'''
stage = "{STAGE.as_posix()}"
seed = 11
[simulation]
samples = 64
method = "light"
[compute]
sensor_block = 5
[[candidates]]
name = "wp"
on = ["/Office/Room/Floor"]
height_m = 0.8
spacing_m = 1.0
drop_inside = ["/Office/Furniture/*"]
[[candidates]]
name = "cell"
kind = "photosensor"
points = [[1.5, 1.5, 2.98], [3.0, 2.0, 2.98], [4.5, 2.5, 2.98]]
normal = [0, 0, -1]
[[group]]
name = "window_row"
lights = ["/Office/Lights/WindowRow/*"]
[[group]]
name = "corridor_row"
lights = ["/Office/Lights/CorridorRow"]
[[group]]
name = "sky"
lights = ["/Office/Sky"]
[[scenario]]
name = "evening"
levels = {{ window_row = [0.5, 1.0], corridor_row = 1.0 }}
[[scenario]]
name = "overcast"
levels = {{ sky = 1.0, corridor_row = 0.5 }}
[[zone]]
name = "all"
candidates = "wp"
targets = {{ mean = 300 }}
[placement]
k = 2
candidates = ["cell"]
objective = "correlation"
replicates = 50
'''


def tiny_study(tmp_path: Path) -> Path:
    p = tmp_path / "tiny_study.toml"
    p.write_text(TINY)
    return p


def _run(path: Path, out: Path, **kw):
    """The study run into ``out`` (its chunk store), and its readings.csv and summary.csv as
    ``write_outputs`` writes them (the same functions, kept in memory: the plans and report
    page it also draws are pictures of these numbers and took a third of these tests' time)."""
    study, p = load_study(path)
    res = run_study(study, p, out, reference_run=False, **kw)
    return res, long_csv(res).encode(), summary_csv(res).encode()


def test_killed_and_resumed_study_gives_byte_identical_outputs(tmp_path):
    path = tiny_study(tmp_path)
    full, long_a, summ_a = _run(path, tmp_path / "full", mode="inprocess")
    assert full.chunks_total == 4 and full.chunks_computed == 4  # 18 sensors in blocks of 5, one trace group
    with pytest.raises(StudyInterrupted):
        _run(path, tmp_path / "resumed", mode="inprocess", stop_after=2)
    assert not (tmp_path / "resumed" / "readings.csv").exists()
    assert len(list((tmp_path / "resumed" / "chunks").glob("*.npz"))) == 2
    res, long_b, summ_b = _run(path, tmp_path / "resumed", mode="inprocess")
    assert (res.chunks_loaded, res.chunks_computed) == (2, 2)
    assert long_a == long_b and summ_a == summ_b
    # a damaged chunk file no longer matches its manifest entry: it is computed again
    victim = sorted((tmp_path / "resumed" / "chunks").glob("*.npz"))[0]
    victim.write_bytes(victim.read_bytes()[:-10])
    res, long_c, _ = _run(path, tmp_path / "resumed", mode="inprocess")
    assert (res.chunks_loaded, res.chunks_computed) == (3, 1)
    assert long_c == long_a
    # figures: readings and their errors are there for every scenario × sensor
    assert long_a.count(b"\n") == 1 + 3 * 18
    assert b",nan" not in long_a  # (the header's "luminance" holds the letters)


def test_a_changed_study_recomputes_only_what_changed(tmp_path):
    path = tiny_study(tmp_path)
    _run(path, tmp_path / "o", mode="inprocess")
    path.write_text(TINY.replace("points = [[1.5, 1.5, 2.98], [3.0, 2.0, 2.98], [4.5, 2.5, 2.98]]",
                                 "points = [[1.5, 1.5, 2.98], [3.0, 2.0, 2.98], [4.4, 2.5, 2.98]]"))  # fmt: skip
    res, _, _ = _run(path, tmp_path / "o", mode="inprocess")
    assert (res.chunks_loaded, res.chunks_computed) == (3, 1)  # only the last block holds the moved sensor


@pytest.mark.skipif(os.environ.get("PROBESIM_SKIP_CLUSTER") == "1", reason="PROBESIM_SKIP_CLUSTER=1")
def test_two_worker_local_cluster_gives_byte_identical_outputs(tmp_path):
    """Guided paths, the sun in the sky group (its sunlit patches concentrate the
    pilot's light, so each chunk's pilot-learnt guide is used): in this process a
    chunk traces on every core, on the cluster on one thread; the CSVs are the same bytes."""
    pytest.importorskip("distributed")
    path = tiny_study(tmp_path)
    path.write_text(TINY.replace('method = "light"', 'method = "guided"').replace('["/Office/Sky"]', '["/Office/Sky", "/Office/Sun"]'))
    _, long_a, summ_a = _run(path, tmp_path / "inproc", mode="inprocess")
    res, long_b, summ_b = _run(path, tmp_path / "cluster", mode="local", workers=2)
    assert res.mode == "local" and res.workers == 2 and res.chunks_computed == 4
    assert long_a == long_b and summ_a == summ_b


def test_a_killed_process_resumes_to_byte_identical_outputs(tmp_path):
    """SIGKILL the command once its manifest lists a chunk, start it again: only the
    missing chunks are computed and the CSVs equal those of an uninterrupted run."""
    import json
    import signal
    import subprocess
    import sys
    import time

    text = TINY.replace("sensor_block = 5", "sensor_block = 2\nmode = \"inprocess\"").replace("samples = 64", "samples = 2048")
    path = tmp_path / "kill_study.toml"
    path.write_text(text)
    root = Path(__file__).resolve().parent.parent
    out = tmp_path / "killed"
    cmd = [sys.executable, "-m", "simulator", "study", str(path), "--out", str(out)]
    proc = subprocess.Popen(cmd, cwd=root, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    manifest = out / "manifest.json"
    n_at_kill = 0
    t0 = time.monotonic()
    try:
        while proc.poll() is None and time.monotonic() - t0 < 120:
            if manifest.is_file():
                try:
                    n_at_kill = len(json.loads(manifest.read_text())["chunks"])
                except ValueError:
                    n_at_kill = 0
                if n_at_kill >= 1:
                    proc.send_signal(signal.SIGKILL)
                    break
            time.sleep(0.01)
    finally:
        proc.wait(timeout=60)
    if proc.returncode == 0:
        pytest.skip("the study finished before it could be killed")
    assert n_at_kill >= 1 and not (out / "readings.csv").exists()
    res, long_b, summ_b = _run(path, out, mode="inprocess")
    assert res.chunks_loaded >= n_at_kill and res.chunks_computed == res.chunks_total - res.chunks_loaded > 0
    _, long_a, summ_a = _run(path, tmp_path / "whole", mode="inprocess")
    assert long_a == long_b and summ_a == summ_b


def test_chunks_another_build_traced_are_not_reused(tmp_path, monkeypatch):
    """A study folder resumed by another build of probesim (any file of the package changed, or
    another Warp or numpy) traces every chunk again, removes the other build's and says how many, once:
    chunks of two builds would agree only within their errors, and the study would no longer be the
    bytes of one run whole. The same build reuses them all (above), with no warning."""
    from simulator.study.trace import chunks

    path = tiny_study(tmp_path)
    _, long_a, _ = _run(path, tmp_path / "o", mode="inprocess")
    monkeypatch.setattr(chunks, "code_digest", lambda: "another build")
    res, long_b, _ = _run(path, tmp_path / "o", mode="inprocess")
    assert (res.chunks_loaded, res.chunks_computed) == (0, 4)
    assert [w for w in res.warnings if "another build of probesim" in w] == [
        f"{tmp_path / 'o'}: 4 finished chunks in this folder were traced by another build of probesim: removed, and "
        "traced again where this study needs them"]  # fmt: skip
    assert long_b == long_a  # the same code really: the same bytes
    assert len(list((tmp_path / "o" / "chunks").glob("*.npz"))) == 4  # the other build's 4 are gone
    res, _, _ = _run(path, tmp_path / "o", mode="inprocess")  # that build again: its own chunks reused, said nothing
    assert (res.chunks_loaded, res.chunks_computed) == (4, 0)
    assert not [w for w in res.warnings if "another build of probesim" in w]


def test_the_code_digest_follows_every_file_of_the_tree(tmp_path):
    """tree_digest changes when a source, table or settings file is edited, added, removed or
    renamed, and not for compiled caches or other files."""
    from simulator.study.trace.chunks import tree_digest

    (tmp_path / "pkg" / "sub").mkdir(parents=True)
    (tmp_path / "pkg" / "a.py").write_text("x = 1\n")
    (tmp_path / "pkg" / "sub" / "t.csv").write_text("1,2\n")
    root = tmp_path / "pkg"
    seen = {tree_digest(root)}
    (root / "__pycache__").mkdir()
    (root / "__pycache__" / "a.cpython-311.pyc").write_bytes(b"\0")
    (root / "notes.txt").write_text("not code")
    assert tree_digest(root) in seen
    (root / "a.py").write_text("x = 2\n")
    seen.add(tree_digest(root))
    (root / "b.toml").write_text("k = 1\n")
    seen.add(tree_digest(root))
    (root / "sub" / "t.csv").rename(root / "t.csv")
    seen.add(tree_digest(root))
    (root / "b.toml").unlink()
    seen.add(tree_digest(root))
    assert len(seen) == 5


def test_a_worker_of_another_build_refuses_a_chunk():
    """A dask worker installed apart from the study's machine may run another probesim, Warp or numpy:
    it refuses the chunk with one line naming it, rather than trace numbers of another build."""
    import re
    import socket

    from simulator.errors import UserError
    from simulator.study.trace.chunks import ChunkSpec, code_digest, compute_chunk

    spec = ChunkSpec("c0ffee", "key", 0, str(STAGE), "photometric", (), None, (), (), (), {}, 1, code="another build")
    assert code_digest() != "another build"
    with pytest.raises(UserError, match=rf"^chunk c0ffee: the worker on {re.escape(socket.gethostname())} runs another build of probesim"):
        compute_chunk(spec)
