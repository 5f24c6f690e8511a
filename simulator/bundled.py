"""Where the bundled reference configs are.

The stages and configs ship beside the package in a source checkout; the
commands that run them as a suite (bench, chart, stability, verify) look in
``configs/`` under the working directory first, so a user's own copy of the
folder is used when they run from it.
"""

from __future__ import annotations

from pathlib import Path

from simulator.errors import UserError

__all__ = ["configs_dir", "bundled_configs"]


def configs_dir(sub: str = "", command: str = "probesim") -> Path:
    """``configs/<sub>`` under the working directory, else beside the package.

    Raises
    ------
    UserError
        Neither exists (for example an installed copy run outside a checkout).
    """
    for root in (Path.cwd(), Path(__file__).resolve().parents[1]):
        d = root / "configs" / sub
        if d.is_dir():
            return d
    raise UserError(f"{command}: configs/{sub} not found (run from the project directory, or name configs)")


def bundled_configs(names: tuple[str, ...], command: str) -> list[Path]:
    """The named configs (``<name>.toml``) present in :func:`configs_dir`."""
    d = configs_dir(command=command)
    found = [d / f"{n}.toml" for n in names if (d / f"{n}.toml").exists()]
    if not found:
        raise UserError(f"{command}: no bundled configs found in {d} (name configs)")
    return found
