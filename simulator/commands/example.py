"""``probesim example NAME DIR``: a bundled config (or study file) and its stage, copied out.

The copy is self-contained and editable::

    DIR/NAME.toml            the config, its paths rewritten to point inside DIR
    DIR/stages/<stage>.usda  the stage it traces
    DIR/stages/textures/...  the files that stage names (asset paths), if any

so ``probesim run DIR/NAME.toml`` works wherever probesim is installed. In
the config only two values change: ``stage`` (``"../stages/x.usda"`` becomes
``"stages/x.usda"``) and an ``[output] csv`` that would land outside DIR
(``"../out/x.csv"`` becomes ``"out/x.csv"``); a ``[spectra] lights`` SPD
file under ``stages/`` is copied too and its path rewritten alike; comments
stay as they are. The study files of ``configs/studies/`` (placement,
daylight, annual) are examples too, for ``probesim study DIR/NAME.toml``:
their ``[output] dir`` becomes ``"out/<name>"`` and an ``[annual] weather``
file is copied beside the stage (``stages/weather/...``).

Nothing is written if the name is unknown or any file to be written already
exists with other, non-empty contents: that is a one-line :class:`UserError`
(exit 2). A file identical to the one it would be (a stage two examples
share) is simply kept, so several examples can go in one folder.
"""

from __future__ import annotations

import re
import shutil
import tomllib
from pathlib import Path, PurePosixPath

from simulator.bundled import STUDIES, example_config, example_names, stages_dir
from simulator.errors import UserError

__all__ = ["list_examples", "example_kind", "example_files", "copy_example"]

#: an asset path in a .usda layer, ``@./textures/x.exr@`` (not ``@@@`` text)
_ASSET = re.compile(r"(?<!@)@([^@\n]+)@(?!@)")


def list_examples() -> list[tuple[str, str]]:
    """``(name, stage)`` of every bundled example (run configs, then studies), ``stage`` relative to ``stages/``."""
    out = []
    for name in example_names():
        stage = _stage_of(example_config(name))
        out.append((name, stage.relative_to(stages_dir("example").resolve()).as_posix()))
    return out


def example_kind(name: str) -> str:
    """What example ``name`` is: ``"run"`` (a run config), or a study file: ``"study: annual"`` (an
    ``[annual]`` year), ``"study: daylight"`` (a group traced as sky patches), ``"study: placement"``."""
    config = example_config(name)
    if config is None or config.parent.name != STUDIES:
        return "run"
    with open(config, "rb") as fh:
        raw = tomllib.load(fh)
    if "annual" in raw:
        return "study: annual"
    if any("sky" in g for g in raw.get("group", [])):
        return "study: daylight"
    return "study: placement"


def _command(name: str) -> str:
    """The command that runs example ``name``: ``run`` or ``study``."""
    return "run" if example_kind(name) == "run" else "study"


def _stage_of(config: Path) -> Path:
    with open(config, "rb") as fh:
        return (config.parent / tomllib.load(fh)["stage"]).resolve()


def _assets(layer: Path, root: Path) -> list[Path]:
    """The files a stage layer names (asset paths), recursively, under ``root``."""
    found: list[Path] = []
    todo = [layer]
    while todo:
        current = todo.pop()
        for ref in _ASSET.findall(current.read_text(encoding="utf-8")):
            path = (current.parent / ref).resolve()
            if not path.is_relative_to(root) or not path.is_file():
                raise RuntimeError(f"bundled stage {current} names {ref}, which is not a bundled file")
            if path not in found and path != layer:
                found.append(path)
                if path.suffix in (".usda", ".usd", ".usdc"):
                    todo.append(path)
    return found


def example_files(name: str) -> tuple[str, dict[Path, Path]]:
    """The rewritten config text and the stage files of example ``name``.

    Returns
    -------
    (str, dict)
        The config's text for ``DIR/<name>.toml``, and ``{source: path
        relative to DIR}`` for the stage and every file it names.

    Raises
    ------
    UserError
        No bundled config has that name.
    """
    config = example_config(name)
    if config is None:
        raise UserError(f"example: no bundled example {name!r} (one of: {', '.join(example_names())})")
    root = stages_dir("example").resolve()
    text = config.read_text(encoding="utf-8")
    raw = tomllib.loads(text)
    stage = (config.parent / raw["stage"]).resolve()
    files = {p: Path("stages", p.relative_to(root)) for p in [stage, *_assets(stage, root)]}
    stage_to = PurePosixPath(*files[stage].parts).as_posix()
    text = _replace_value(text, "stage", raw["stage"], stage_to)
    outputs = {}  # ("output", key): new value, for an output (a run's csv, a study's dir) outside the folder
    for key in ("csv", "dir"):
        value = raw.get("output", {}).get(key)
        if value is not None and PurePosixPath(value).parts[:1] == ("..",):
            outputs[key] = f"out/{PurePosixPath(value).name}"
            text = _replace_value(text, key, value, outputs[key])
    weather = raw.get("annual", {}).get("weather")
    weather_to = None
    if isinstance(weather, str):  # a study's climate file: copied beside the stage
        src = (config.parent / weather).resolve()
        if not src.is_relative_to(root) or not src.is_file():
            raise RuntimeError(f"bundled study {config} names {weather}, which is not a bundled file")
        files[src] = Path("stages", src.relative_to(root))
        weather_to = PurePosixPath(*files[src].parts).as_posix()
        text = _replace_value(text, "weather", weather, weather_to)
    lights = raw.get("spectra", {}).get("lights")
    lights_to = None
    if isinstance(lights, str) and lights.lower().endswith(".csv"):  # an SPD file: copied beside the stage
        spd = (config.parent / lights).resolve()
        if not spd.is_relative_to(root) or not spd.is_file():
            raise RuntimeError(f"bundled config {config} names {lights}, which is not a bundled file")
        files[spd] = Path("stages", spd.relative_to(root))
        lights_to = PurePosixPath(*files[spd].parts).as_posix()
        text = _replace_value(text, "lights", lights, lights_to)
    new = tomllib.loads(text)  # the rewrite must have changed exactly those values
    if (new["stage"] != stage_to or any(new["output"][k] != v for k, v in outputs.items())
            or (lights_to and new["spectra"]["lights"] != lights_to)
            or (weather_to and new["annual"]["weather"] != weather_to)):
        raise RuntimeError(f"bundled config {config}: could not rewrite its paths")
    return text, files


def _replace_value(text: str, key: str, old: str, new: str) -> str:
    """Replace the string value of the first ``key = "old"`` line."""
    line = re.compile(rf'^(\s*{key}\s*=\s*)(["\']){re.escape(old)}\2', re.MULTILINE)
    return line.sub(lambda m: f'{m.group(1)}"{new}"', text, count=1)


def copy_example(name: str, dest: str | Path) -> list[Path]:
    """Copy example ``name`` into folder ``dest`` (created if missing).

    Returns
    -------
    list of Path
        The files written, the config first.

    Raises
    ------
    UserError
        Unknown name, ``dest`` is a file, or a file to be written exists,
        is not empty and differs; nothing is written then.
    """
    text, files = example_files(name)
    dest = Path(dest)
    if dest.exists() and not dest.is_dir():
        raise UserError(f"example: {dest} exists and is not a folder")
    targets = [dest / f"{name}.toml", *(dest / rel for rel in files.values())]
    contents = [text.encode("utf-8"), *(src.read_bytes() for src in files)]
    for t, data in zip(targets, contents):
        if t.exists() and (not t.is_file() or (t.stat().st_size > 0 and t.read_bytes() != data)):
            raise UserError(f"example: {t} already exists; choose a new or empty folder")
    for (src, rel) in files.items():
        (dest / rel).parent.mkdir(parents=True, exist_ok=True)
        shutil.copyfile(src, dest / rel)
    targets[0].parent.mkdir(parents=True, exist_ok=True)
    targets[0].write_text(text, encoding="utf-8")
    return targets


def main_example(name: str | None, dest: str | None, list_only: bool, log=print) -> int:
    """The ``example`` command: list the examples, or copy one out."""
    if list_only:
        rows = list_examples()
        width = max(len(n) for n, _ in rows)
        swidth = max(len(stage) for _, stage in rows) + len("stages/")
        for n, stage in rows:
            log(f"{n:<{width}}  {'stages/' + stage:<{swidth}}  {example_kind(n)}")
        return 0
    if name is None or dest is None:
        raise UserError("example: give an example's NAME and the DIR to copy it into (names: probesim example --list)")
    written = copy_example(name, dest)
    log(f"wrote {', '.join(str(p) for p in written)}")
    log(f"run it: probesim {_command(name)} {written[0]}")
    return 0
