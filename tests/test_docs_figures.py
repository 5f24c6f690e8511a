"""Every figure the README and docs/ quote comes from a command named beside it.

The rule, applied mechanically to README.md and docs/*.md (not docs/DESIGN.md,
the design notes, nor docs/REFERENCES.md, published values):

- A *measured figure* is a number with a unit of time (``0.66 s``, ``30 ms``,
  ``0.2 µs``, ``77 s⁻¹``), a speed or cost ratio written as a number glued to
  ``×`` or ``x`` (``1.8×``, ``0.15×``, ``1.90x``; ``64 × 32``, a size, is not one),
  or a percentage of more or less time, CPU, variance, rays or samples, faster
  or slower (``16% less variance``, ``21% faster``; ``0.2% less area`` is geometry).
- Each *section* (the text under one heading, down to the next heading of any
  level; fenced code blocks belong to their section) that holds a measured
  figure must name a command that measures: in backticks or a fenced code
  block, ``probesim <command>``, ``python -m <module>`` or ``python
  benchmarks/<script>.py`` (``python3``, a leading ``PYTHONPATH=.``, ``time``
  or ``$`` allowed).
- A figure nobody can rerun is kept only as history: its paragraph says
  ``historical`` and names the tree it was measured on by its commit (7 to 40
  hex digits); such paragraphs are exempt.
"""

from __future__ import annotations

import re
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
#: the pages the rule leaves out: design notes and published values
EXEMPT_PAGES = {"docs/DESIGN.md", "docs/REFERENCES.md"}

_TIME = r"\d[\d,]*(?:\.\d+)?\s?(?:s|ms|µs|us|min)(?![\w/])"
_RATIO = r"\d[\d,]*(?:\.\d+)?[×x](?![\w\d]|\s*\d)"
_PERCENT = r"\d[\d,]*(?:\.\d+)?\s?%\s+(?:(?:less|more)\s+(?:CPU|time|wall|variance|rays|samples)|faster|slower)\b"
FIGURE = re.compile(rf"(?<![\w.^/-])(?:{_TIME}|{_RATIO}|{_PERCENT})")

_COMMAND = r"(?:PYTHONPATH=\S+\s+)?(?:time\s+)?(?:probesim\s+[a-z]|python3?\s+(?:-m\s+[\w.]+|benchmarks/[\w]+\.py))"
#: a command in backticks, or on its own line in a code block
COMMAND_INLINE = re.compile(rf"`\s*(?:\$\s*)?{_COMMAND}")
COMMAND_LINE = re.compile(rf"^\s*(?:\$\s*)?(?:\w+=\S+\s+)*\\?\s*{_COMMAND}")
HISTORICAL = re.compile(r"historical.*?\b[0-9a-f]{7,40}\b", re.IGNORECASE | re.DOTALL)


def pages() -> list[Path]:
    docs = (p for p in (ROOT / "docs").glob("*.md") if p.relative_to(ROOT).as_posix() not in EXEMPT_PAGES)
    return [ROOT / "README.md"] + sorted(docs)


def sections(text: str) -> list[tuple[str, list[str], list[str]]]:
    """``(heading, prose lines, code lines)`` per section; ``#`` lines inside code fences are not headings."""
    out: list[tuple[str, list[str], list[str]]] = [("(top)", [], [])]
    fenced = False
    for line in text.splitlines():
        if line.lstrip().startswith("```"):
            fenced = not fenced
            continue
        if not fenced and re.match(r"#{1,6}\s", line):
            out.append((line.strip(), [], []))
            continue
        out[-1][2 if fenced else 1].append(line)
    return out


def _paragraphs(lines: list[str]) -> list[str]:
    text = "\n".join(lines)
    return [p for p in re.split(r"\n\s*\n", text) if p.strip()]


def unexplained_figures(text: str) -> list[tuple[str, str]]:
    """``(heading, figure)`` for every measured figure in a section that names no command
    (historical paragraphs left out)."""
    found = []
    for heading, prose, code in sections(text):
        has_command = any(COMMAND_INLINE.search(l) for l in prose + code) or any(COMMAND_LINE.search(l) for l in code)
        if has_command:
            continue
        for para in _paragraphs(prose) + _paragraphs(code):
            if HISTORICAL.search(para):
                continue
            for m in FIGURE.finditer(para):
                found.append((heading, m.group(0)))
    return found


def test_the_rule_finds_figures_and_commands():
    """The rule itself: a time, a ratio and a percentage are figures; a size, a version and a
    percentage target are not; a command in backticks or a code block explains its section;
    a historical paragraph names its commit."""
    for figure in ("took 0.66 s", "in 30 ms", "1.8× over", "1.90x", "16% less variance", "77 s⁻¹", "0.2 µs"):
        assert FIGURE.search(figure), figure
    for plain in ("64 × 32 pixels", "a 0.6 × 0.6 m panel", "Mitsuba 3.9", "±1%", "DA300 96.7%",
                  "cd/m²", "x0, y0", "1.5x1.5", "10 klx", "0.53°", "5 mm", "2**31", "0.2% less area"):  # fmt: skip
        assert not FIGURE.search(plain), plain
    timed = "## A\nIt takes 3 s.\n"
    assert unexplained_figures(timed) == [("## A", "3 s")]
    assert unexplained_figures(timed + "Measured by `probesim bench configs/x.toml`.\n") == []
    assert unexplained_figures(timed + "```bash\nPYTHONPATH=. python benchmarks/small_runs.py\n```\n") == []
    assert unexplained_figures("## A\nHistorical (tree 1234abc): 3 s.\n") == []
    assert unexplained_figures("## A\nHistorical: 3 s.\n") == [("## A", "3 s")]
    # a command in another section does not explain this one
    assert unexplained_figures("## A\n`probesim run x.toml`\n## B\nIt takes 3 s.\n") == [("## B", "3 s")]


def test_every_figure_in_the_docs_names_the_command_that_measured_it():
    """README.md and docs/*.md: every section holding a measured figure names its command (see the module)."""
    bad = []
    for page in pages():
        for heading, figure in unexplained_figures(page.read_text(encoding="utf-8")):
            bad.append(f"{page.relative_to(ROOT)}: {heading}: {figure}")
    assert not bad, "figures with no command beside them:\n" + "\n".join(bad)


def test_every_historical_figure_names_a_tree_of_this_project():
    """The commit a historical paragraph names is one of this repository's (checked where the
    checkout has its git history; skipped in an installed copy or a tarball)."""
    import shutil
    import subprocess

    import pytest

    if shutil.which("git") is None or not (ROOT / ".git").exists():
        pytest.skip("no git history here")
    named = set()
    for page in pages():
        text = page.read_text(encoding="utf-8")
        named.update(m.group(1) for m in re.finditer(r"historical[^\n]*?\btree\s+([0-9a-f]{7,40})\b", text, re.IGNORECASE))
    assert named, "no historical paragraph found (the pattern is stale)"
    for commit in sorted(named):
        found = subprocess.run(["git", "cat-file", "-e", f"{commit}^{{commit}}"], cwd=ROOT, capture_output=True)
        assert found.returncode == 0, f"{commit}: not a commit of this repository"
