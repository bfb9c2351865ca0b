"""Chromium, headless, for the tests that look at a page as a person would: a screenshot of a file:// page and its
DOM once the page's scripts ran. Found as ``$CHROMIUM``, else by its usual names on the PATH (Debian's ``chromium``,
Ubuntu's ``chromium-browser``, Google's ``google-chrome``); the README's test command installs Debian's where none is
found, as ``.ci/run`` does. A test that needs it fails, never skips, where it is missing."""

from __future__ import annotations

import os
import shutil
import subprocess
import tempfile
from pathlib import Path

NAMES = ("chromium", "chromium-browser", "google-chrome", "google-chrome-stable")
CHROMIUM = os.environ.get("CHROMIUM") or next(filter(None, map(shutil.which, NAMES)), "/usr/bin/chromium")
FLAGS = ("--headless", "--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run",
         "--disable-background-networking", "--disable-component-update", "--disable-sync",
         "--disable-default-apps", "--disable-extensions", "--mute-audio", "--hide-scrollbars",
         "--force-device-scale-factor=1")
"""Without the networking flags Chromium keeps trying hosts this machine cannot reach; scale 1: a
screenshot's pixels are CSS pixels."""
TIMEOUT_S = 900.0
"""s: a Chromium run that has not ended by then hangs (a page is drawn in seconds, under load in well under a minute)."""


def _run(args: list[str], timeout: float = TIMEOUT_S) -> subprocess.CompletedProcess:
    """Chromium with :data:`FLAGS` and a fresh profile of its own, then ``args``; raises if it fails."""
    if not Path(CHROMIUM).exists():
        raise FileNotFoundError(f"no Chromium: none of {', '.join(NAMES)} is on the PATH and $CHROMIUM is not set "
                                f"(apt-get install chromium)")
    with tempfile.TemporaryDirectory(prefix="chromium-profile-") as profile:
        return subprocess.run([CHROMIUM, *FLAGS, f"--user-data-dir={profile}", *args], capture_output=True,
                              text=True, timeout=timeout, check=True, stdin=subprocess.DEVNULL)


def screenshot(html_path: Path, png_path: Path, size: tuple[int, int] = (1200, 3000)) -> Path:
    """``html_path`` drawn to ``png_path`` in a window of ``size`` (width, height) px; returns ``png_path``."""
    png_path = Path(png_path).resolve()
    _run([f"--window-size={size[0]},{size[1]}", f"--screenshot={png_path}", "--virtual-time-budget=5000",
          Path(html_path).resolve().as_uri()])
    if not png_path.is_file():
        raise RuntimeError(f"chromium wrote no screenshot of {html_path}")
    return png_path


def dump_dom(html_path: Path) -> str:
    """The DOM of ``html_path`` once loaded and its load handlers have run, serialised as HTML."""
    return _run(["--virtual-time-budget=5000", "--dump-dom", Path(html_path).resolve().as_uri()]).stdout
