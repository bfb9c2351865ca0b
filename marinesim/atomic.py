"""Atomic file output, the one way marinesim writes a file: to a temporary file beside the target,
then renamed over it.

An interrupted run never leaves a half-written file behind, an existing file is replaced only by
a complete one, and every output gets the same permissions (0666 less the umask, as ``open``
would give; ``mkstemp`` alone makes 0600).
"""

from __future__ import annotations

import contextlib
import json
import os
import tempfile
from pathlib import Path
from typing import Iterator

from marinesim.errors import MarinesimError


class AtomicFile:
    """A file of ``path`` being written under the temporary name :attr:`temp` until :meth:`commit`."""

    def __init__(self, path: str | os.PathLike) -> None:
        self.path = Path(path)
        if not self.path.parent.is_dir():
            raise MarinesimError(f"cannot write {self.path}: folder {self.path.parent} does not exist")
        fd, temp = tempfile.mkstemp(prefix=f".{self.path.stem}.", suffix=f".part{self.path.suffix}",
                                    dir=self.path.parent)
        os.close(fd)
        self.temp = Path(temp)

    def commit(self) -> Path:
        """Give the temporary file the usual permissions and rename it to :attr:`path`."""
        umask = os.umask(0)
        os.umask(umask)
        os.chmod(self.temp, 0o666 & ~umask)
        os.replace(self.temp, self.path)
        return self.path

    def discard(self) -> None:
        """Delete the temporary file, keeping whatever :attr:`path` held before."""
        with contextlib.suppress(FileNotFoundError):
            os.unlink(self.temp)


@contextlib.contextmanager
def atomic_path(path: str | os.PathLike) -> Iterator[Path]:
    """Yield a temporary path to write; on success it is renamed to ``path``, else removed."""
    file = AtomicFile(path)
    try:
        yield file.temp
        file.commit()
    except BaseException:
        file.discard()
        raise


def write_json(path: str | os.PathLike, data: dict) -> Path:
    """``data`` as indented JSON (UTF-8, one trailing newline) to ``path``, atomically."""
    with atomic_path(path) as temp:
        temp.write_text(json.dumps(data, indent=2) + "\n", encoding="utf-8")
    return Path(path)
