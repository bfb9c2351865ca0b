"""Local wave solver: dispersive deep-water waves around the vessel, driven by the hull.

:class:`GpuSolver` (moderngl compute shaders) and :class:`ReferenceSolver` (NumPy, the same
numerics in float64) share :class:`LocalSolver`; see spectral.py for the scheme, footprint.py for
the hull's displaced depth and local.py for the grid, the forcing modes and the sub-steps.
"""

from marinesim.solver.local import LocalSolver, SolverConfig
from marinesim.solver.reference import ReferenceSolver

__all__ = ["LocalSolver", "ReferenceSolver", "SolverConfig"]
