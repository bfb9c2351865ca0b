"""The JSON sidecar beside every table a run writes: what produced it, so that it can be produced again.

It holds no clock time: the same scenario, seed and inputs give the same bytes.
"""

from __future__ import annotations

import hashlib
import platform
from pathlib import Path

import numpy as np

from marinesim import __version__
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
