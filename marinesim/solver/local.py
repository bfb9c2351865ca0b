"""The local wave solver's common part: configuration, grid placement, sub-steps, hull forcing.

The grid is a window of ``size`` x ``size`` cells on a lattice fixed in the Earth frame (cell
``(I, J)`` of the lattice covers ``[I c, (I + 1) c] x [J c, (J + 1) c]``, ``c`` the cell size). It
follows the vessel by whole cells: when the track point leaves the central cell the content is
shifted and the cells that come in are at rest. :attr:`LocalSolver.origin` is the world position of
the grid's corner, so where the field lies is always known; the vessel's offset from the grid
centre (less than a cell) is :attr:`LocalSolver.vessel_offset`.

Forcing (see spectral.py): the hull is a pressure ``rho g d`` with ``d`` the displaced depth
(footprint.py); a hull at rest holds the surface at ``h = -d`` and makes no waves; a change of
``d`` radiates. Two modes:

- ``"unsteady"`` (default, with the precomputed Kelvin wake): ``d = d(pose) - d(steady pose)``.
  The steady pose is the hull on its track without the 6-DOF motion, which is exactly the hull
  the Kelvin wake is computed for; a vessel on a steady course drives nothing here, so the steady
  wake is counted once (by the Kelvin field) and the solver adds what the motions radiate. The
  renderer adds the two fields.
- ``"full"``: ``d = d(pose)``; the solver makes the whole wave pattern itself (no Kelvin field,
  or a body the precompute does not know). Started at rest about the hull (h = -d).

Obstacles (quays, breakwaters) are polygons fixed in the Earth frame; inside them the surface is
held still (h = phi = 0), so waves reflect off their edges.

The hull's waterplane is not such an obstacle: there the hull's pressure holds the surface at
``h = -d``. Holding it at rest instead would cut the hull's own forcing off from the water (it
acts through phi, which an obstacle fixes), and a hull at rest would not leave the water flat.

A vessel that moves faster than ``max_speed_m_s`` between two calls has jumped (a scenario reset,
a teleport): the grid is placed on it afresh and the water starts at rest, rather than the hull
being dragged through it. A caller that pauses should not pass the paused time as ``dt``: every
second of it is stepped.
"""

from __future__ import annotations

import logging
import math
from dataclasses import dataclass

import numpy as np

from marinesim.constants import RHO_SEAWATER, G
from marinesim.errors import ParameterError, require_finite, require_positive
from marinesim.hull.mesh import Hull
from marinesim.hull.waterplane import inside
from marinesim.pose import Pose
from marinesim.solver import spectral
from marinesim.solver.footprint import Placement, to_grid

log = logging.getLogger("marinesim.solver")

FORCING_MODES = ("unsteady", "full")
MAX_SPEED_M_S = 20.0
JUMP_FACTOR = 1.5
"""A pose that moved faster than this times the maximum speed since the last call has jumped."""
CELLS_PER_SHORTEST_WAVE = 8
SHORTEST_WAVE_PER_HULL_LENGTH = 1.0 / 12.0
"""The shortest wave worth resolving here is a twelfth of the hull: shorter ones barely move it
(and the FFT ocean draws them); so the default grid of 512 spans about 5 hull lengths."""


@dataclass(frozen=True)
class SolverConfig:
    """Grid and numerics of the local solver.

    ``damping_s``: e-folding time (s) of the shortest wave on the grid (2 cells); a wave ``m``
    times longer lasts ``m^2`` times longer (k^2 viscosity). ``None`` turns damping off.
    ``sponge_cells``: width of the absorbing layer at each edge (default size / 8): it
    absorbs waves up to that length (spectral.sponge_rate).
    """

    size: int = 512
    cell_m: float = 0.5
    damping_s: float | None = 5.0
    sponge_cells: int | None = None
    max_speed_m_s: float = MAX_SPEED_M_S
    forcing: str = "unsteady"
    g: float = G
    rho: float = RHO_SEAWATER

    def __post_init__(self) -> None:
        if not (isinstance(self.size, int) and 16 <= self.size <= 2048 and self.size & (self.size - 1) == 0):
            raise ParameterError(f"solver grid size must be a power of two from 16 to 2048, got {self.size!r}")
        require_positive("solver cell size (m)", self.cell_m)
        if self.damping_s is not None:
            require_positive("solver damping time (s)", self.damping_s)
        width = self.sponge_width
        if not 0 <= width <= self.size // 4:
            raise ParameterError(f"sponge width must be 0 to a quarter of the grid ({self.size // 4} cells), got {width}")
        speed = require_positive("solver maximum speed (m/s)", self.max_speed_m_s)
        if speed > MAX_SPEED_M_S:
            raise ParameterError(f"solver maximum speed must be <= {MAX_SPEED_M_S:g} m/s, got {speed:g}")
        if self.forcing not in FORCING_MODES:
            raise ParameterError(f"solver forcing must be one of {', '.join(FORCING_MODES)}, got {self.forcing!r}")
        require_positive("g", self.g)

    @property
    def sponge_width(self) -> int:
        """Cells of the absorbing layer at each edge."""
        return self.size // 8 if self.sponge_cells is None else int(self.sponge_cells)

    @classmethod
    def for_hull(cls, hull: Hull, size: int = 512, **options) -> SolverConfig:
        """Cells of a twelfth of the hull's length over CELLS_PER_SHORTEST_WAVE."""
        shortest = hull.overall_length_m * SHORTEST_WAVE_PER_HULL_LENGTH
        return cls(size=size, cell_m=shortest / CELLS_PER_SHORTEST_WAVE, **options)


class LocalSolver:
    """The solver's logic; a backend (NumPy reference or GPU) supplies the field operations.

    ``step(dt, pose)`` advances by ``dt`` seconds to the vessel pose at the end of the interval,
    in fixed sub-steps (:func:`spectral.substep_limit`); the pose is interpolated between calls.
    Time left over (less than one sub-step) is carried to the next call.
    """

    def __init__(self, config: SolverConfig, hull: Hull | None = None, pose: Pose | None = None,
                 obstacles: tuple[np.ndarray, ...] = ()) -> None:
        self.config, self.hull = config, hull
        self.obstacles = tuple(np.asarray(p, dtype=float) for p in obstacles)
        for polygon in self.obstacles:
            if polygon.ndim != 2 or polygon.shape[1] != 2 or len(polygon) < 3 or not np.all(np.isfinite(polygon)):
                raise ParameterError("an obstacle must be a polygon of at least three finite (x, y) points in metres")
        c = config
        self.substep = spectral.substep_limit(c.cell_m, c.max_speed_m_s, c.g)
        self.coefficients = spectral.rotation(c.size, c.cell_m, self.substep, c.g, spectral.viscosity(c.cell_m, c.damping_s))
        self.sponge = spectral.sponge(c.size, c.sponge_width, c.cell_m, c.g, self.substep)
        self.steps = 0           # sub-steps taken; the field is at time steps * substep
        self.resets = 0
        self._frame_time = 0.0   # s, time of the last pose given
        self._setup()
        self.place(pose or Pose())

    # --- placement -------------------------------------------------------------------------
    @property
    def origin(self) -> tuple[float, float]:
        """World position (m, E frame) of the grid's corner (the outer corner of cell (0, 0))."""
        return (self._corner[0] * self.config.cell_m, self._corner[1] * self.config.cell_m)

    @property
    def extent_m(self) -> float:
        return self.config.size * self.config.cell_m

    @property
    def time(self) -> float:
        """Simulated time of the field (s): at most one sub-step behind the last pose given."""
        return self.steps * self.substep

    @property
    def vessel_offset(self) -> tuple[float, float]:
        """Track point of the field's sub-step minus the grid centre (m), each within half a cell."""
        half = 0.5 * self.extent_m
        return (self._grid_pose.x - self.origin[0] - half, self._grid_pose.y - self.origin[1] - half)

    def cell_centres(self) -> tuple[np.ndarray, np.ndarray]:
        """World x of the columns and y of the rows (m)."""
        centres = (np.arange(self.config.size) + 0.5) * self.config.cell_m
        return self.origin[0] + centres, self.origin[1] + centres

    def _corner_for(self, pose: Pose) -> tuple[int, int]:
        half = self.config.size // 2
        return (round(pose.x / self.config.cell_m) - half, round(pose.y / self.config.cell_m) - half)

    # --- stepping ---------------------------------------------------------------------------
    def step(self, dt: float, pose: Pose | None = None) -> int:
        """Advance ``dt`` seconds to ``pose`` (default: where the vessel was). Returns sub-steps taken."""
        dt = require_positive("solver time step (s)", dt)
        target = self._pose if pose is None else _checked(pose)
        start_pose, start_time = self._pose, self._frame_time
        self._frame_time += dt
        if math.hypot(target.x - start_pose.x, target.y - start_pose.y) > JUMP_FACTOR * self.config.max_speed_m_s * dt:
            log.info("local wave solver: the vessel jumped to (%.1f, %.1f) m; the water there starts at rest",
                     target.x, target.y)
            self.steps = math.floor(self._frame_time / self.substep + 1e-9)
            self.place(target)
            return 0
        taken = 0
        while (self.steps + 1) * self.substep <= self._frame_time + 1e-9 * self.substep:
            self.steps += 1
            now = start_pose.toward(target, (self.time - start_time) / dt)
            self._follow(now)
            self._advance(self._placements(now))
            taken += 1
        self._pose = target
        bad = self._take_nonfinite()
        if bad:
            self.resets += 1
            self._rest()
            log.warning("local wave solver: %d non-finite values at t = %.2f s; the field was reset to rest", bad, self.time)
        return taken

    def place(self, pose: Pose) -> None:
        """Centre the grid on ``pose`` with the water at rest (start, after a jump, or when the session seeks)."""
        pose = _checked(pose)
        self._pose = self._grid_pose = pose   # _grid_pose: what the grid was last placed for (the last sub-step's pose)
        self._corner = self._corner_for(pose)
        self._load_keep()
        self._rest()

    def _rest(self) -> None:
        """Water at rest about the hull where the grid now is (h = -d in full forcing, else 0)."""
        self._clear()
        if self.hull is not None and self.config.forcing == "full":
            self._start_at_rest(self._placements(self._grid_pose))

    def release(self) -> None:
        """Free what the backend holds (GPU buffers); nothing for the NumPy reference."""

    def _follow(self, pose: Pose) -> None:
        self._grid_pose = pose
        corner = self._corner_for(pose)
        shift = (corner[0] - self._corner[0], corner[1] - self._corner[1])
        if shift == (0, 0):
            return
        self._corner = corner
        self._shift(shift)            # a sub-step moves less than a cell: jumps are caught in step()
        if self.obstacles:
            self._load_keep()

    def _placements(self, pose: Pose) -> list[Placement] | None:
        """The hull on the grid in ``pose`` (and minus its steady pose, unless the forcing is full); None without
        a hull."""
        if self.hull is None:
            return None
        poses = [(pose, 1.0)] if self.config.forcing == "full" else [(pose, 1.0), (pose.steady(), -1.0)]
        return [(to_grid(p, self.origin, self.config.cell_m), w) for p, w in poses]

    def _load_keep(self) -> None:
        keep = self.sponge * ~inside(self.obstacles, *self.cell_centres()) if self.obstacles else self.sponge
        self._set_keep(keep)

    # --- what the backends provide ------------------------------------------------------------
    def _setup(self) -> None:
        raise NotImplementedError

    def _set_keep(self, keep: np.ndarray) -> None:
        raise NotImplementedError

    def _start_at_rest(self, placements: list[Placement]) -> None:
        raise NotImplementedError

    def _advance(self, placements: list[Placement] | None) -> None:
        raise NotImplementedError

    def _shift(self, shift: tuple[int, int]) -> None:
        raise NotImplementedError

    def _clear(self) -> None:
        raise NotImplementedError

    def _write(self, h: np.ndarray, phi: np.ndarray) -> None:
        raise NotImplementedError

    def _take_nonfinite(self) -> int:
        raise NotImplementedError

    def fields(self) -> tuple[np.ndarray, np.ndarray]:
        """``(h, phi)``: elevation (m) and surface potential (m^2/s), (size, size) float64, rows y."""
        raise NotImplementedError

    def set_fields(self, h: np.ndarray, phi: np.ndarray) -> None:
        """Replace the state: elevation ``h`` (m) and surface potential ``phi`` (m^2/s), rows y."""
        shape = (self.config.size,) * 2
        h, phi = np.asarray(h, dtype=float), np.asarray(phi, dtype=float)
        if h.shape != shape or phi.shape != shape:
            raise ParameterError(f"solver fields must be {shape} arrays, got {h.shape} and {phi.shape}")
        self._write(h, phi)

    def height(self) -> np.ndarray:
        """Surface elevation (m), (size, size), rows y (north), columns x (east)."""
        return self.fields()[0]

    def energy(self) -> float:
        """Wave energy in the grid (J): :func:`spectral.energy`."""
        h, phi = self.fields()
        return spectral.energy(h, phi, self.config.cell_m, self.config.g, self.config.rho)


def _checked(pose: Pose) -> Pose:
    values = (pose.x, pose.y, pose.heading, *pose.motion)
    if len(pose.motion) != 6 or not all(math.isfinite(require_finite("hull pose", v)) for v in values):
        raise ParameterError(f"hull pose must be finite numbers with six motions, got {pose!r}")
    return pose
