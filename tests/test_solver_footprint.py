"""The hull's displaced depth (marinesim.solver.footprint), the pressure the local wave solver is
forced with: it holds the hull's hydrostatic volume in any pose, and the GPU render equals the NumPy one."""

from __future__ import annotations

import numpy as np
import pytest

from conftest import ROOT
from marinesim.hull.hydrostatics import hydrostatics
from marinesim.hull.mesh import load_hull
from marinesim.hull.shapes import wigley_hull
from marinesim.pose import Pose
from marinesim.solver import SolverConfig
from marinesim.solver.footprint import displaced_depth, hull_triangles, to_grid
from marinesim.solver.gpu import GpuSolver


@pytest.fixture(scope="module")
def ctx(gl_context):
    return gl_context


def test_the_displaced_depth_holds_the_hulls_volume_in_any_pose(ctx):
    """Summed over the cells, the rendered depth is the displaced volume of hydrostatics (0.5 %
    for a Wigley hull 80 cells long at any heading); heaving down 0.1 m adds the waterplane area
    times 0.1 m (3 %); the GPU render equals the NumPy one."""
    hull = wigley_hull(20.0, 2.0, 1.25, nx=40, nz=8)
    statics = hydrostatics(hull)
    config = SolverConfig(size=128, cell_m=0.25, forcing="full")
    for heading in (0.0, 0.5, 2.0):
        pose = Pose(0.3, -0.2, heading)
        gpu = GpuSolver(config, hull, pose, ctx=ctx)
        placed = [(to_grid(pose, gpu.origin, config.cell_m), 1.0)]
        reference = displaced_depth(hull_triangles(hull, placed), config.size)
        assert np.abs(gpu.depth - reference).max() <= 1e-4 * reference.max()
        assert reference.sum() * config.cell_m ** 2 == pytest.approx(statics.volume_m3, rel=0.005)
        sunk = Pose(0.3, -0.2, heading, (0.0, 0.0, -0.1, 0.0, 0.0, 0.0))
        deeper = displaced_depth(hull_triangles(hull, [(to_grid(sunk, gpu.origin, config.cell_m), 1.0)]), config.size)
        added = (deeper.sum() - reference.sum()) * config.cell_m ** 2
        assert added == pytest.approx(0.1 * statics.waterplane_area_m2, rel=0.03)
        gpu.release()


def test_a_wetted_surface_mesh_open_at_the_waterline_gives_its_volume(ctx):
    """The WAMIT tanker .gdf has no deck; its missing lid would add nothing (z = 0), so the depth
    render still holds the hydrostatic volume (1 %)."""
    tanker = load_hull(ROOT / "hulls" / "tanker.gdf")
    statics = hydrostatics(tanker)
    config = SolverConfig.for_hull(tanker, size=256, forcing="full")
    solver = GpuSolver(config, tanker, Pose(heading=0.7), ctx=ctx)
    assert solver.depth.sum() * config.cell_m ** 2 == pytest.approx(statics.volume_m3, rel=0.01)
    assert np.all(solver.height() <= 0.0)              # started at rest: the surface held down under the hull
    solver.release()
