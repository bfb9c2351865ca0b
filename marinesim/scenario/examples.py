"""The shipped scenarios (``configs/*.toml``) and exercises (``configs/training/*.toml``): named by their file's
stem wherever a command takes a scenario, listed with a line of description, and copied out with every file they
refer to (RAO tables, hulls, visual meshes, station, mooring and wind files) so that a user can edit them.

In a checkout the shipped files are the top-level ``configs``, ``rao`` and ``hulls``; a wheel carries them inside
the package (:mod:`marinesim.resources`). A copy keeps their layout below a folder of the user's (``DEST/configs``,
``DEST/rao``, ``DEST/hulls``), so the scenarios' relative paths (``../rao/...``) hold in the copy too.
"""

from __future__ import annotations

import filecmp
import glob
import re
import shutil
import tomllib
from collections.abc import Iterator, Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from marinesim.atomic import atomic_path
from marinesim.errors import MarinesimError, ScenarioError
from marinesim.resources import resource_dir

FOLDERS = ("", "training")
"""The folders of ``configs`` that hold scenarios; the others (vessels/, station/, ...) hold their side files."""
COPIED = ("configs", "rao", "hulls")
"""The resource folders a scenario's files lie in; a copy keeps each as a folder of the destination."""
NAMED = {"vessel.manoeuvring": "vessels", "station.vessel": "station", "station.moorings": "moorings"}
"""The scenario keys that name a shipped side file by its stem (``configs/<folder>/<name>.toml``)."""
NOTICES = ("LICENSE*", "README*", "NOTICE*", "COPYING*")
"""The licence and provenance notices that travel with the data in their folder and the folders below it."""
DESCRIPTION_WIDTH = 88
"""The longest description a listing gives, characters."""


@dataclass(frozen=True)
class Example:
    """A shipped scenario: its name (the file's stem), file, one-line description and whether it is an exercise (in
    ``training/`` or with ``[[criteria]]``: ``marinesim assess`` scores it)."""

    name: str
    path: Path
    description: str
    exercise: bool

    @property
    def kind(self) -> str:
        """``exercise`` or ``scenario``."""
        return "exercise" if self.exercise else "scenario"

    @property
    def relative(self) -> Path:
        """The file below ``configs`` (``default.toml``, ``training/crane_lift.toml``)."""
        return self.path.relative_to(resource_dir("configs"))


def shipped() -> tuple[Example, ...]:
    """Every shipped scenario, those of ``configs`` first, each folder's by name."""
    root = resource_dir("configs")
    return tuple(_example(path, folder == "training") for folder in FOLDERS
                 for path in sorted((root / folder).glob("*.toml")))


def names() -> str:
    """The shipped scenarios' names, comma-separated, for a message."""
    return ", ".join(example.name for example in shipped())


def find(name: str | Path) -> Example | None:
    """The shipped scenario ``name`` names (``crane_lift``, ``crane_lift.toml``, ``training/crane_lift.toml``,
    ``configs/training/crane_lift.toml``), or None."""
    wanted = Path(name).as_posix().removeprefix("configs/").removesuffix(".toml")
    return next((example for example in shipped()
                 if wanted in (example.name, example.relative.with_suffix("").as_posix())), None)


def resolve(given: str | Path) -> Path:
    """The scenario file a user's argument names: an existing path as given, else a shipped scenario by name;
    :class:`ScenarioError` if it is neither."""
    path = Path(given)
    try:
        path.stat()
        return path
    except FileNotFoundError:
        example = find(given)
    except (OSError, ValueError):
        return path  # there but unreadable, or a NUL byte in the name: the reader words it (formats.check_file)
    if example is None:
        raise ScenarioError(f"{path}: no such scenario file; shipped scenarios: {names()} (see `marinesim examples`)")
    return example.path


def needed_files(scenario: Path) -> list[Path]:
    """The files a shipped ``scenario`` reads, itself first: every file its strings name (relative to it, or a
    shipped side file by name), recursively through the side TOML files, with the files beside each data file
    that share its stem (a WAMIT run's ``.1``, ``.frc``, ``.pot`` ... beside its ``.4``)."""
    found: dict[Path, None] = {}
    pending = [scenario.resolve()]
    while pending:
        file = pending.pop(0)
        if file in found:
            continue
        found[file] = None
        if file.suffix == ".toml":
            data = tomllib.loads(file.read_text(encoding="utf-8-sig"))
            pending += [named for key, value in _strings(data) if (named := _named(file, key, value)) is not None]
        else:
            pending += sorted(file.parent.glob(f"{glob.escape(file.stem)}.*"))
    return list(found)


@dataclass(frozen=True)
class Copied:
    """What :func:`copy_examples` did: the scenarios copied, the files written and those already there unchanged
    (paths in the destination)."""

    examples: tuple[Example, ...]
    written: tuple[Path, ...]
    unchanged: tuple[Path, ...]


def copy_examples(wanted: Sequence[str] | str, dest: str | Path) -> Copied:
    """Copy the shipped scenarios ``wanted`` (names, or ``"all"``) into ``dest`` with every file they read and the
    licence notices beside that data, keeping the shipped layout. A file already there with the same bytes is kept;
    one with other bytes is refused (:class:`MarinesimError`, naming it) before anything is written. Each file is
    written atomically."""
    examples = _chosen([wanted] if isinstance(wanted, str) else list(wanted))
    dest = Path(dest)
    if dest.exists() and not dest.is_dir():
        raise MarinesimError(f"cannot copy into {dest}: it is a file, not a folder")
    plan = {target: source for example in examples for source, target in _targets(example, dest)}
    for target, source in plan.items():
        if target.exists() and not (target.is_file() and filecmp.cmp(source, target, shallow=False)):
            raise MarinesimError(f"cannot copy {source.name} to {target}: a different file is there; move it away "
                                 "or copy into another folder")
    written, unchanged = [], []
    for target, source in plan.items():
        if target.exists():
            unchanged.append(target)
            continue
        target.parent.mkdir(parents=True, exist_ok=True)
        with atomic_path(target) as temp:
            shutil.copyfile(source, temp)
        written.append(target)
    return Copied(examples, tuple(written), tuple(unchanged))


def _chosen(wanted: list[str]) -> tuple[Example, ...]:
    """The shipped scenarios ``wanted`` names (``all``: every one), in the listing's order."""
    if "all" in wanted:
        return shipped()
    chosen = []
    for name in wanted:
        example = find(name)
        if example is None:
            raise ScenarioError(f"no shipped scenario {name!r}; shipped scenarios: {names()} (or all)")
        chosen.append(example)
    return tuple(dict.fromkeys(chosen))


def _targets(example: Example, dest: Path) -> Iterator[tuple[Path, Path]]:
    """(shipped file, its place in ``dest``) for every file ``example`` needs and the notices beside them."""
    roots = {kind: resource_dir(kind).resolve() for kind in COPIED}
    for file in needed_files(example.path):
        kind, root = next((kind, root) for kind, root in roots.items() if file.is_relative_to(root))
        yield file, dest / kind / file.relative_to(root)
        folder = file.parent
        while folder.is_relative_to(root):
            for pattern in NOTICES:
                for notice in sorted(folder.glob(pattern)):
                    yield notice, dest / kind / notice.relative_to(root)
            folder = folder.parent


def _example(path: Path, training: bool) -> Example:
    """The shipped scenario ``path`` (in ``training/`` if ``training``)."""
    text = path.read_text(encoding="utf-8-sig")
    return Example(path.stem, path, _description(text), training or "criteria" in tomllib.loads(text))


def _description(text: str) -> str:
    """The first sentence of the file's opening comment, without an ``Exercise:`` label and its asides in brackets,
    cut at a clause (or a word) to at most :data:`DESCRIPTION_WIDTH` characters."""
    comment = []
    for line in text.splitlines():
        if not line.startswith("#"):
            break
        comment.append(line.lstrip("#").strip())
    sentence = re.sub(r"^(Training exercise|Exercise):\s*", "", " ".join(comment))
    sentence = re.split(r"(?<=\.)\s", re.sub(r"\s*\([^()]*\)", "", sentence))[0].rstrip(".:;, ")
    if len(sentence) > DESCRIPTION_WIDTH:
        clauses = [m.start() for m in re.finditer(r"[:;,]\s", sentence[:DESCRIPTION_WIDTH + 1]) if m.start() >= 40]
        sentence = (sentence[:clauses[-1]] if clauses
                    else sentence[:DESCRIPTION_WIDTH - 3].rsplit(" ", 1)[0] + "...")
    return sentence[:1].upper() + sentence[1:]


def _strings(data: Any, key: str = "") -> Iterator[tuple[str, str]]:
    """(dotted key, value) for every string in the TOML ``data`` (``[[...]]`` items keep their table's key)."""
    if isinstance(data, str):
        yield key, data
    elif isinstance(data, dict):
        for name, value in data.items():
            yield from _strings(value, f"{key}.{name}" if key else name)
    elif isinstance(data, list):
        for value in data:
            yield from _strings(value, key)


def _named(file: Path, key: str, value: str) -> Path | None:
    """The existing file the string ``value`` at ``key`` of ``file`` names: a shipped side file by its stem (the
    keys of :data:`NAMED`), else a path relative to ``file``; None if it names no file."""
    candidates = [file.parent / value]
    if key in NAMED:
        candidates.insert(0, resource_dir("configs") / NAMED[key] / f"{value}.toml")
    for candidate in candidates:
        try:
            if candidate.is_file():
                return candidate.resolve()
        except OSError:  # a message or a briefing, too long for a file name
            continue
    return None
