"""Where marinesim keeps what it can compute again: ``$MARINESIM_CACHE_DIR``, else
``$XDG_CACHE_HOME/marinesim``, else ``~/.cache/marinesim``."""

from __future__ import annotations

import os
from pathlib import Path


def cache_root() -> Path:
    if os.environ.get("MARINESIM_CACHE_DIR"):
        return Path(os.environ["MARINESIM_CACHE_DIR"])
    return Path(os.environ.get("XDG_CACHE_HOME") or Path.home() / ".cache") / "marinesim"
