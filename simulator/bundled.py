"""Where the bundled stages, textures and configs are.

The project's reference stages (``stages/``, with ``stages/textures/``) and
their configs (``configs/``, with ``configs/stability/`` and the study files
``configs/studies/``) live at the top of
a source checkout. A built wheel carries a copy of both folders inside the
package, as ``simulator/_data/stages`` and ``simulator/_data/configs`` (the
build step is in ``setup.py``), so an installed probesim finds them too.
Both copies keep the two folders side by side, so a config's relative stage
path (``stage = "../stages/x.usda"``) resolves in either.

The lookup depends only on where this module is, never on the working
directory: ``probesim verify`` reads the same cases from anywhere.
"""

from __future__ import annotations

from pathlib import Path

from simulator.errors import UserError

__all__ = ["data_root", "configs_dir", "stages_dir", "bundled_configs", "example_names", "run_example_names",
           "study_example_names", "example_config", "STUDIES"]

_PACKAGE = Path(__file__).resolve().parent
#: the copy a built wheel installs inside the package
_INSTALLED = _PACKAGE / "_data"
#: the source checkout holding this package
_CHECKOUT = _PACKAGE.parent


def _holds_data(root: Path) -> bool:
    return (root / "configs").is_dir() and (root / "stages").is_dir()


def data_root(command: str = "probesim") -> Path:
    """The folder holding ``configs/`` and ``stages/``.

    The installed copy inside the package when there is one (a wheel
    install), else the source checkout the package sits in (a checkout, or
    an editable install), recognised by its ``pyproject.toml``.

    Raises
    ------
    UserError
        Neither is present (a package copied without its data).
    """
    if _holds_data(_INSTALLED):
        return _INSTALLED
    if (_CHECKOUT / "pyproject.toml").is_file() and _holds_data(_CHECKOUT):
        return _CHECKOUT
    raise UserError(f"{command}: the bundled configs and stages are missing from this installation "
                    f"(looked in {_INSTALLED} and {_CHECKOUT}); reinstall probesim")


def configs_dir(sub: str = "", command: str = "probesim") -> Path:
    """``configs/<sub>`` of the bundled data (see :func:`data_root`).

    Raises
    ------
    UserError
        The data or that sub-folder is missing.
    """
    root = data_root(command)
    d = root / "configs" / sub
    if not d.is_dir():
        raise UserError(f"{command}: configs/{sub} not found in the bundled data ({root})")
    return d


def stages_dir(command: str = "probesim") -> Path:
    """``stages/`` of the bundled data (see :func:`data_root`)."""
    return data_root(command) / "stages"


def bundled_configs(names: tuple[str, ...], command: str) -> list[Path]:
    """The named configs (``<name>.toml``) present in :func:`configs_dir`."""
    d = configs_dir(command=command)
    found = [d / f"{n}.toml" for n in names if (d / f"{n}.toml").exists()]
    if not found:
        raise UserError(f"{command}: no bundled configs found in {d} (name configs)")
    return found


#: the folder of ``configs/`` holding the bundled study files, examples for ``probesim study``
STUDIES = "studies"


def run_example_names(command: str = "example") -> list[str]:
    """Names of the bundled top-level configs (``configs/<name>.toml``, for ``probesim run``), sorted."""
    return sorted(p.stem for p in configs_dir(command=command).glob("*.toml"))


def study_example_names(command: str = "example") -> list[str]:
    """Names of the bundled study files (``configs/studies/<name>.toml``, for ``probesim study``), sorted."""
    d = data_root(command) / "configs" / STUDIES
    return sorted(p.stem for p in d.glob("*.toml")) if d.is_dir() else []


def example_names(command: str = "example") -> list[str]:
    """Every bundled example: the run configs, sorted, then the study files, sorted."""
    return run_example_names(command) + study_example_names(command)


def example_config(name: str, command: str = "example") -> Path | None:
    """The bundled file of example ``name`` (a run config first, else a study file); None if none."""
    for path in (configs_dir(command=command) / f"{name}.toml", data_root(command) / "configs" / STUDIES / f"{name}.toml"):
        if path.is_file():
            return path
    return None
