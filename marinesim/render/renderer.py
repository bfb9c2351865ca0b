"""Draws a :class:`~marinesim.session.timeline.Simulation` with moderngl: sky, ocean, vessel.

Per frame, :meth:`Renderer.update` brings the GPU up to the simulation's time (the cascades'
fields uploaded to texture arrays with mipmaps, foam persistence in a compute pass; the local
solver, which the simulation steps, is read as it is) and :meth:`Renderer.draw` draws a camera's view into the bound framebuffer:

1. the sky (a full-screen pass: analytic sky, sun, haze below the horizon);
2. the ocean: rings of vertices around the camera out to ``OCEAN_RADIUS_M``, each displaced by
   the cascades (mip level from its spacing), the Kelvin wake (vessel frame) and the solver's
   field (Earth-fixed grid); shaded with Fresnel, sky reflection, subsurface tint, glitter, foam
   and haze (``shaders/ocean.*``, ``surface.glsl``, ``sky.glsl``); no water inside the hull;
3. the vessel mesh (the scenario's visual mesh, else one made from the hull) in its 6-DOF pose.

Everything is in the Earth frame (m); the shaders state their inputs' units.
"""

from __future__ import annotations

import math
import time
from dataclasses import dataclass

import moderngl
import numpy as np

from marinesim.angles import compass_to_math
from marinesim.gl import GraphicsError, is_software, shader_source
from marinesim.render.camera import Eye
from marinesim.hull.waterplane import inside, waterline_loops
from marinesim.render.vessel_mesh import VesselMesh, vessel_mesh, visual_mesh
from marinesim.session.timeline import Simulation
from marinesim.wake.compute import Wake

OCEAN_RADIUS_M = 20_000.0
RING_SEGMENTS = 192
INNER_SPACING_M = 0.5
FOAM_TAU_S = 4.0
"""The held Jacobian relaxes back to 1 as exp(-t / tau) once the surface stops folding (foam.comp)."""
FOAM_J_START, FOAM_J_FULL = 0.90, 0.60
"""Jacobian of the surface where foam starts and where it covers the surface fully."""
BREAKING_SLOPE = 0.3
"""Steepest wake slope drawn (a Stokes wave breaks at a slope of about 0.45; groups break earlier)."""
WAKE_SLOPE_FOAM = (0.2, 0.3)
"""Wake slopes where the wake's own foam starts and is full (breaking diverging waves)."""
HULL_MASK_CELLS = (512, 128)


@dataclass(frozen=True)
class RenderOptions:
    """What to draw: the Kelvin wake, foam, the vessel, the local solver (``solver_size`` cells a side), the sun
    (compass azimuth and elevation, deg) and the visibility (m) that sets the haze."""

    wake: bool = True
    foam: bool = True
    vessel: bool = True
    solver: bool = False
    solver_size: int = 512
    sun_azimuth_deg: float = 200.0
    sun_elevation_deg: float = 30.0
    visibility_m: float = 15_000.0

    def sun(self) -> tuple[float, float, float]:
        azimuth, elevation = compass_to_math(self.sun_azimuth_deg), math.radians(self.sun_elevation_deg)
        return (math.cos(elevation) * math.cos(azimuth), math.cos(elevation) * math.sin(azimuth), math.sin(elevation))


@dataclass(frozen=True)
class FrameTimes:
    """Seconds spent in the last update and draw: simulation (the ocean's FFTs),
    upload (textures, mipmaps, foam pass) and draw. GPU work is asynchronous unless ``sync`` was asked."""

    simulation: float
    upload: float
    draw: float = 0.0


class Renderer:
    """The GL side of a simulation, on ``ctx`` (a window's context or a headless one)."""

    def __init__(self, ctx: moderngl.Context, sim: Simulation, options: RenderOptions = RenderOptions()) -> None:
        self.ctx, self.sim, self.options = ctx, sim, options
        self._last_time: float | None = None
        self.times = FrameTimes(0.0, 0.0)
        tiles = sim.ocean.tiles
        self._tile_count, n = len(tiles), sim.ocean.resolution
        defines = {"TILES": self._tile_count, "TILE_LOD": f"{math.log2(n):.1f}", "FOAM_J_START": FOAM_J_START,
                   "FOAM_J_FULL": FOAM_J_FULL}

        def program(name: str) -> moderngl.Program:
            return ctx.program(vertex_shader=shader_source(f"{name}.vert", **defines),
                               fragment_shader=shader_source(f"{name}.frag", **defines))
        try:
            self._sky, self._ocean, self._vessel_program = program("sky"), program("ocean"), program("vessel")
            self._foam_pass = ctx.compute_shader(shader_source("foam.comp"))
        except moderngl.Error as error:
            raise GraphicsError(f"a viewer shader did not compile: {error}") from None

        self._cascades = self._texture_array(n, 4)
        self._slopes = self._texture_array(n, 2)
        self._foam = self._texture_array(n, 2)  # held Jacobian and its square (foam.comp)
        self._foam.write(np.ones((self._tile_count, n, n, 2), np.float32).tobytes())  # nothing folded yet
        self._packed = np.empty((self._tile_count, n, n, 4), np.float32)
        self._packed_slopes = np.empty((self._tile_count, n, n, 2), np.float32)

        self._sky_vao = ctx.vertex_array(self._sky, [])
        grid, indices = ring_grid(OCEAN_RADIUS_M, RING_SEGMENTS, INNER_SPACING_M)
        self._grid_vbo, self._grid_ibo = ctx.buffer(grid.tobytes()), ctx.buffer(indices.tobytes())
        self._ocean_vao = ctx.vertex_array(self._ocean, [(self._grid_vbo, "3f", "in_grid")], self._grid_ibo)
        # as bytes: moderngl takes a one-element array uniform only as a scalar
        self._set(self._ocean, "u_tile_size", np.array([t.size for t in tiles], np.float32).tobytes())
        self._set(self._ocean, "u_tile_spacing", np.array([t.spacing for t in tiles], np.float32).tobytes())

        self._wake_textures: dict[int, tuple[moderngl.Texture, tuple[float, float, float, float]]] = {}
        self._blank = ctx.texture((1, 1), 4, np.zeros(4, np.float32).tobytes(), dtype="f4")
        hull = sim.vessel.hull if sim.vessel is not None else None
        self._vessel_vao = self._mask = None
        self.mesh = drawn_mesh(sim)
        if self.mesh is not None:
            self._vessel_vbo = ctx.buffer(self.mesh.vertex_data().tobytes())
            self._vessel_vao = ctx.vertex_array(self._vessel_program, [
                (self._vessel_vbo, "3f 3f 3f", "in_position", "in_normal", "in_colour")])
        if hull is not None:
            self._mask, self._mask_rect = self._hull_mask(hull)

    # -- resources ------------------------------------------------------------------------------

    def _texture_array(self, n: int, components: int) -> moderngl.TextureArray:
        texture = self.ctx.texture_array((n, n, self._tile_count), components, dtype="f4")
        texture.filter = (moderngl.LINEAR_MIPMAP_LINEAR, moderngl.LINEAR)
        texture.repeat_x = texture.repeat_y = True
        texture.anisotropy = 1.0 if is_software(self.ctx) else 8.0  # llvmpipe filters anisotropically at a crawl
        return texture

    def _hull_mask(self, hull) -> tuple[moderngl.Texture, tuple[float, float, float, float]]:
        """The waterplane (inside the waterline loops) rasterised in the vessel frame."""
        loops = waterline_loops(hull)
        corners = np.concatenate(loops)
        lo, hi = corners.min(axis=0), corners.max(axis=0)
        pad = 0.02 * (hi - lo)
        lo, hi = lo - pad, hi + pad
        nx, ny = HULL_MASK_CELLS
        x = lo[0] + (np.arange(nx) + 0.5) * (hi[0] - lo[0]) / nx
        y = lo[1] + (np.arange(ny) + 0.5) * (hi[1] - lo[1]) / ny
        hull_cells = inside(loops, x, y)
        # shrink by one cell so the water meets the hull instead of leaving a gap beside it
        hull_cells[1:-1, 1:-1] &= (hull_cells[:-2, 1:-1] & hull_cells[2:, 1:-1] & hull_cells[1:-1, :-2]
                                   & hull_cells[1:-1, 2:])
        texture = self.ctx.texture((nx, ny), 1, (hull_cells * 255).astype(np.uint8).tobytes())
        texture.repeat_x = texture.repeat_y = False
        return texture, (lo[0], lo[1], 1.0 / (hi[0] - lo[0]), 1.0 / (hi[1] - lo[1]))

    def _wake_texture(self, wake: Wake) -> tuple[moderngl.Texture, tuple[float, float, float, float]]:
        key = id(wake)
        if key not in self._wake_textures:
            self._wake_textures[key] = upload_wake(self.ctx, wake, self.sim.vessel.hull)
        return self._wake_textures[key]

    # -- per frame --------------------------------------------------------------------------------

    def update(self, sync: bool = False) -> FrameTimes:
        """Bring the GPU to the simulation's time: fields and foam. ``sync`` waits for the GPU
        after each stage so that the times split truly (for benchmarks)."""
        t = self.sim.time
        dt = 0.0 if self._last_time is None else max(t - self._last_time, 0.0)
        self._last_time = t
        start = time.perf_counter()
        fields = self.sim.ocean.fields(t)
        if sync:
            self.ctx.finish()
        simulated = time.perf_counter()
        packed, slopes = self._packed, self._packed_slopes
        for i, f in enumerate(fields):
            packed[i, ..., 0], packed[i, ..., 1] = f.displacement_x, f.displacement_y
            packed[i, ..., 2], packed[i, ..., 3] = f.height, f.jacobian
            slopes[i, ..., 0], slopes[i, ..., 1] = f.slope_x, f.slope_y
        self._cascades.write(packed)  # buffer protocol: no copy
        self._slopes.write(slopes)
        self._cascades.build_mipmaps()
        self._slopes.build_mipmaps()
        self._update_foam(dt)
        if sync:
            self.ctx.finish()
        self.times = FrameTimes(simulated - start, time.perf_counter() - simulated)
        return self.times

    def _update_foam(self, dt: float) -> None:
        n = self.sim.ocean.resolution
        self._cascades.use(0)
        self._foam.bind_to_image(0, read=True, write=True)
        shader = self._foam_pass
        self._set(shader, "u_cascades", 0)
        self._set(shader, "u_decay", math.exp(-dt / FOAM_TAU_S))
        shader.run(n // 16, n // 16, self._tile_count)
        self.ctx.memory_barrier()
        self._foam.build_mipmaps()

    def draw(self, eye: Eye, size: tuple[int, int], sync: bool = False) -> float:
        """Draw the view of ``eye`` into the bound framebuffer of ``size`` (w, h) px; returns seconds."""
        start = time.perf_counter()
        ctx = self.ctx
        width, height = size
        view_projection = eye.view_projection(width / height)
        shared = {"u_sun": self.options.sun(), "u_visibility": self.options.visibility_m,
                  "u_eye": tuple(eye.position)}
        ctx.enable_only(moderngl.DEPTH_TEST)
        ctx.clear(0.0, 0.0, 0.0, 1.0, depth=1.0)

        ctx.disable(moderngl.DEPTH_TEST)
        self._uniforms(self._sky, shared | {
            "u_inverse_view_projection": _matrix(np.linalg.inv(view_projection))})
        self._sky_vao.render(moderngl.TRIANGLES, vertices=3)
        ctx.enable(moderngl.DEPTH_TEST)

        pose = self.sim.pose()
        self._draw_ocean(eye, view_projection, shared, pose)
        if self._vessel_vao is not None and self.options.vessel:
            ctx.enable(moderngl.CULL_FACE)
            self._uniforms(self._vessel_program, shared | {"u_model": _matrix(pose.matrix()),
                                                           "u_view_projection": _matrix(view_projection)})
            self._vessel_vao.render(moderngl.TRIANGLES)
            ctx.disable(moderngl.CULL_FACE)
        if sync:
            ctx.finish()
        seconds = time.perf_counter() - start
        self.times = FrameTimes(self.times.simulation, self.times.upload, seconds)
        return seconds

    def _draw_ocean(self, eye: Eye, view_projection: np.ndarray, shared: dict, pose) -> None:
        centre = np.floor(eye.position[:2] / (4.0 * INNER_SPACING_M)) * (4.0 * INNER_SPACING_M)
        values = shared | {"u_view_projection": _matrix(view_projection), "u_centre": tuple(centre),
                           "u_track": (pose.x, pose.y, pose.heading), "u_foam_on": float(self.options.foam),
                           "u_cascades": 0, "u_slopes": 1, "u_foam": 2, "u_wake0": 3, "u_wake1": 4,
                           "u_solver": 5, "u_hull_mask": 6}
        self._cascades.use(0)
        self._slopes.use(1)
        self._foam.use(2)
        wakes = self.sim.wakes() if self.options.wake else []
        weights = [0.0, 0.0]
        for slot in range(2):
            texture, rect = (self._blank, (0.0, 0.0, 1.0, 1.0))
            if slot < len(wakes):
                texture, rect = self._wake_texture(wakes[slot][0])
                weights[slot] = wakes[slot][1]
            texture.use(3 + slot)
            values[f"u_wake_rect{slot}"] = rect
        values["u_wake_weight"] = tuple(weights)
        solver = self.sim.solver
        if solver is not None:
            solver.height_texture.use(5)
            origin = solver.origin
            values["u_solver_rect"] = (origin[0], origin[1], 1.0 / solver.extent_m, 1.0)
            values["u_solver_cell"] = solver.config.cell_m
        else:
            self._blank.use(5)
            values["u_solver_rect"] = (0.0, 0.0, 1.0, 0.0)
            values["u_solver_cell"] = 1.0
        if self._mask is not None:
            self._mask.use(6)
            values["u_hull_rect"] = self._mask_rect
        else:
            self._blank.use(6)
            values["u_hull_rect"] = (0.0, 0.0, 0.0, 0.0)
        self._uniforms(self._ocean, values)
        self._ocean_vao.render(moderngl.TRIANGLES)

    def _uniforms(self, program: moderngl.Program, values: dict) -> None:
        for name, value in values.items():
            self._set(program, name, value)

    @staticmethod
    def _set(program, name: str, value) -> None:
        """Set a uniform the compiler kept (unused ones are optimised away)."""
        try:
            member = program[name]
        except KeyError:
            return
        if isinstance(value, bytes):
            member.write(value)
        else:
            member.value = value

    def release(self) -> None:
        for texture, _ in self._wake_textures.values():
            texture.release()
        for resource in (self._cascades, self._slopes, self._foam, self._blank, self._grid_vbo, self._grid_ibo,
                         self._ocean_vao, self._sky_vao, self._sky, self._ocean, self._vessel_program,
                         self._foam_pass):
            resource.release()
        if self._vessel_vao is not None:
            self._vessel_vao.release()
            self._vessel_vbo.release()
        if self._mask is not None:
            self._mask.release()


def drawn_mesh(sim: Simulation) -> VesselMesh | None:
    """The vessel as drawn (body frame, m): the scenario's visual mesh, else the hull with topsides and a
    deckhouse around the bridge point; None without either."""
    vessel = sim.vessel
    if vessel is not None and vessel.visual is not None:
        return visual_mesh(vessel.visual)
    if vessel is not None and vessel.hull is not None:
        return vessel_mesh(vessel.hull, house_at=vessel.points.get("bridge"))
    return None


def ring_grid(radius_m: float, segments: int, inner_spacing_m: float) -> tuple[np.ndarray, np.ndarray]:
    """Rings of ``segments`` vertices whose spacing grows with the radius (cells stay square),
    from ``inner_spacing_m`` out to ``radius_m``, and a disc in the middle. Returns float32 rows
    (x, y, spacing) in m and uint32 triangle indices."""
    step = 2.0 * math.pi / segments
    radii = [0.0]
    r = inner_spacing_m / step
    uniform_rings = int(r / inner_spacing_m)
    radii += list(inner_spacing_m * np.arange(1, uniform_rings + 1))
    r = radii[-1]
    while r < radius_m:
        r *= 1.0 + step
        radii.append(r)
    radii = np.array(radii[1:])
    angle = np.arange(segments) * step
    x = (radii[:, None] * np.cos(angle)).ravel()
    y = (radii[:, None] * np.sin(angle)).ravel()
    spacing = np.repeat(np.maximum(radii * step, inner_spacing_m), segments)
    vertices = np.c_[np.r_[0.0, x], np.r_[0.0, y], np.r_[inner_spacing_m, spacing]].astype(np.float32)
    ring = np.arange(segments)
    following = (ring + 1) % segments
    triangles = [np.c_[np.zeros(segments, int), ring + 1, following + 1]]
    for i in range(len(radii) - 1):
        a, b = 1 + i * segments, 1 + (i + 1) * segments
        triangles.append(np.c_[a + ring, b + ring, b + following])
        triangles.append(np.c_[a + ring, b + following, a + following])
    return vertices, np.concatenate(triangles).astype(np.uint32)


def upload_wake(ctx: moderngl.Context, wake: Wake, hull) -> tuple[moderngl.Texture, tuple[float, float, float, float]]:
    """The wake as an RGBA32F texture (elevation m, d/dx, d/dy in the vessel frame, foam 0..1) and
    its rect (x, y of the grid's outer corner, 1 / width, 1 / height; m, vessel frame).

    Thin-ship theory overpredicts the waves of full hulls, up to slopes no water wave survives: a
    field whose steepest waves (99.9th percentile of the slope) pass ``BREAKING_SLOPE`` is scaled
    down to it, as breaking would cap them. Foam: where the diverging waves are near breaking
    (slope ``WAKE_SLOPE_FOAM``), and the turbulent wash
    astern, a band as wide as the beam that spreads by a tenth of its width per beam travelled and
    fades over three hull lengths, stronger at higher Froude number.
    """
    h = np.asarray(wake.elevation, np.float64)
    spacing = float(wake.x[1] - wake.x[0])
    dhdy, dhdx = np.gradient(h, spacing)
    slope = np.hypot(dhdx, dhdy)
    limit = BREAKING_SLOPE / max(float(np.percentile(slope, 99.9)), BREAKING_SLOPE)
    h, dhdx, dhdy, slope = h * limit, dhdx * limit, dhdy * limit, slope * limit
    lo, hi = WAKE_SLOPE_FOAM
    foam = np.clip((slope - lo) / (hi - lo), 0.0, 1.0)
    stern = float(hull.vertices[:, 0].min())
    beam = float(np.ptp(hull.vertices[:, 1]))
    length = float(np.ptp(hull.vertices[:, 0]))
    behind = np.maximum(stern - wake.x, 0.0)[None, :]
    half_width = 0.5 * beam * (1.0 + 0.1 * behind / beam)
    froude = float(wake.info.get("froude", 0.2))
    wash = np.exp(-(wake.y[:, None] / half_width) ** 2) * np.exp(-behind / (3.0 * length))
    wash *= (wake.x[None, :] < stern) * min(1.0, 3.0 * froude)
    foam = np.maximum(foam, wash)
    data = np.stack([h, dhdx, dhdy, foam], axis=-1).astype(np.float32)
    texture = ctx.texture((h.shape[1], h.shape[0]), 4, data.tobytes(), dtype="f4")
    texture.repeat_x = texture.repeat_y = False
    x0, y0 = float(wake.x[0]) - 0.5 * spacing, float(wake.y[0]) - 0.5 * spacing
    return texture, (x0, y0, 1.0 / (spacing * h.shape[1]), 1.0 / (spacing * h.shape[0]))


def _matrix(m: np.ndarray) -> bytes:
    """A 4 x 4 matrix as a GLSL mat4 (column-major float32)."""
    return np.ascontiguousarray(m.T, dtype=np.float32).tobytes()
