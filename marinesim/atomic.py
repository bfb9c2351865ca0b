"""Atomic file output, the one way marinesim writes a file: to a temporary file beside the target,
then renamed over it.

An interrupted run never leaves a half-written file behind, an existing file is replaced only by
a complete one, and every output gets the permissions ``open`` would give (0666 less the umask,
the temporary file being created with them). Only a regular file (or nothing) is ever replaced: a
device, a FIFO, a directory or a symbolic link at the target is refused before anything is written.
A failed write (a full disk, a read-only folder) is reported as a :class:`MarinesimError` naming the
target, never its temporary name.

Inside :func:`inputs_kept` (a command's run) no output is written over a file the command reads: every
reader passes :func:`~marinesim.formats.check_file`, which notes the file (and its sidecar) here, and the
same file under any name, symbolic or hard link, is refused as an output.

Files that belong together (a table and the sidecar that describes it) are committed by
:func:`commit_together`: SIGINT and SIGTERM wait until the last is in place, and if a rename fails
the files renamed before it get their previous contents back, so the pair on disk is the old one
or the new one. :func:`output_lock` keeps a second writer off an output while the first runs, and
clears what a writer that was killed left behind.
"""

from __future__ import annotations

import contextlib
import json
import math
import os
import re
import secrets
import signal
import stat
import threading
from pathlib import Path
from typing import Any, Iterator, Sequence

import filelock

from marinesim.errors import MarinesimError, ParameterError

PART = ".part"
"""What a temporary file's name carries before the target's suffix: ``.<stem>.<8 hex>.part<suffix>``."""


class AtomicFile:
    """A file of ``path`` being written under the temporary name :attr:`temp` until :meth:`commit`;
    errors name :attr:`named`: ``named`` if given, else ``path``."""

    def __init__(self, path: str | os.PathLike, named: str | os.PathLike | None = None) -> None:
        self.path = Path(path)
        self.named = self.path if named is None else Path(named)
        if not self.path.parent.is_dir():
            raise MarinesimError(f"cannot write {self.named}: folder {self.path.parent} does not exist")
        check_replaceable(self.path)
        refuse_input(self.path, f"cannot write {self.named}")
        self.temp = temporary(self.path, named=self.named)

    def commit(self) -> Path:
        """Rename the temporary file to :attr:`path`."""
        os.replace(self.temp, self.path)
        return self.path

    def discard(self) -> None:
        """Delete the temporary file, keeping whatever :attr:`path` held before."""
        with contextlib.suppress(FileNotFoundError):
            os.unlink(self.temp)


def temporary(path: Path, part: str = PART, named: Path | None = None) -> Path:
    """A new empty temporary file beside ``path``, ``.<stem>.<8 hex><part><suffix>``, created with mode 0666 (the
    umask applies, as ``open``'s); errors name ``named`` (default ``path``)."""
    named = path if named is None else named
    for _ in range(100):
        temp = path.with_name(f".{path.stem}.{secrets.token_hex(4)}{part}{path.suffix}")
        try:
            os.close(os.open(temp, os.O_WRONLY | os.O_CREAT | os.O_EXCL, 0o666))
            return temp
        except FileExistsError:
            continue
        except OSError as error:
            raise MarinesimError(f"cannot write {named}: {error.strerror or error}") from None
    raise MarinesimError(f"cannot write {named}: no free temporary name beside it")


def _temporaries(path: Path) -> re.Pattern:
    """The names :func:`temporary` gives the temporary files of ``path``."""
    return re.compile(rf"\.{re.escape(path.stem)}\.[0-9a-f]{{8}}{re.escape(PART + path.suffix)}")


def sidecar_path(path: Path) -> Path:
    """Where the sidecar of the table (or log) ``path`` goes: its full name plus ``.json``."""
    return path.with_name(path.name + ".json")


_inputs: dict[tuple[int, int], Path] | None = None
"""The files the running command reads, by (device, inode): None outside :func:`inputs_kept`."""
_inputs_lock = threading.Lock()


@contextlib.contextmanager
def inputs_kept() -> Iterator[None]:
    """Inside the block, the files :func:`note_input` is told of are refused as outputs."""
    global _inputs
    _inputs = {}
    try:
        yield
    finally:
        _inputs = None


def note_input(path: Path) -> None:
    """Note ``path`` (and its sidecar, if there is one) as read by the running command; outside
    :func:`inputs_kept`, nothing."""
    inputs = _inputs  # one read: the block may end in another thread meanwhile
    if inputs is None:
        return
    for file in (Path(path), sidecar_path(Path(path))):
        try:
            found = os.stat(file)
        except (OSError, ValueError):
            continue
        with _inputs_lock:
            inputs.setdefault((found.st_dev, found.st_ino), file)


def refuse_input(path: Path, doing: str) -> None:
    """Refuse (:class:`ParameterError`, after ``doing``) an output ``path`` that is, by any name or link, a
    file the running command reads: writing it would lose that input."""
    inputs = _inputs
    if inputs is None:
        return
    try:
        found = os.stat(path)
    except (OSError, ValueError):
        return
    with _inputs_lock:
        given = inputs.get((found.st_dev, found.st_ino))
    if given is not None:
        same = "" if given.resolve() == Path(path).resolve() else f" (the same file as {given})"
        raise ParameterError(f"{doing}: it is one of this command's inputs{same}; writing it would lose it, "
                             "choose another path")


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


def strict_json(value: Any, indent: int | None = None) -> str:
    """``value`` as strict JSON, what a browser or another program reads: a non-finite float (NaN, infinity)
    becomes null."""
    return json.dumps(_finite(value), indent=indent, allow_nan=False)


def _finite(value: Any) -> Any:
    if isinstance(value, float):
        return value if math.isfinite(value) else None
    if isinstance(value, dict):
        return {key: _finite(item) for key, item in value.items()}
    if isinstance(value, (list, tuple)):
        return [_finite(item) for item in value]
    return value


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
def output_lock(path: Path, covers: Sequence[Path] = ()) -> Iterator[None]:
    """Hold ``<path>.lock`` (an OS lock, given up when the process ends however it ends) while ``path`` and
    ``covers`` are written: a second writer is refused while the first runs. Once it is held, the temporary
    files a killed writer of these outputs left are removed."""
    lock = path.with_name(path.name + ".lock")
    held = filelock.FileLock(lock, timeout=0)
    try:
        held.acquire()
    except filelock.Timeout:
        owner = _lock_owner(lock)
        process = f" (process {owner})" if owner is not None else ""
        raise MarinesimError(f"cannot write {path}: another marinesim{process} is writing it; wait for it to "
                             "finish") from None
    except OSError as error:
        raise MarinesimError(f"cannot write {path}: {error.strerror or error}") from None
    try:
        with contextlib.suppress(OSError):  # only for a second writer's message: a full disk is told by the output
            lock.write_text(f"{os.getpid()}\n")
        _clear_leftovers([path, *covers])
        yield
    finally:
        with contextlib.suppress(FileNotFoundError):
            os.unlink(lock)  # while held: a writer waiting on this inode sees it unlinked and makes a new one
        held.release()


def _clear_leftovers(outputs: Sequence[Path]) -> None:
    """Remove the temporary files of ``outputs`` and of their sidecars (only the lock's holder writes these
    outputs: a temporary file there now was left by a writer that no longer runs)."""
    for output in outputs:
        for target in (output, sidecar_path(output)):
            names = _temporaries(target)
            for found in target.parent.iterdir():
                if names.fullmatch(found.name):
                    with contextlib.suppress(FileNotFoundError):
                        os.unlink(found)


def _lock_owner(lock: Path) -> int | None:
    """The process named in ``lock`` (None if it names none yet)."""
    try:
        return int(lock.read_text().strip())
    except (OSError, ValueError):
        return None
