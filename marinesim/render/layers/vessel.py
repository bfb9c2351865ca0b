"""The vessel pass: the drawn mesh (body frame) carried by the 6-DOF pose, lit by the sky and sun, its draft marks
painted on (:mod:`~marinesim.render.draft_marks`)."""

from __future__ import annotations

import moderngl

from marinesim.gl import Program
from marinesim.pose import Pose
from marinesim.render.draft_marks import GLYPH, NO_MARKS, DraftMarks
from marinesim.render.layers.base import View, mat4
from marinesim.render.vessel_mesh import TOPSIDES, VesselMesh, buoy_mesh, vessel_mesh, visual_mesh
from marinesim.scenario.schema import OtherVessel
from marinesim.session.timeline import Simulation


def drawn_mesh(sim: Simulation) -> VesselMesh | None:
    """The vessel as drawn (body frame, m): the scenario's visual mesh, else a ship made from the hull (topsides,
    paint, the superstructure around the bridge point); None without either."""
    vessel = sim.vessel
    if vessel is not None and vessel.visual is not None:
        return visual_mesh(vessel.visual)
    if vessel is not None and vessel.hull is not None:
        topsides = TOPSIDES if vessel.topsides_rgb is None else tuple(c / 255.0 for c in vessel.topsides_rgb)
        return vessel_mesh(vessel.hull, house_at=vessel.points.get("bridge"), topsides=topsides,
                           deck_layout=vessel.deck_layout)
    return None


def other_mesh(other: OtherVessel) -> VesselMesh:
    """Another body as drawn (body frame, m): its visual mesh, a ship made from its hull, or a buoy."""
    if other.visual is not None:
        return visual_mesh(other.visual)
    if other.hull is not None:
        topsides = TOPSIDES if other.topsides_rgb is None else tuple(c / 255.0 for c in other.topsides_rgb)
        length = float(other.hull.vertices[:, 0].max() - other.hull.vertices[:, 0].min())
        house = (float(other.hull.vertices[:, 0].min()) + 0.12 * length, 0.0, 0.08 * length)
        return vessel_mesh(other.hull, house_at=house, topsides=topsides)
    return buoy_mesh()


class VesselLayer:
    """Draws ``mesh`` with back faces culled and ``marks`` painted on; nothing when it is None or not ``shown``."""

    def __init__(self, ctx: moderngl.Context, mesh: VesselMesh | None, shown: bool = True,
                 marks: DraftMarks | None = None) -> None:
        self.ctx, self.mesh, self.shown = ctx, mesh, shown
        self.marks = marks.uniforms() if marks is not None else NO_MARKS
        self.program = Program.from_files(ctx, "vessel", **GLYPH)
        self.vao = self._vbo = None
        if mesh is not None:
            self._vbo = ctx.buffer(mesh.vertex_data().tobytes())
            self.vao = ctx.vertex_array(self.program.gl, [
                (self._vbo, "3f 3f 3f", "in_position", "in_normal", "in_colour")])

    def replace(self, mesh: VesselMesh) -> None:
        """Draw ``mesh`` from now on: as many triangles as the mesh it was made with (a wire moved each frame)."""
        self.mesh = mesh
        self._vbo.write(mesh.vertex_data().tobytes())

    def draw(self, view: View, pose: Pose) -> None:
        """The mesh in ``pose`` (body -> E frame)."""
        if self.vao is None or not self.shown:
            return
        self.ctx.enable(moderngl.CULL_FACE)
        self.program.update(view.shared() | self.marks | {"u_model": mat4(pose.matrix()),
                                                          "u_view_projection": mat4(view.view_projection)})
        self.vao.render(moderngl.TRIANGLES)
        self.ctx.disable(moderngl.CULL_FACE)

    def release(self) -> None:
        if self.vao is not None:
            self.vao.release()
            self._vbo.release()
        self.program.release()
