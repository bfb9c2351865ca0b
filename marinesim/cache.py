"""Where marinesim keeps what it can compute again: ``$MARINESIM_CACHE_DIR``, else
``$XDG_CACHE_HOME/marinesim``, else ``~/.cache/marinesim``.

The cache is an optimisation: one that cannot be written (a read-only folder, a file where the
folder should be, a full disk) costs a warning, once per process, and the run goes on without it.
"""

from __future__ import annotations

import logging
import os
from pathlib import Path
from typing import Callable

from marinesim.errors import MarinesimError

log = logging.getLogger("marinesim.cache")
_warned = False


def cache_root() -> Path:
    if os.environ.get("MARINESIM_CACHE_DIR"):
        return Path(os.environ["MARINESIM_CACHE_DIR"])
    return Path(os.environ.get("XDG_CACHE_HOME") or Path.home() / ".cache") / "marinesim"


def store(path: Path, save: Callable[[Path], None]) -> None:
    """Write the cache file ``path`` with ``save(path)`` (an atomic writer, as all of marinesim's are); if it
    cannot be written, the process's first such failure is logged as a one-line warning and nothing raised."""
    global _warned
    try:
        path.parent.mkdir(parents=True, exist_ok=True)
        save(path)
    except (OSError, MarinesimError) as error:
        if not _warned:
            _warned = True
            failure = f"cannot write {error.filename}: {error.strerror}" if isinstance(error, OSError) else error
            log.warning("marinesim: warning: %s; going on without the cache", failure)
