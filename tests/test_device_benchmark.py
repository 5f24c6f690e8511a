"""benchmarks/device.py, the GPU benchmark waiting for a device, runs on the CPU and keeps its result format.

Until a CUDA device is lent its figures cannot be measured (README, docs/benchmarks.md), so the
script must be ready when one is: here one office workload runs on the CPU through the same code a
CUDA run takes (another ``device`` only), and its JSON line carries every key of the fixed format
(``KEYS``), with a sample rate, a ray rate and a time to the target that are positive and finite.
"""

from __future__ import annotations

import importlib.util
import json
import math
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]


def _device_benchmark():
    spec = importlib.util.spec_from_file_location("device_benchmark", ROOT / "benchmarks" / "device.py")
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    return mod


def test_a_workload_on_the_cpu_gives_every_key_of_the_fixed_format():
    bench = _device_benchmark()
    row = bench.measure("office_emissive", "cpu", samples=16, rel_error=0.2, every=200)
    line = json.loads(json.dumps({k: row[k] for k in bench.KEYS}))
    assert list(line) == list(bench.KEYS)
    assert line["device"] == "cpu" and line["sensors"] == len(range(0, 1464, 200))
    for key in ("samples_per_s", "rays_per_s", "rays_per_sample", "fixed_s", "time_to_target_s"):
        assert math.isfinite(line[key]) and line[key] > 0, key
    assert line["target_met"] is True and line["adaptive_samples"] >= 16 * line["sensors"]
    table = bench.table([row]).splitlines()
    assert len(table) == 2 and table[1].split()[:2] == ["office_emissive", "cpu"]
