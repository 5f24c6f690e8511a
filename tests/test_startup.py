"""A short command's start-up (simulator.commands.startup): collections paused and one BLAS thread
in a fresh process only, and collections back on afterwards."""

from __future__ import annotations

import gc
import os
import subprocess
import sys
from pathlib import Path

from simulator.commands.cli import main
from simulator.commands.startup import lean_start

ROOT = Path(__file__).resolve().parents[1]

PROBE = """
import gc, os, sys
from simulator.commands.startup import lean_start, resume_collections
took = lean_start()
print(took, gc.isenabled(), os.environ.get("OPENBLAS_NUM_THREADS"), "numpy" in sys.modules)
resume_collections()
print(gc.isenabled())
"""


def _fresh(env_extra: dict) -> list[str]:
    env = {k: v for k, v in os.environ.items() if k != "OPENBLAS_NUM_THREADS"}
    env.update(env_extra, PYTHONPATH=os.pathsep.join([str(ROOT), env.get("PYTHONPATH", "")]))
    out = subprocess.run([sys.executable, "-c", PROBE], env=env, capture_output=True, text=True, check=True)
    return out.stdout.split()


def test_a_fresh_process_starts_lean_and_resumes_collections():
    assert _fresh({}) == ["True", "False", "1", "False", "True"]
    assert _fresh({"OPENBLAS_NUM_THREADS": "2"}) == ["True", "False", "2", "False", "True"]  # the user's setting stays


def test_an_in_process_caller_is_left_as_it_is(capsys):
    """``main(argv)`` called from Python (not the process's own command line) starts nothing lean;
    and once numpy is loaded there is nothing to gain: ``lean_start`` does nothing."""
    import numpy  # noqa: F401

    assert main(["plan", str(ROOT / "configs" / "point.toml")]) == 0
    assert gc.isenabled()
    assert "analytic" in capsys.readouterr().out
    assert lean_start() is False and gc.isenabled()


ENDING = """
import atexit, sys, threading
from simulator.commands.startup import end_lean
atexit.register(lambda: print("exit functions ran"))
if sys.argv[1] == "thread":
    stop = threading.Event()
    threading.Thread(target=stop.wait).start()  # not a daemon: a normal exit waits for it
    end_lean(3)
    print("returned")
    stop.set()
    sys.exit(4)
sys.stdout.write("x" * 200_000)  # more than a pipe's buffer: all of it must still arrive
end_lean(3)
print("not reached")
"""


def _ending(mode: str) -> subprocess.CompletedProcess:
    env = dict(os.environ, PYTHONPATH=os.pathsep.join([str(ROOT), os.environ.get("PYTHONPATH", "")]))
    return subprocess.run([sys.executable, "-c", ENDING, mode], env=env, capture_output=True, text=True)


def test_a_lean_process_ends_at_once_with_its_output_and_exit_functions():
    """``end_lean(3)``: status 3, the 200,000 characters written before it and the exit function's line
    arrive whole, and nothing after it runs."""
    out = _ending("plain")
    assert out.returncode == 3
    assert out.stdout == "x" * 200_000 + "exit functions ran\n"


def test_a_running_thread_makes_it_end_the_usual_way():
    """A thread still running (not a daemon): ``end_lean`` returns, the usual exit waits for the thread
    and runs the exit functions once."""
    out = _ending("thread")
    assert out.returncode == 4
    assert out.stdout == "returned\nexit functions ran\n"


SCAN = """
import sys
from simulator.engine import device
if sys.argv[1] == "skip":
    device.skip_reload_scan()
from simulator.engine import kernel_modules as KM
m = KM.trace_module(False).module
import warp._src.context as C
refs = sum(len(u.references) for name, u in C.user_modules.items() if name.startswith("simulator.kernels"))
print(refs, m.get_module_hash(1).hex())
"""


def test_skipping_the_reload_scan_leaves_the_module_hash_as_it_is():
    """Warp's scan of probesim's kernel functions for re-imports, skipped in a fresh run: no dependency
    noted between probesim's kernel modules, and the trace module's hash (what finds its object file)
    the same as with the scan."""
    env = dict(os.environ, PYTHONPATH=os.pathsep.join([str(ROOT), os.environ.get("PYTHONPATH", "")]))
    said = {mode: subprocess.run([sys.executable, "-c", SCAN, mode], env=env, capture_output=True, text=True,
                                 check=True).stdout.split() for mode in ("scan", "skip")}  # fmt: skip
    assert int(said["scan"][0]) > 0 and int(said["skip"][0]) == 0
    assert said["scan"][1] == said["skip"][1]
