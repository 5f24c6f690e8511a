"""The README is for users: short, its config reference complete and current, its links and the docs' links whole."""

from __future__ import annotations

import re
from pathlib import Path

from simulator.config.keys import BEGIN, END, key_rows, reference_markdown

ROOT = Path(__file__).resolve().parents[1]
README = ROOT / "README.md"
MAX_LINES = 400

_LINK = re.compile(r"!?\[[^\]]*\]\(([^)\s]+)(?:\s+\"[^\"]*\")?\)")


def _text(path: Path) -> str:
    return path.read_text(encoding="utf-8")


def test_the_readme_is_at_most_400_lines():
    n = len(_text(README).splitlines())
    assert n <= MAX_LINES, f"README.md has {n} lines (at most {MAX_LINES}: move the rest to docs/)"


def test_the_readme_opens_with_the_install_and_test_commands():
    """The first code block installs and runs the bundled quickstart, then installs the test extra
    and runs the tests (what .ci/run runs)."""
    block = re.search(r"```bash\n(.*?)```", _text(README), re.DOTALL).group(1)
    lines = block.strip().splitlines()
    assert lines[0].startswith("python3 -m pip install . && probesim run configs/quickstart.toml")
    assert lines[1].startswith('python3 -m pip install ".[test]" && python3 -m pytest')


def test_the_config_reference_in_the_readme_is_the_schema_s():
    """The table between the markers is exactly what ``python -m simulator.config.keys`` renders
    now: every key of every table of both schemas, none stale (regenerate with ``--write README.md``)."""
    text = _text(README)
    assert text.count(BEGIN) == 1 and text.count(END) == 1
    between = text[text.index(BEGIN) + len(BEGIN) : text.index(END)]
    assert between.strip() == reference_markdown().strip(), (
        "README.md's config reference is stale: run python -m simulator.config.keys --write README.md")


def test_every_key_has_a_meaning():
    """Every row of both schemas has a description (a new field without one fails here)."""
    from simulator.config.schema import RunFile
    from simulator.study.schema import Study

    for model in (RunFile, Study):
        rows = key_rows(model)
        assert len(rows) > 30
        missing = [key for key, _, _, _, meaning in rows if not meaning.strip()]
        assert not missing, f"{model.__name__}: keys with no description: {missing}"


def test_the_reference_lists_every_key_the_loaders_take():
    """Spot checks that the walk reaches nested and per-kind keys: a sensor kind's own key, a grid key,
    a scenario's sun, an annual key, a control key."""
    body = reference_markdown()
    for key in ("simulation.rel_error", "sensor.half_angle_deg", "sensor.facing", "grid.spacing", "output.responses",
                "scenario.sun.azimuth_deg", "scenario.sky.horizontal_lx", "annual.sun_bin_deg", "control.deadband",
                "area.maintenance_factor", "compute.sensor_block"):  # fmt: skip
        assert f"| `{key}` |" in body, key


def _slug(heading: str) -> str:
    """GitHub's anchor of a heading: lower case, punctuation dropped, spaces to hyphens."""
    text = re.sub(r"[`*_]", "", heading.strip().lstrip("#").strip()).lower()
    text = re.sub(r"[^\w\- ]", "", text)
    return text.replace(" ", "-")


def _anchors(path: Path) -> set[str]:
    out, fenced = set(), False
    for line in _text(path).splitlines():
        if line.lstrip().startswith("```"):
            fenced = not fenced
        elif not fenced and re.match(r"#{1,6}\s", line):
            out.add(_slug(line))
    return out


def test_every_relative_link_in_the_readme_and_docs_resolves():
    """Each ``[text](target)`` that is not a web address names a file that exists (relative to the page),
    and its ``#anchor``, if any, a heading of that page."""
    pages = [README] + sorted((ROOT / "docs").glob("*.md"))
    bad = []
    for page in pages:
        for target in _LINK.findall(_text(page)):
            if re.match(r"[a-z]+:", target):
                continue
            file, _, anchor = target.partition("#")
            dest = (page.parent / file).resolve() if file else page
            if not dest.exists():
                bad.append(f"{page.relative_to(ROOT)}: {target}: no such file")
            elif anchor and dest.suffix == ".md" and anchor not in _anchors(dest):
                bad.append(f"{page.relative_to(ROOT)}: {target}: no such heading")
    assert not bad, "\n".join(bad)
