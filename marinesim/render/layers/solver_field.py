"""The local solver's field on the water: its height texture (the solver owns and steps it) and where it lies."""

from __future__ import annotations

import moderngl

from marinesim.render.layers.base import blank_texture
from marinesim.session.timeline import Simulation


class SolverFieldLayer:
    """Binds ``sim.solver``'s height texture (m, Earth-fixed grid) and its rect (origin x, y in m, E frame,
    1 / extent, weight 1), or nothing (weight 0) while the simulation runs no solver on the GPU."""

    units = 1

    def __init__(self, ctx: moderngl.Context, sim: Simulation) -> None:
        self.sim = sim
        self._blank = blank_texture(ctx)

    def bind(self, unit: int) -> dict[str, object]:
        solver = self.sim.solver
        if solver is None:
            self._blank.use(unit)
            return {"u_solver": unit, "u_solver_rect": (0.0, 0.0, 1.0, 0.0), "u_solver_cell": 1.0}
        solver.height_texture.use(unit)
        origin = solver.origin
        return {"u_solver": unit, "u_solver_rect": (origin[0], origin[1], 1.0 / solver.extent_m, 1.0),
                "u_solver_cell": solver.config.cell_m}

    def release(self) -> None:
        self._blank.release()
