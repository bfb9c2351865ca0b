"""The JSON sidecar beside every table a run writes: what produced it, so that it can be produced again.

A table ``m.csv`` has its sidecar ``m.csv.json`` (so ``m.csv`` and ``m.parquet`` keep their own),
which names the table's sha256 (``data_sha256``): the two are written as one unit
(:func:`write_table`), and a reader can tell that a sidecar describes the bytes beside it. The
sidecar holds no clock time: the same scenario, seed and inputs give the same bytes.
"""

from __future__ import annotations

import contextlib
import hashlib
import platform
from pathlib import Path
from typing import Callable

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


def write_table(path: Path, write: Callable[[Path], None], describe: Callable[[], dict]) -> Path:
    """Write a table with ``write(temporary path)`` and its sidecar (``describe()`` after the table's name
    and ``data_sha256``) as one unit, the output locked against a second writer; returns the sidecar's path."""
    path = Path(path)
    with output_lock(path), contextlib.ExitStack() as temporaries:
        with signals_held():  # each temporary file's removal is registered before a signal can end the process
            table = AtomicFile(path)
            temporaries.callback(table.discard)
            sidecar = AtomicFile(sidecar_path(path))
            temporaries.callback(sidecar.discard)
        with writing(table, sidecar):
            write(table.temp)
            metadata = {"file": path.name, "data_sha256": sha256(table.temp)} | describe()
            sidecar.temp.write_text(json_text(metadata), encoding="utf-8")
            commit_together([sidecar, table])
    return sidecar.path


def run_sidecar(assembly: Assembly, duration_s: float, dt_s: float, components: Components) -> dict:
    """What every sidecar says of a run: the scenario and its hash, the seed, the time axis (s), the wave
    components used and the sea (from the spectrum and measured on the surface), the versions."""
    scenario = assembly.scenario
    return {
        "scenario": str(scenario.path),
        "scenario_sha256": sha256(scenario.path),
        "seed": scenario.run.seed,
        "duration_s": duration_s,
        "dt_s": dt_s,
        "components": len(components),
        "variance_fraction": VARIANCE_FRACTION,
        "sea": summary(assembly.ocean),
        "versions": {"marinesim": __version__, "numpy": np.__version__, "python": platform.python_version()},
    }
