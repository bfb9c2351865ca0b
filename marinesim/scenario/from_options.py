"""A scenario from command-line options: the TOML text of sections of scenario keys, and the scenario that text
describes, built as :func:`~marinesim.scenario.load_scenario` builds a file's.

``marinesim export`` and ``run`` describe a vessel and her sea with ``--rao`` and the sea options: they make the
text once, run the scenario it gives and save that very text, so that the saved file and the run never disagree.
"""

from __future__ import annotations

import os
import tomllib
from pathlib import Path

import tomlkit

from marinesim.errors import ScenarioError
from marinesim.scenario.model import WAVE_PARAMETERS, ScenarioFile, validate
from marinesim.scenario.schema import Scenario, build_scenario

Value = str | bool | int | float | Path
"""A key's value; a :class:`~pathlib.Path` is a file the scenario reads (floats by their shortest repr: ``inf`` and
``nan`` too, which the model refuses as it refuses a file's)."""
Table = dict[str, Value | None]
"""A section's keys (None: the key is left out)."""

KEYS = {parameter: key for key, parameter in WAVE_PARAMETERS.items()}
"""A :func:`~marinesim.sea.build.wave_system` parameter -> the ``[[sea]]`` key that gives it."""
HEADER = "A marinesim scenario written from command-line options; relative paths start at this file's folder."


def sea_table(kind: str, from_deg: float, **parameters: float | str) -> Table:
    """The ``[[sea]]`` table of a wave system given as :func:`~marinesim.sea.build.wave_system`'s arguments (a
    ``kind`` of wave system, the compass direction ``from_deg`` (deg) it comes from, its parameters in their units)."""
    return {"type": kind, "from_deg": from_deg} | {KEYS[name]: value for name, value in parameters.items()}


def scenario_text(sections: dict[str, Table | list[Table]], folder: Path) -> str:
    """The scenario file of ``sections`` (a section's name -> its keys, or a list of tables such as ``[[sea]]``),
    in their order; a section with no keys is left out. A path is written relative to ``folder`` (where the file
    goes), absolute where no relative path leads to it (another drive). Written by tomlkit, which quotes and
    escapes what a file name may hold."""
    document = tomlkit.document()
    document.add(tomlkit.comment(HEADER))
    for name, section in sections.items():
        if isinstance(section, list):
            tables = tomlkit.aot()
            for table in section:
                tables.append(tomlkit.item(_keys(table, folder)))
            document.add(name, tables)
        elif keys := _keys(section, folder):
            document.add(name, tomlkit.item(keys))
    return tomlkit.dumps(document)


def _keys(table: Table, folder: Path) -> dict[str, str | bool | int | float]:
    """The keys of ``table`` that are given, a path as a name relative to ``folder``."""
    return {key: _relative(value, folder) if isinstance(value, Path) else value
            for key, value in table.items() if value is not None}


def load_text(text: str, path: Path) -> Scenario:
    """The scenario of the TOML ``text`` as :func:`~marinesim.scenario.load_scenario` would load it from ``path``
    (where the text is to be saved: its relative paths are read from the folder of ``path``, which must exist).
    A :class:`ScenarioError` names the key, as for a file."""
    try:
        return build_scenario(path, validate(ScenarioFile, tomllib.loads(text)))
    except ScenarioError as error:
        raise ScenarioError(f"the scenario of the options: {error}") from None


def _relative(path: Path, folder: Path) -> str:
    """``path`` relative to ``folder`` (both with their links resolved), else absolute; with ``/`` separators."""
    target = path.resolve()
    try:
        name = Path(os.path.relpath(target, folder.resolve())).as_posix()
    except ValueError:  # on another drive
        name = target.as_posix()
    try:
        name.encode("utf-8")
    except UnicodeEncodeError:
        raise ScenarioError(f"{path}: a file name that is not UTF-8 cannot be written in a scenario file") from None
    return name
