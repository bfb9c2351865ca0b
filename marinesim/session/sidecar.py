"""The JSON sidecar beside every table a run writes: what produced it, so that it can be produced again.

A table ``m.csv`` has its sidecar ``m.csv.json`` (so ``m.csv`` and ``m.parquet`` keep their own),
which names the table's sha256 (``data_sha256``): the two are written as one unit
(:func:`write_table`), and a reader can tell that a sidecar describes the bytes beside it. The
sidecar holds no clock time and no absolute path: the files it names (by their hashes too) are
given relative to its folder, so the same scenario, seed and inputs give the same bytes, and a
folder of inputs and outputs moved or copied elsewhere still reads.
"""

from __future__ import annotations

import contextlib
import hashlib
import os
import platform
from pathlib import Path
from typing import Any, Callable

import numpy as np

from marinesim import __version__
from marinesim.atomic import (AtomicFile, commit_together, json_text, output_lock, sidecar_path, signals_held,
                              writing)
from marinesim.sea.ocean import Components
from marinesim.sea.summary import summary
from marinesim.session.assembly import VARIANCE_FRACTION, Assembly


def sha256(path: Path) -> str:
    """The sha256 of a file's bytes (hex)."""
    digest = hashlib.sha256()
    with path.open("rb") as handle:
        for chunk in iter(lambda: handle.read(1 << 20), b""):
            digest.update(chunk)
    return digest.hexdigest()


UNITS = (("_deg_s2", "deg/s^2"), ("_m_s2", "m/s^2"), ("_deg_min", "deg/min"), ("_deg_s", "deg/s"), ("_m_s", "m/s"),
         ("_knm", "kN m"), ("_kn", "kN"), ("_rpm", "rpm"), ("_pct", "%"), ("_deg", "deg"), ("_m", "m"), ("_s", "s"))
"""A column's unit by the ending of its name (docs/CONVENTIONS.md, "Time series and files"), longer endings first;
``_kn`` is kN but in a speed's name (``speed_over_ground_kn``), where it is knots."""


def column_units(columns: list[str]) -> dict[str, str]:
    """Each column's unit (:data:`UNITS`); a column whose name ends in none of them is a ValueError (a column
    added without a unit in its name)."""
    units = {}
    for name in columns:
        unit = next((unit for ending, unit in UNITS if name.endswith(ending)), None)
        if unit is None:
            raise ValueError(f"column {name!r} has no unit in its name")
        units[name] = "kn" if unit == "kN" and "speed" in name else unit
    return units


def relative_path(path: Path, folder: Path) -> str:
    """``path`` relative to ``folder`` (POSIX separators, links resolved); its name alone where no relative path
    leads there (another drive)."""
    try:
        return Path(os.path.relpath(Path(path).resolve(), Path(folder).resolve())).as_posix()
    except ValueError:
        return Path(path).name


def _relative_paths(value: Any, folder: Path) -> Any:
    """``value`` with every :class:`Path` in it (in dicts and lists) written relative to ``folder``."""
    if isinstance(value, Path):
        return relative_path(value, folder)
    if isinstance(value, dict):
        return {key: _relative_paths(item, folder) for key, item in value.items()}
    if isinstance(value, list):
        return [_relative_paths(item, folder) for item in value]
    return value


def write_table(path: Path, write: Callable[[Path], None], describe: Callable[[], dict]) -> Path:
    """Write a table with ``write(temporary path)`` and its sidecar (``describe()`` after the table's name
    and ``data_sha256``) as one unit, the output locked against a second writer; returns the sidecar's path.
    A :class:`Path` in the description is written relative to the sidecar's folder (:func:`relative_path`)."""
    path = Path(path)
    with output_lock(path), contextlib.ExitStack() as temporaries:
        with signals_held():  # each temporary file's removal is registered before a signal can end the process
            table = AtomicFile(path)
            temporaries.callback(table.discard)
            sidecar = AtomicFile(sidecar_path(path))
            temporaries.callback(sidecar.discard)
        with writing(table, sidecar):
            write(table.temp)
            metadata = {"file": path.name, "data_sha256": sha256(table.temp)}
            metadata |= _relative_paths(describe(), path.parent)
            sidecar.temp.write_text(json_text(metadata), encoding="utf-8")
            commit_together([sidecar, table])
    return sidecar.path


def run_sidecar(assembly: Assembly, duration_s: float, dt_s: float, components: Components) -> dict:
    """What every sidecar says of a run: the scenario (its path, made relative by :func:`write_table`) and its hash,
    the seed, the time axis (s), the wave components used and the sea (from the spectrum and measured on the
    surface), the versions."""
    scenario = assembly.scenario
    return {
        "scenario": scenario.path,
        "scenario_sha256": sha256(scenario.path),
        "seed": scenario.run.seed,
        "duration_s": duration_s,
        "dt_s": dt_s,
        "components": len(components),
        "variance_fraction": VARIANCE_FRACTION,
        "sea": summary(assembly.ocean),
        "versions": {"marinesim": __version__, "numpy": np.__version__, "python": platform.python_version()},
    }
