"""probesim: a radiometric light-probe sensor simulator.

Public API (see docs/python-api.md)::

    import simulator
    cfg = simulator.load_config("configs/quickstart.toml")
    out = simulator.run(cfg)          # writes the CSV and run record
    for row in out.rows: ...

Heavy modules (Warp, USD) load on first use, so ``import simulator`` is cheap.
"""

__version__ = "0.1.0"

import time as _time

#: when the package began loading (ns since the epoch): every probesim module this process runs was read
#: after it (the disk stage cache trusts only code last modified before, simulator.scene.stage_disk)
_LOADED_NS = _time.time_ns()

__all__ = ["__version__", "load_config", "run", "RunConfig", "RunOutput", "Scene", "Sensor", "Light", "UserError"]

_LAZY = {
    "load_config": "simulator.config",
    "RunConfig": "simulator.config",
    "run": "simulator.pipeline",
    "RunOutput": "simulator.pipeline",
    "Scene": "simulator.scene.model",
    "Sensor": "simulator.scene.model",
    "Light": "simulator.scene.model",
    "UserError": "simulator.errors",
}


def __getattr__(name):
    if name in _LAZY:
        import importlib

        return getattr(importlib.import_module(_LAZY[name]), name)
    raise AttributeError(f"module 'simulator' has no attribute {name!r}")
