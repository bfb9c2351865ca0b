"""Staging of unwritable folders for real, shared by the tests of caches and outputs that cannot be written."""

from __future__ import annotations

import contextlib
import subprocess
import tempfile
from pathlib import Path
from typing import Iterator

import pytest


@contextlib.contextmanager
def tmpfs(options: str) -> Iterator[Path]:
    """A folder with a 64 KiB tmpfs mounted on it (``options`` added, e.g. ``ro``), unmounted afterwards; the
    test is skipped, with the reason, where no tmpfs can be mounted (not root)."""
    folder = Path(tempfile.mkdtemp(prefix="marinesim-tmpfs-"))
    mounted = subprocess.run(["mount", "-t", "tmpfs", "-o", f"size=64k,{options}", "tmpfs", str(folder)],
                             capture_output=True, text=True)
    if mounted.returncode != 0:
        folder.rmdir()
        pytest.skip(f"cannot mount a tmpfs to stage an unwritable folder ({mounted.stderr.strip() or 'mount failed'})")
    try:
        yield folder
    finally:
        subprocess.run(["umount", "-l", str(folder)], check=False)
        folder.rmdir()
