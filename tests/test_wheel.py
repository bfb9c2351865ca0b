"""A plain ``pip install`` works: the wheel carries every package and every resource, and installed
outside the checkout it runs the default scenario headless and renders a screenshot.

A wheel without ``shaders/`` or ``configs/`` (as one built from a checkout once was) would break
every GL path and ``marinesim run`` for anyone who installs marinesim rather than clones it.
"""

from __future__ import annotations

import os
import subprocess
import sys
import sysconfig
import zipfile
from pathlib import Path

import pytest

from conftest import ROOT

pytestmark = pytest.mark.slow

RESOURCES = ("shaders", "configs", "hulls", "rao")


@pytest.fixture(scope="module")
def wheel(tmp_path_factory) -> Path:
    """The wheel ``pip wheel`` builds from the checkout (no dependencies)."""
    out = tmp_path_factory.mktemp("wheel")
    subprocess.run([sys.executable, "-m", "pip", "wheel", "--quiet", "--no-deps", "--wheel-dir", str(out), str(ROOT)],
                   check=True, cwd=out, timeout=600)
    (path,) = out.glob("marinesim-*.whl")
    return path


@pytest.fixture(scope="module")
def installed(wheel, tmp_path_factory) -> Path:
    """A fresh virtual environment outside the checkout with the wheel installed; its dependencies are the
    test environment's, seen through a path file (whose .pth files are not run, so its editable marinesim
    is not imported; pip ignores it rather than uninstall it)."""
    venv = tmp_path_factory.mktemp("venv")
    subprocess.run([sys.executable, "-m", "venv", "--without-pip", str(venv)], check=True, timeout=300)
    python = venv / "bin" / "python"
    site = Path(subprocess.run([python, "-c", "import sysconfig; print(sysconfig.get_paths()['purelib'])"],
                               check=True, capture_output=True, text=True).stdout.strip())
    (site / "test-dependencies.pth").write_text(sysconfig.get_paths()["purelib"] + "\n")
    subprocess.run([sys.executable, "-m", "pip", "--python", str(python), "install", "--quiet", "--no-deps",
                    "--ignore-installed", str(wheel)], check=True, timeout=300)
    return venv


def _run(venv: Path, program: str, *args: str, cwd: Path) -> subprocess.CompletedProcess:
    """``program`` (python, or the installed marinesim command) of ``venv``, run in ``cwd`` without PYTHONPATH."""
    env = {key: value for key, value in os.environ.items() if key != "PYTHONPATH"}
    return subprocess.run([str(venv / "bin" / program), *args], cwd=cwd, env=env, capture_output=True, text=True,
                          timeout=900)


def test_the_wheel_holds_every_package_and_resource(wheel):
    """Every package of the source tree and every resource file is in the wheel, with the data licence; the scripts
    among the resources (hulls/make/visual_ships.py, which writes the visual meshes) are not: what they write is."""
    names = set(zipfile.ZipFile(wheel).namelist())
    for init in (ROOT / "marinesim").rglob("__init__.py"):
        assert init.relative_to(ROOT).as_posix() in names, f"package {init.parent.name} is missing from the wheel"
    for kind in RESOURCES:
        for path in (ROOT / kind).rglob("*"):
            if path.is_file() and "__pycache__" not in path.parts:
                shipped = f"marinesim/{path.relative_to(ROOT).as_posix()}" in names
                if path.suffix == ".py":
                    assert not shipped, f"{path} is a script that makes resources: it is not one of them"
                else:
                    assert shipped, f"{path} is missing from the wheel"
    assert "marinesim/rao/LICENSE-MSS" in names and "marinesim/hulls/LICENSE-MSS" in names


def test_installed_outside_the_checkout_it_runs_and_renders(installed, tmp_path):
    """Installed from the wheel, marinesim finds its own resources: ``run`` with no scenario opens the packaged
    default and writes its files headless; ``render --screenshot`` compiles the shaders and draws a frame."""
    where = _run(installed, "python", "-c", "import marinesim, marinesim.resources as r; "
                 "print(marinesim.__file__); print(r.default_scenario())", cwd=tmp_path)
    assert where.returncode == 0, where.stderr
    package, default = (Path(line) for line in where.stdout.split())
    assert installed in package.parents and installed in default.parents and default.is_file()
    assert ROOT not in package.parents

    run = _run(installed, "marinesim", "run", "--headless", "--quiet", "--duration", "2", "--out", "out",
               cwd=tmp_path)
    assert run.returncode == 0, run.stderr[-3000:]
    for name in ("sea.png", "motions.csv", "motions.csv.json", "rao.png"):
        assert (tmp_path / "out" / name).stat().st_size > 0, f"the headless run did not write {name}"
    assert str(default) in run.stdout

    shot = _run(installed, "marinesim", "render", str(default), "--screenshot", "shot.png", "--size", "160x90",
                cwd=tmp_path)
    assert shot.returncode == 0, shot.stderr[-3000:]
    import numpy as np
    from PIL import Image

    image = np.asarray(Image.open(tmp_path / "shot.png").convert("RGB"))
    assert image.shape == (90, 160, 3) and len(np.unique(image.reshape(-1, 3), axis=0)) > 50, "the screenshot is blank"


def test_a_wheel_user_names_the_shipped_examples_and_exports_motions_without_a_scenario(installed, tmp_path):
    """Installed from the wheel, outside the checkout: ``examples`` lists the shipped exercises, a shipped exercise
    is assessed by its name, ``examples copy`` gives a self-contained folder, and motions come from an RAO file and
    sea options alone. If this fails, a wheel user (who has no configs/ folder) cannot reach what the README shows."""
    listing = _run(installed, "marinesim", "examples", cwd=tmp_path)
    assert listing.returncode == 0, listing.stderr
    assert "crane_lift" in listing.stdout and "helideck_landing" in listing.stdout

    assess = _run(installed, "marinesim", "assess", "crane_lift", "--duration", "60", "--quiet", cwd=tmp_path)
    assert assess.returncode == 0, assess.stderr[-3000:]
    assert "crane tip vertical velocity" in assess.stdout and "verdict:" in assess.stdout
    assert str(ROOT) not in assess.stdout, "the installed marinesim read the checkout's scenario"

    copy = _run(installed, "marinesim", "examples", "copy", "crane_lift", "mine", cwd=tmp_path)
    assert copy.returncode == 0, copy.stderr
    rao = tmp_path / "mine" / "rao" / "supply" / "input.re1"
    assert rao.is_file() and (tmp_path / "mine" / "rao" / "LICENSE-MSS").is_file()

    export = _run(installed, "marinesim", "export", "--rao", str(rao), "--hs", "3", "--tp", "9", "--duration", "60",
                  "--out", "m.csv", "--quiet", cwd=tmp_path)
    assert export.returncode == 0, export.stderr[-3000:]
    import pandas as pd

    motions = pd.read_csv(tmp_path / "m.csv")
    assert len(motions) == 601 and motions["heave_m"].std() > 0.05, "3 m waves and no heave"
