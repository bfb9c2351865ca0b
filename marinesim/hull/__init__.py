"""Hull meshes in the body frame, their wetted surface and hydrostatics, parametric hulls, visual meshes."""

from marinesim.atomic import signals_held

with signals_held():  # trimesh imports its optional modules in try/except BaseException: a Ctrl-C or
    import trimesh  # noqa: F401  SIGTERM arriving then was swallowed and the command ran on; now it waits

from marinesim.hull.hydrostatics import Hydrostatics, format_hydrostatics, hydrostatics
from marinesim.hull.mesh import Hull, load_hull, make_hull
from marinesim.hull.shapes import box_hull, wigley_half_breadth, wigley_hull
from marinesim.hull.visual import VisualMesh, load_visual_mesh
from marinesim.hull.wetted import Surface

__all__ = ["Hull", "Hydrostatics", "Surface", "VisualMesh", "box_hull", "format_hydrostatics", "hydrostatics",
           "load_hull", "load_visual_mesh", "make_hull", "wigley_half_breadth", "wigley_hull"]
