"""The same kernels on CUDA: readings agree with the CPU within their errors.

Skipped where Warp finds no CUDA device (CI has none)."""

from pathlib import Path

import numpy as np
import pytest

from simulator.config.loader import load_config
from simulator.engine.driver import Engine, cuda_available
from simulator.pipeline import collect_sensors, load_scene

CONFIGS = Path(__file__).resolve().parents[1] / "configs"

pytestmark = pytest.mark.skipif(not cuda_available(), reason="no CUDA device")


@pytest.mark.parametrize("config, method", [("rect", "light"), ("quickstart", "path"), ("furnace", "path")])
def test_cpu_and_cuda_agree_within_errors(config, method):
    """Same scene, same seed: the two devices draw the same random streams but
    round differently, so readings must agree within 4 combined standard
    errors (plus float32 slack), not bit for bit."""
    cfg = load_config(CONFIGS / f"{config}.toml")
    scene = load_scene(cfg)
    sensors = [s for s in collect_sensors(cfg, scene) if s.kind.name != "PROBE"][:32]
    cpu = Engine(scene, sensors, device="cpu").run(method, samples=4096, seed=3)
    gpu = Engine(scene, sensors, device="cuda").run(method, samples=4096, seed=3)
    assert gpu.device.startswith("cuda")
    bound = 4 * np.hypot(cpu.stderr, gpu.stderr) + 2e-6 * np.abs(cpu.mean) + 1e-12
    assert np.all(np.abs(cpu.mean - gpu.mean) <= bound)
