"""The live motion recorder: rows at the run's dt from its start to its stop, written as ``marinesim
export`` writes them, with the export's sidecar.

Each row is computed on its own (:meth:`Simulation.frame` at one time ``k dt``), after the clock has
passed it and before any live action at that time: its bits depend on the timeline only, not on
how the frames fell, so a replay of the session (:mod:`marinesim.session.replay`) writes the same
bytes. Rows stream to a temporary file beside the target; on :meth:`Recorder.stop` the table and
its sidecar are put in place as one unit.
"""

from __future__ import annotations

import math
import os
from pathlib import Path

import numpy as np

from marinesim.atomic import check_replaceable, temporary
from marinesim.errors import MarinesimError
from marinesim.session.exercise import Exercise
from marinesim.session.export import motions_sidecar, write_csv_block
from marinesim.session.sidecar import write_table


class Recorder:
    """Records ``exercise``'s vessel motions to the CSV ``path`` from now until :meth:`stop`."""

    def __init__(self, exercise: Exercise, path: Path) -> None:
        self.exercise, self.path = exercise, Path(path)
        if exercise.sim.vessel is None:
            raise MarinesimError("nothing to record: the scenario has no vessel")
        self.path.parent.mkdir(parents=True, exist_ok=True)
        check_replaceable(self.path)
        self._temp = temporary(self.path, ".rows")
        self._handle = self._temp.open("w", encoding="utf-8", newline="")
        self._dt = exercise.dt
        self._first = self._next = math.ceil(exercise.sim.time / self._dt - 1e-9)  # the next row's index
        self.rows = 0

    def catch_up(self) -> None:
        """Write the rows up to the clock, one at a time."""
        last = math.floor(self.exercise.sim.time / self._dt + 1e-9)
        if last < self._next:
            return
        rows = [self.exercise.sim.frame(np.array([k * self._dt])) for k in range(self._next, last + 1)]
        write_csv_block(self._handle, {name: np.concatenate([row[name] for row in rows]) for name in rows[0]},
                        header=self.rows == 0)
        self.rows += len(rows)
        self._next = last + 1

    def stop(self) -> Path:
        """Write the last rows, then the table and its sidecar as one unit; returns the table's path."""
        self.catch_up()
        self._handle.close()
        span = (self._next - 1) * self._dt

        def describe() -> dict:
            return {"format": "csv", **motions_sidecar(self.exercise, self.rows, span),
                    "first_time_s": self._first * self._dt}

        try:
            write_table(self.path, lambda temp: os.replace(self._temp, temp), describe)
        finally:
            self._discard()
        return self.path

    def abandon(self) -> None:
        """Close and delete the rows written so far, keeping nothing (writing them failed)."""
        self._handle.close()
        self._discard()

    def _discard(self) -> None:
        try:
            os.unlink(self._temp)
        except FileNotFoundError:
            pass
