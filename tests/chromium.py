"""Debian's Chromium, headless, for the tests that look at a page as a person would: a screenshot of a
file:// page and its DOM after the page's scripts ran. Chromium must be installed (``.ci/run`` installs it)."""

from __future__ import annotations

import shutil
import subprocess
import tempfile
from pathlib import Path

CHROMIUM = shutil.which("chromium") or "/usr/bin/chromium"
FLAGS = ("--headless", "--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run",
         "--disable-background-networking", "--disable-component-update", "--disable-sync", "--hide-scrollbars")
"""Without the networking flags Chromium keeps trying hosts this machine cannot reach."""


def _run(args: list[str], timeout: float = 120.0) -> subprocess.CompletedProcess:
    if not Path(CHROMIUM).exists():
        raise FileNotFoundError(f"{CHROMIUM} is missing: apt-get install chromium")
    with tempfile.TemporaryDirectory() as profile:
        return subprocess.run([CHROMIUM, *FLAGS, f"--user-data-dir={profile}", *args], capture_output=True,
                              text=True, timeout=timeout, check=True)


def screenshot(page: Path, png: Path, size: tuple[int, int] = (1200, 3000)) -> Path:
    """``page`` rendered to ``png`` at ``size`` (w, h) px."""
    _run([f"--window-size={size[0]},{size[1]}", f"--screenshot={png}", Path(page).resolve().as_uri()])
    return png


def dump_dom(page: Path) -> str:
    """The DOM of ``page`` once loaded and its load handlers have run."""
    return _run(["--virtual-time-budget=5000", "--dump-dom", Path(page).resolve().as_uri()]).stdout
