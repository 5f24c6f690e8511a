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
