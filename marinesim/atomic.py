"""Atomic file output, the one way marinesim writes a file: to a temporary file beside the target,
then renamed over it.

An interrupted run never leaves a half-written file behind, an existing file is replaced only by
a complete one, and every output gets the same permissions (0666 less the umask, as ``open``
would give; ``mkstemp`` alone makes 0600). Only a regular file (or nothing) is ever replaced: a
device, a FIFO, a directory or a symbolic link at the target is refused before anything is written.
A failed write (a full disk, a read-only folder) is reported as a :class:`MarinesimError` naming the
target, never its temporary name.

Files that belong together (a table and the sidecar that describes it) are committed by
:func:`commit_together`: SIGINT and SIGTERM wait until the last is in place, and if a rename fails
the files renamed before it get their previous contents back, so the pair on disk is the old one
or the new one. :func:`output_lock` keeps a second writer off an output while the first runs.
"""

from __future__ import annotations

import contextlib
import json
import os
import signal
import stat
import tempfile
import threading
from pathlib import Path
from typing import Iterator, Sequence

from marinesim.errors import MarinesimError


class AtomicFile:
    """A file of ``path`` being written under the temporary name :attr:`temp` until :meth:`commit`;
    errors name :attr:`named`: ``named`` if given (the output a lock file is for), else ``path``."""

    def __init__(self, path: str | os.PathLike, named: str | os.PathLike | None = None) -> None:
        self.path = Path(path)
        self.named = self.path if named is None else Path(named)
        if not self.path.parent.is_dir():
            raise MarinesimError(f"cannot write {self.named}: folder {self.path.parent} does not exist")
        check_replaceable(self.path)
        try:
            fd, temp = tempfile.mkstemp(prefix=f".{self.path.stem}.", suffix=f".part{self.path.suffix}",
                                        dir=self.path.parent)
        except OSError as error:
            raise MarinesimError(f"cannot write {self.named}: {error.strerror or error}") from None
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


def check_replaceable(path: Path) -> None:
    """Refuse (:class:`MarinesimError`) a target that exists and is not a regular file."""
    try:
        mode = os.lstat(path).st_mode
    except FileNotFoundError:
        return
    if not stat.S_ISREG(mode):
        kind = ("a symbolic link" if stat.S_ISLNK(mode) else "a folder" if stat.S_ISDIR(mode)
                else "a FIFO" if stat.S_ISFIFO(mode) else "a device" if stat.S_ISCHR(mode) or stat.S_ISBLK(mode)
                else "not a regular file")
        raise MarinesimError(f"cannot write {path}: it is {kind}; give the path of a regular file")


@contextlib.contextmanager
def atomic_path(path: str | os.PathLike) -> Iterator[Path]:
    """Yield a temporary path to write; on success it is renamed to ``path``, else removed."""
    file = AtomicFile(path)
    with writing(file):
        yield file.temp
        file.commit()


@contextlib.contextmanager
def writing(*files: AtomicFile) -> Iterator[None]:
    """Discard the temporary ``files`` if the block fails. A file-system error about one of them (or
    about no file, as a full disk's) is raised as a :class:`MarinesimError` naming the user's file."""
    try:
        yield
    except OSError as error:
        for file in files:
            file.discard()
        named = next((file.named for file in files if error.filename in (str(file.temp), file.temp)), None)
        if named is None and error.filename is not None:
            raise  # about another file: the message already names it
        text = str(error)
        for file in files:
            text = text.replace(str(file.temp), str(file.named))
        reason = error.strerror or text.partition("\n")[0] or type(error).__name__
        raise MarinesimError(f"cannot write {named or files[0].named}: {reason}") from None
    except BaseException:
        for file in files:
            file.discard()
        raise


def json_text(data: dict) -> str:
    """``data`` as the indented JSON every sidecar is written in (one trailing newline)."""
    return json.dumps(data, indent=2) + "\n"


def commit_together(files: Sequence[AtomicFile]) -> None:
    """Rename every file into place in order, as one unit (see the module's docstring)."""
    backups: list[tuple[AtomicFile, Path | None]] = []
    with signals_held():
        try:
            for file in files:
                backups.append((file, _backup(file.path)))
                file.commit()
        except BaseException:
            for file, backup in reversed(backups[:-1]):
                if backup is not None:
                    os.replace(backup, file.path)
                else:
                    with contextlib.suppress(FileNotFoundError):
                        os.unlink(file.path)
            raise
        finally:
            for _, backup in backups:
                if backup is not None:
                    with contextlib.suppress(FileNotFoundError):
                        os.unlink(backup)


def _backup(path: Path) -> Path | None:
    """A hard link to the file at ``path`` under a temporary name (None if there is none)."""
    if not path.exists():
        return None
    backup = path.with_name(f".{path.name}.{os.getpid()}.previous")
    with contextlib.suppress(FileNotFoundError):
        os.unlink(backup)
    os.link(path, backup)
    return backup


@contextlib.contextmanager
def signals_held() -> Iterator[None]:
    """SIGINT and SIGTERM are noted, not acted on, inside the block and delivered once it ends (main thread;
    elsewhere a no-op). Python handlers are swapped rather than the signal mask set: a process-directed signal
    reaches any thread that does not block it (an FFT or a thread pool's worker) and Python then runs the
    handler on the main thread whatever that thread's mask says."""
    if threading.current_thread() is not threading.main_thread():
        yield
        return
    noted: list[int] = []
    previous = {number: signal.signal(number, lambda number, frame: noted.append(number))
                for number in (signal.SIGINT, signal.SIGTERM)}
    try:
        yield
    finally:
        for number, handler in previous.items():
            signal.signal(number, handler)
        if noted:
            signal.raise_signal(noted[0])


@contextlib.contextmanager
def output_lock(path: Path) -> Iterator[None]:
    """Hold ``<path>.lock`` (it names this process) while ``path`` is written; a second writer is refused
    while the first runs, and a lock left by a process that no longer runs is taken over."""
    lock = path.with_name(path.name + ".lock")
    mine = AtomicFile(lock, named=path)
    with writing(mine):
        mine.temp.write_text(f"{os.getpid()}\n")
    try:
        for _ in range(2):
            try:
                os.link(mine.temp, lock)  # fails if the lock exists: creating it with its content is atomic
                break
            except FileExistsError:
                owner = _lock_owner(lock)
                if owner is not None:
                    raise MarinesimError(f"cannot write {path}: another marinesim (process {owner}) is writing "
                                         f"it; wait for it to finish (or remove {lock} if it no longer runs)") from None
                with contextlib.suppress(FileNotFoundError):
                    os.unlink(lock)
        else:
            raise MarinesimError(f"cannot write {path}: the lock {lock} keeps coming back")
    finally:
        mine.discard()
    try:
        yield
    finally:
        with contextlib.suppress(FileNotFoundError):
            os.unlink(lock)


def _lock_owner(lock: Path) -> int | None:
    """The process that holds ``lock`` if it still runs, else None (a lock names its process from the start)."""
    try:
        pid = int(lock.read_text().strip())
    except (OSError, ValueError):
        return None
    if pid <= 0:
        return None
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return None
    except PermissionError:
        return pid
    return pid
