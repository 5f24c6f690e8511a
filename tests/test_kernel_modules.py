"""Kernel modules: a compile is said aloud when the cache lacks a module and not when it has it.

A cold compile of the real trace modules takes a minute or more of CPU, so
the cache behaviour is checked on a one-line kernel in a module of its own,
compiled into a fresh temporary kernel cache: the same code path
(:func:`kernel_modules.is_cached`, :func:`kernel_modules.load`) that a run
takes for the trace modules. Which module a stage's run loads is checked on
the real ones (they are compiled once per test run by other tests too).
"""

from __future__ import annotations

import io
from pathlib import Path

import numpy as np
import pytest

from simulator.commands.cli import main
from simulator.commands.compiling import CompileDisplay, header
from simulator.engine import kernel_modules as KM
from simulator.engine.device import warp

ROOT = Path(__file__).resolve().parents[1]

wp = warp()


@wp.kernel(module="tests.kernel_modules_tiny")
def _twice(a: wp.array(dtype=float)):
    i = wp.tid()
    a[i] = 2.0 * a[i]


TINY = KM.KernelModule("tiny test kernel", _twice.module)


@pytest.fixture
def fresh_cache(tmp_path, monkeypatch):
    """An empty kernel cache for this test, and the tiny module unloaded (as in a new process)."""
    monkeypatch.setattr(wp.config, "kernel_cache_dir", str(tmp_path / "kernels"))
    _twice.module.unload()
    yield tmp_path / "kernels"
    _twice.module.unload()


@pytest.fixture
def reports(monkeypatch):
    """Every CompileProgress of the test, in order."""
    got = []
    monkeypatch.setattr(KM, "_reporter", got.append)
    return got


def _launch_twice() -> np.ndarray:
    a = wp.array(np.array([1.0, 3.0], dtype=np.float32), device="cpu")
    wp.launch(_twice, dim=2, inputs=[a], device="cpu")
    return a.numpy()


def test_cold_cache_reports_the_compile_and_warm_cache_does_not(fresh_cache, reports):
    assert not KM.is_cached(TINY)
    assert KM.load([TINY]) == ("tiny test kernel",)
    assert reports[0].done == 0 and reports[0].finished is None and reports[0].labels == ("tiny test kernel",)
    assert reports[-1].done == 1 and reports[-1].finished == "tiny test kernel"
    assert [r for r in reports if r.finished is not None] == reports[-1:]  # one module: one completion
    np.testing.assert_array_equal(_launch_twice(), [2.0, 6.0])
    # a later process: the module is not loaded, but its object file is in the cache
    _twice.module.unload()
    assert KM.is_cached(TINY)
    n = len(reports)
    assert KM.load([TINY]) == ()
    assert len(reports) == n  # nothing compiled, nothing said
    np.testing.assert_array_equal(_launch_twice(), [2.0, 6.0])


def test_display_names_the_compile_before_it_and_each_module_after(fresh_cache, monkeypatch):
    out = io.StringIO()  # not a terminal: a line per module, no bar
    monkeypatch.setattr(KM, "_reporter", CompileDisplay(out))
    KM.load([TINY])
    lines = out.getvalue().splitlines()
    assert lines[0] == header(1, "cpu") + ": tiny test kernel"
    assert lines[0].startswith("compiling kernels (first run only, cached afterwards): 1 module on cpu")
    assert lines[1].startswith("compiled tiny test kernel (1/1, ")
    assert len(lines) == 2
    _twice.module.unload()
    out.truncate(0)
    KM.load([TINY])
    assert out.getvalue() == ""  # cached: silent


def test_warmup_exits_0_and_leaves_the_cache_serving_a_later_load(fresh_cache, monkeypatch, capsys):
    """``probesim warmup`` on its cheap form (the tiny module standing for every module): exit 0, the
    compile said on stderr, and a later load (a run's) finds every module cached and compiles nothing."""
    monkeypatch.setattr(KM, "every_module", lambda: [TINY])
    monkeypatch.setattr(KM, "_reporter", None)  # main() sets the process's reporter: restored after the test
    assert main(["warmup", "--device", "cpu"]) == 0
    cap = capsys.readouterr()
    assert "compiling kernels (first run only, cached afterwards): 1 module on cpu" in cap.err
    assert "kernels ready on cpu: 1 modules, 1 compiled, 0 cached" in cap.out
    _twice.module.unload()
    assert all(KM.is_cached(km) for km in KM.every_module())
    assert main(["warmup", "--device", "cpu"]) == 0
    cap = capsys.readouterr()
    assert cap.err == "" and "all cached" in cap.out
    _twice.module.unload()
    got = []
    monkeypatch.setattr(KM, "_reporter", got.append)
    assert KM.load([TINY]) == () and got == []
    np.testing.assert_array_equal(_launch_twice(), [2.0, 6.0])


def test_warmup_cuda_without_a_device_is_a_one_line_error(capsys, monkeypatch):
    from simulator.engine.device import cuda_available

    if cuda_available():
        pytest.skip("a CUDA device is present")
    monkeypatch.setattr(KM, "_reporter", None)
    assert main(["warmup", "--device", "cuda"]) == 2
    err = capsys.readouterr().err.strip()
    assert err.startswith("probesim: error: --device cuda: no CUDA device") and "\n" not in err


def test_a_matte_stage_loads_only_its_variant():
    """The quickstart (all matte) loads the matte trace module (estimator and probe kernels); the
    surface model's module and the closed forms' stay unloaded."""
    from simulator.engine.driver import Engine
    from simulator.scene.model import Sensor, SensorKind
    from simulator.scene.usd import load_stage

    matte, full = KM.trace_module(False).module, KM.trace_module(True).module
    full_loaded = dict(full.execs)
    scene = load_stage(ROOT / "stages" / "quickstart.usda")
    engine = Engine(scene, [Sensor("s", SensorKind.IRRADIANCE, np.array([2.5, 2.0, 0.8]), np.array([0.0, 0.0, 1.0]))])
    engine.run("path", samples=8, seed=1)
    assert engine.scene_rec.surfaces == 0
    assert matte.execs and dict(full.execs) == full_loaded  # nothing new loaded for the surface model
    assert engine.trace_variant.estimate_kernel.module is matte
    from simulator.kernels import probe as KP

    assert KP.probe_kernel_for(0).module is matte and KP.probe_kernel_for(1).module is full


def test_a_warp_that_names_its_files_otherwise_still_loads_silently(fresh_cache, reports, monkeypatch):
    """The cache test reads Warp's private file naming: where that is missing, the module is taken as
    cached (nothing said, never a false "compiling" on every run) and still compiles and runs."""
    def renamed(*args):
        raise AttributeError("'Module' object has no attribute '_get_meta_name'")

    monkeypatch.setattr(KM, "_cache_files", renamed)
    assert KM.is_cached(TINY)
    assert KM.load([TINY]) == () and reports == []
    assert _twice.module.execs  # loaded (compiled by Warp, unannounced)
    np.testing.assert_array_equal(_launch_twice(), [2.0, 6.0])


def test_every_module_compiles_with_warps_flags_at_the_measured_inlining_thresholds():
    """Warp's CPU flags with only the two inlining thresholds replaced by ``INLINE_THRESHOLDS``
    (5000 and 1700: docs/DESIGN.md §Kernel modules), set once for the process so that modules
    compiled on two threads at once never ask LLVM's process-wide options for different values; a
    flag string without thresholds (or none) is left as it is."""
    from simulator.engine import device

    warp_default = ("-march=native -mllvm=-inline-threshold=9000 -mllvm=-inline-cold-callsite-threshold=3000"
                    " -mllvm=-slp-recursion-max-depth=4")
    assert device.INLINE_THRESHOLDS == (5000, 1700)
    assert device.cpu_compiler_flags(warp_default) == (
        "-march=native -mllvm=-inline-threshold=5000 -mllvm=-inline-cold-callsite-threshold=1700"
        " -mllvm=-slp-recursion-max-depth=4")
    assert device.cpu_compiler_flags("-march=native") == "-march=native"
    assert device.cpu_compiler_flags(None) is None
    flags = wp.config.cpu_compiler_flags
    assert "-inline-threshold=5000" in flags and "-inline-cold-callsite-threshold=1700" in flags
    assert _twice.module.options["cpu_compiler_flags"] is None  # no module asks for flags of its own
