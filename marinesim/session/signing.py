"""This installation's key for signing session logs, and a log's signature.

The key is 32 random bytes kept as 64 hex digits in :data:`KEY_FILE` under :func:`config_root`, readable by
its owner only, made on first use and never replaced (the logs signed with it would become unverifiable). A
signature is an HMAC-SHA256 of a log's bytes under the key, with the key's public name: a log signed on
another installation is told apart from a forged one.
"""

from __future__ import annotations

import contextlib
import hashlib
import hmac
import os
import re
import secrets
from pathlib import Path

import platformdirs

from marinesim.errors import MarinesimError

KEY_FILE = "session-log.key"
"""This installation's key for signing session logs, in :func:`config_root`: 64 hex digits."""


def config_root() -> Path:
    """Where marinesim keeps what is this installation's own and cannot be made again (unlike the cache):
    ``$MARINESIM_CONFIG_DIR``, else the user's configuration folder as :func:`platformdirs.user_config_path` finds it
    (``$XDG_CONFIG_HOME/marinesim`` where that is set, else ``~/.config/marinesim`` on Linux,
    ``~/Library/Application Support/marinesim`` on macOS, ``%LOCALAPPDATA%\\marinesim`` on Windows)."""
    if os.environ.get("MARINESIM_CONFIG_DIR"):
        return Path(os.environ["MARINESIM_CONFIG_DIR"])
    with contextlib.suppress(RuntimeError):  # no HOME and no passwd entry (some containers)
        folder = platformdirs.user_config_path("marinesim", appauthor=False)
        if folder.is_absolute():  # older platformdirs leave an unknown home as "~"
            return folder
    raise MarinesimError("no home folder to keep the session-log key in: set MARINESIM_CONFIG_DIR")


def installation_key(create: bool = False) -> bytes | None:
    """This installation's key for signing session logs (32 bytes), from :data:`KEY_FILE` in :func:`config_root`;
    with ``create``, made there if there is none (else None). One that cannot be read or made is refused
    (:class:`MarinesimError`)."""
    path = config_root() / KEY_FILE
    try:
        if create and not os.path.lexists(path):
            _make_key(path)
        text = path.read_text(encoding="ascii")
    except (OSError, UnicodeDecodeError) as error:
        if isinstance(error, FileNotFoundError) and not create:
            return None
        raise MarinesimError(f"cannot read or make the session-log key {path}: "
                             f"{getattr(error, 'strerror', None) or error}") from None
    if not re.fullmatch(r"[0-9a-f]{64}\n?", text):
        raise MarinesimError(f"{path} is not a session-log key (64 hex digits); move it away for a new one to be "
                             "made (the logs signed with it can then no longer be checked)")
    return bytes.fromhex(text.strip())


def _make_key(path: Path) -> None:
    """A new key at ``path``, mode 0600, in place at once or not at all; a key another process put there first is
    kept (replacing it would leave the logs signed with it unverifiable)."""
    path.parent.mkdir(parents=True, exist_ok=True, mode=0o700)
    temp = path.with_name(f".{path.name}.{secrets.token_hex(4)}")
    handle = os.fdopen(os.open(temp, os.O_WRONLY | os.O_CREAT | os.O_EXCL, 0o600), "w", encoding="ascii")
    try:
        with handle:
            handle.write(secrets.token_hex(32) + "\n")
            handle.flush()
            os.fsync(handle.fileno())
        with contextlib.suppress(FileExistsError):
            os.link(temp, path)
    finally:
        with contextlib.suppress(FileNotFoundError):
            os.unlink(temp)


def key_id(key: bytes) -> str:
    """A key's public name: the first 16 hex digits of a sha256 of it (the key cannot be had from it)."""
    return hashlib.sha256(b"marinesim session-log key\0" + key).hexdigest()[:16]


def signature(key: bytes, data: bytes) -> dict[str, str]:
    """The sidecar's signature of a log of bytes ``data``: its HMAC-SHA256 under ``key``, and the key's name."""
    return {"key_id": key_id(key), "hmac_sha256": hmac.new(key, data, hashlib.sha256).hexdigest()}
