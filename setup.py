"""Build step that puts the bundled stages and configs inside the package.

``stages/`` and ``configs/`` stay at the top of the source tree, where the
configs' relative stage paths (``../stages/x.usda``) point. A wheel built
from it must carry them too, or an installed probesim could not run
``verify``, ``chart``, ``stability``, ``bench`` or ``example``. This
``build_py`` copies both folders, whole and side by side, to
``simulator/_data/`` in the build tree, so the same relative paths resolve
there (see ``simulator/bundled.py``).

Why a copy at build time rather than ``package-data`` with a
``package-dir`` mapping: a mapping would turn two data folders into
pseudo-packages (``simulator._data.stages`` ...), which package discovery,
editable installs and ``importlib`` each treat differently, and every new
sub-folder (``stages/textures/``) would need its own entry. The copy has one
rule, "everything under stages/ and configs/", and no side effects on the
import system. The build tree's copy is rebuilt from scratch each time, so a
file removed from the source never lingers in a wheel. Editable installs
skip it: they find the folders in the checkout. ``MANIFEST.in`` puts the
folders in the sdist, so a wheel built from the sdist is complete too.
"""

import shutil
from pathlib import Path

from setuptools import setup
from setuptools.command.build_py import build_py

#: source folders copied into the package, relative to this file
BUNDLED = ("stages", "configs")
#: where they go inside the package
TARGET = Path("simulator", "_data")


class build_py_with_bundled_data(build_py):
    """``build_py`` that also copies :data:`BUNDLED` into ``simulator/_data``."""

    def run(self):
        super().run()
        if getattr(self, "editable_mode", False):
            return
        here = Path(__file__).resolve().parent
        target = Path(self.build_lib) / TARGET
        if target.exists():
            shutil.rmtree(target)
        for name in BUNDLED:
            shutil.copytree(here / name, target / name,
                            ignore=shutil.ignore_patterns("__pycache__", ".*"))


setup(cmdclass={"build_py": build_py_with_bundled_data})
