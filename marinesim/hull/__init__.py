"""Hull meshes in the body frame, their wetted surface and hydrostatics, parametric hulls, visual meshes.

Importing the package registers its mesh formats in :mod:`marinesim.formats` and nothing more: the names below
are imported on first use, so that listing the formats (``marinesim --help``) imports neither trimesh nor a reader.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from marinesim.formats import Format, register

# Imported now (that module is light): imported later, its module would take the name ``hydrostatics`` from the function
from marinesim.hull.hydrostatics import Hydrostatics, format_hydrostatics, hydrostatics

if TYPE_CHECKING:
    from marinesim.hull.mesh import Hull, load_hull, make_hull
    from marinesim.hull.shapes import box_hull, wigley_half_breadth, wigley_hull
    from marinesim.hull.visual import VisualMesh, load_visual_mesh
    from marinesim.hull.wetted import Surface

__all__ = ["Hull", "Hydrostatics", "Surface", "VisualMesh", "box_hull", "format_hydrostatics", "hydrostatics",
           "load_hull", "load_visual_mesh", "make_hull", "wigley_half_breadth", "wigley_hull"]


def __getattr__(name: str) -> object:
    """The names of ``__all__`` but the hydrostatics', each imported from its module on first use."""
    if name in ("Hull", "load_hull", "make_hull"):
        from marinesim.hull import mesh as module
    elif name in ("box_hull", "wigley_half_breadth", "wigley_hull"):
        from marinesim.hull import shapes as module
    elif name in ("VisualMesh", "load_visual_mesh"):
        from marinesim.hull import visual as module
    elif name == "Surface":
        from marinesim.hull import wetted as module
    else:
        raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
    value = globals()[name] = getattr(module, name)
    return value


register(Format("gdf", "mesh", "WAMIT low-order panels, .gdf", (".gdf",), "marinesim.hull.gdf:read_gdf_mesh"))
register(Format("pnl", "mesh", "HAMS panel mesh, .pnl", (".pnl",), "marinesim.hull.pnl:read_pnl_mesh"))
register(Format("nemoh-mesh", "mesh", "NEMOH mesh, .dat (or Capytaine's .mar)", (".dat", ".mar"),
                "marinesim.hull.nemoh_mesh:read_nemoh_mesh_file", "marinesim.hull.nemoh_mesh:sniff"))
register(Format("gmsh", "mesh", "gmsh mesh, .msh (MSH 2.2 or 4.1): its triangles and quadrangles", (".msh",),
                "marinesim.hull.gmsh_mesh:read_gmsh_mesh"))
register(Format("stl", "mesh", "STL, .stl (or gzipped, .stl.gz)", (".stl", ".stl.gz"),
                "marinesim.hull.mesh:read_mesh"))
register(Format("obj", "mesh", "Wavefront OBJ, .obj (or .obj.gz)", (".obj", ".obj.gz"),
                "marinesim.hull.mesh:read_mesh"))
register(Format("ply", "mesh", "Stanford PLY, .ply (or .ply.gz)", (".ply", ".ply.gz"),
                "marinesim.hull.mesh:read_mesh"))
register(Format("gltf", "mesh", "glTF 2.0, .glb or .gltf", (".glb", ".gltf"), "marinesim.hull.mesh:read_mesh"))
register(Format("off", "mesh", "Object File Format, .off", (".off",), "marinesim.hull.mesh:read_mesh"))
