"""Where marinesim keeps what it can compute again: ``$MARINESIM_CACHE_DIR``, else the user's cache folder as
:func:`platformdirs.user_cache_path` finds it (``$XDG_CACHE_HOME/marinesim`` where that is set, else
``~/.cache/marinesim`` on Linux, ``~/Library/Caches/marinesim`` on macOS, ``%LOCALAPPDATA%\\marinesim\\Cache`` on
Windows).

The cache is an optimisation: one that cannot be written (a read-only folder, a file where the
folder should be, a full disk) costs a warning, once per process, and the run goes on without it.
"""

from __future__ import annotations

import contextlib
import logging
import os
from pathlib import Path
from typing import Callable

import platformdirs

from marinesim.errors import MarinesimError

log = logging.getLogger("marinesim.cache")
_warned = False


def cache_root() -> Path:
    """The cache folder (see above); refused (:class:`MarinesimError`) where there is no home folder to put it in."""
    if os.environ.get("MARINESIM_CACHE_DIR"):
        return Path(os.environ["MARINESIM_CACHE_DIR"])
    with contextlib.suppress(RuntimeError):  # no HOME and no passwd entry (some containers)
        folder = platformdirs.user_cache_path("marinesim", appauthor=False)
        if folder.is_absolute():  # older platformdirs leave an unknown home as "~"
            return folder
    raise MarinesimError("no home folder to keep the cache in: set MARINESIM_CACHE_DIR")


def store(path: Path, save: Callable[[Path], None]) -> bool:
    """Write the cache file ``path`` with ``save(path)`` (an atomic writer, as all of marinesim's are); whether it
    was written. If it cannot be, the process's first such failure is logged as a one-line warning and nothing
    raised."""
    global _warned
    try:
        path.parent.mkdir(parents=True, exist_ok=True)
        save(path)
        return True
    except (OSError, MarinesimError) as error:
        if not _warned:
            _warned = True
            failure = f"cannot write {error.filename}: {error.strerror}" if isinstance(error, OSError) else error
            log.warning("marinesim: warning: %s; going on without the cache", failure)
        return False
