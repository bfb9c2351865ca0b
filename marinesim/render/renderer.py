"""Draws a :class:`~marinesim.session.timeline.Simulation` with moderngl: sky, ocean, vessel.

The renderer composes the layers of :mod:`marinesim.render.layers`, each owning its GL resources.
Per frame, :meth:`Renderer.update` brings the layers that change with time up to the simulation's
time: the cascades' fields, synthesised on the GPU (:mod:`~marinesim.render.layers.synthesis`) or by the
ocean's FFTs on the CPU and uploaded, then their mipmaps and the foam's compute pass; the local solver,
which the simulation steps, and the wakes are read as they are when drawn and :meth:`Renderer.draw`
draws a camera's view into the bound framebuffer:

1. the sky (a full-screen pass: analytic sky, clouds, sun, moon and stars, haze below the horizon);
2. the ocean: rings of vertices around the camera, displaced by the cascades, the Kelvin wake
   (vessel frame) and the solver's field (Earth-fixed grid); shaded with Fresnel, sky reflection,
   subsurface tint, glitter, foam and haze; no water inside the hull;
3. the vessel mesh (the scenario's visual mesh, else one made from the hull) in its 6-DOF pose, draft marks on,
   and the other vessels and structures in theirs;
4. spray thrown up where the bow meets the rising sea and blown off the crests in a gale
   (worked out in the session, :mod:`~marinesim.session.spray`; drawn, never written back);
5. the navigation lights, by night and in restricted visibility (COLREG sectors and intensities);
6. rain, as streaks of falling drops over it all.

Everything is in the Earth frame (m); the shaders state their inputs' units.
"""

from __future__ import annotations

from dataclasses import dataclass

import moderngl
import numpy as np

from marinesim.angles import compass_to_math
from marinesim.errors import ParameterError
from marinesim.gl import is_software
from marinesim.pose import Pose
from marinesim.render import CASCADES
from marinesim.render.aircraft import helicopter_lights, helicopter_mesh
from marinesim.render.camera import Eye
from marinesim.render.daylight import Light, light_at
from marinesim.render.draft_marks import draft_marks
from marinesim.render.nav_lights import place_lights
from marinesim.render.layers.base import View
from marinesim.render.layers.cascades import CascadeLayer
from marinesim.render.layers.foam import FoamLayer
from marinesim.render.layers.hull_mask import HullMaskLayer
from marinesim.render.layers.lights import NavLightsLayer
from marinesim.render.layers.ocean import OceanLayer
from marinesim.render.layers.rain import RainLayer
from marinesim.render.layers.sky import SkyLayer
from marinesim.render.layers.spray import SprayLayer
from marinesim.render.layers.synthesis import CascadeSynthesis
from marinesim.render.layers.solver_field import SolverFieldLayer
from marinesim.render.layers.vessel import VesselLayer, drawn_mesh, other_mesh
from marinesim.render.layers.wake import WakeLayer
from marinesim.render.vessel_mesh import CONTAINER_M, boom_mesh, container_mesh, hawser_mesh, wire_mesh
from marinesim.session.spray import Bow, Spray
from marinesim.session.timeline import Simulation


@dataclass(frozen=True)
class RenderOptions:
    """What to draw: the Kelvin wake, foam, spray, the vessel, the local solver (``solver_size`` cells a side).
    The light comes from the simulation's ``[environment]`` (:mod:`~marinesim.render.daylight`). ``cascades``: where the
    ocean's fields are synthesised each frame, ``"gpu"`` (compute shaders), ``"cpu"`` (the ocean's FFTs,
    uploaded) or ``"auto"`` (the GPU where there is one; the CPU on a software renderer, where the compute
    shaders run 10x slower than FFTW). ``reproducible``: the CPU's fields by numpy.fft, the same pixels
    whatever the FFTW plans in the cache (headless renders; about 20 ms more a frame at 4 x 256^2). ``hud``: one of
    :data:`~marinesim.render.HUDS`, drawn over the picture by the scene."""

    wake: bool = True
    foam: bool = True
    spray: bool = True
    vessel: bool = True
    solver: bool = False
    solver_size: int = 512
    cascades: str = "auto"
    reproducible: bool = False
    hud: str = "strip"


def gpu_cascades(ctx: moderngl.Context, choice: str) -> bool:
    """Whether the cascades are synthesised on the GPU for ``choice`` (one of :data:`CASCADES`) on ``ctx``."""
    if choice not in CASCADES:
        raise ParameterError(f"cascades must be one of {', '.join(CASCADES)}, got {choice!r}")
    return choice == "gpu" or (choice == "auto" and not is_software(ctx))


class Renderer:
    """The GL side of a simulation, on ``ctx`` (a window's context or a headless one): its layers, which read
    ``sim`` and own only GL resources."""

    def __init__(self, ctx: moderngl.Context, sim: Simulation, options: RenderOptions = RenderOptions()) -> None:
        self.ctx, self.sim, self.options = ctx, sim, options
        self._last_time: float | None = None
        self._light: tuple[tuple, Light] | None = None
        tiles, n = sim.ocean.tiles, sim.ocean.resolution
        self.mesh = drawn_mesh(sim)
        self.sky = SkyLayer(ctx)
        self.cascades = CascadeLayer(ctx, len(tiles), n)
        on_gpu = gpu_cascades(ctx, options.cascades)
        self.synthesis = CascadeSynthesis(ctx, sim.ocean, self.cascades) if on_gpu else None
        """The GPU synthesis of the cascades, or None: the ocean's FFTs on the CPU, uploaded."""
        self.foam = FoamLayer(ctx, len(tiles), n)
        self.wake = WakeLayer(ctx, sim, shown=options.wake)
        self.solver_field = SolverFieldLayer(ctx, sim)
        self.hull_mask = HullMaskLayer(ctx, sim.vessel.hull if sim.vessel is not None else None,
                                       speed=lambda: sim.speed_m_s)
        self.ocean = OceanLayer(ctx, tiles, n, foam_on=options.foam)
        vessel = sim.vessel
        marks = (draft_marks(vessel.hull, self.mesh.positions) if vessel is not None and vessel.hull is not None
                 and self.mesh is not None else None)
        self.vessel = VesselLayer(ctx, self.mesh, shown=options.vessel, marks=marks)
        self.nav_lights = NavLightsLayer(ctx, place_lights(self.mesh.positions, vessel.nav_lights,
                                                           vessel.points.get("bridge"), vessel.speed_m_s > 0.0)
                                         if self.mesh is not None and options.vessel else [])
        self.others = [VesselLayer(ctx, other_mesh(body.other), shown=options.vessel) for body in sim.bodies]
        """The other vessels and structures, as :attr:`Simulation.bodies`."""
        self.others_lights = [NavLightsLayer(ctx, place_lights(layer.mesh.positions, _lights_of(body.other),
                                                               None, body.other.route.speed > 0.0)
                                             if options.vessel else [])
                              for layer, body in zip(self.others, sim.bodies)]
        self.load = self.wire = self.boom = None
        self._boom_slew = float("nan")
        if sim.lift is not None and options.vessel:
            self.load = VesselLayer(ctx, container_mesh())
            self.wire = VesselLayer(ctx, wire_mesh(np.zeros(3), -np.ones(3)))
            self.boom = VesselLayer(ctx, boom_mesh(np.zeros(3), np.ones(3)))
        moorings = sim.voyage.ship.moorings if sim.station is not None else None
        self.hawsers = [(i, VesselLayer(ctx, hawser_mesh(np.zeros(3), np.ones(3), 0.0)), self._made_fast(line))
                        for i, line in enumerate(moorings.lines if moorings is not None and options.vessel else ())
                        if line.hawser]
        """Own-ship's hawsers (a line's index, its layer, where its far end is made fast): drawn in air from her
        fairlead to the fixed point, or to where the body holding it has moved that point."""
        self.helicopter = self.helicopter_lights = None
        if sim.helicopter is not None and options.vessel:
            self.helicopter = VesselLayer(ctx, helicopter_mesh())
            self.helicopter_lights = NavLightsLayer(ctx, list(helicopter_lights()))
        self.rain = RainLayer(ctx)
        bow = (Bow.of(vessel.hull, self.mesh.positions) if vessel is not None and vessel.hull is not None
               and self.mesh is not None and options.vessel else None)
        self.spray = Spray(sim, bow) if options.spray else None
        self.spray_layer = SprayLayer(ctx)

    def update(self) -> None:
        """Bring the layers to the simulation's time: the cascades' fields, their mipmaps, the foam and the spray."""
        t = self.sim.time
        dt = 0.0 if self._last_time is None else max(t - self._last_time, 0.0)
        self._last_time = t
        if self.synthesis is not None:
            self.synthesis.run(t)
            self.cascades.build_mipmaps()
        else:
            self.cascades.upload(self.sim.ocean.fields(t, self.options.reproducible))
        self.foam.update(self.cascades, dt)
        if self.spray is not None:
            self.spray.update()

    def light(self) -> Light:
        """The light at the simulation's time (the sun and moon from astral take 0.7 ms: worked out once a frame,
        whatever the views and the HUD ask)."""
        key = (self.sim.time, self.sim.environment, id(self.sim.sea))
        if self._light is None or self._light[0] != key:
            self._light = key, light_at(self.sim.environment, self.sim.time, self.sim.sea)
        return self._light[1]

    def view(self, eye: Eye, size: tuple[int, int]) -> View:
        """The view of ``eye`` into a target of ``size`` (w, h) px, in the light of the simulation's time."""
        width, height = size
        return View(eye, eye.view_projection(width / height), self.light())

    def draw(self, eye: Eye, size: tuple[int, int]) -> None:
        """Draw the view of ``eye`` into the bound framebuffer of ``size`` (w, h) px."""
        view = self.view(eye, size)
        self.ctx.enable_only(moderngl.DEPTH_TEST)
        self.ctx.clear(0.0, 0.0, 0.0, 1.0, depth=1.0)
        self.sky.draw(view)
        pose = self.sim.pose()
        self.ocean.draw(view, pose, (self.cascades, self.foam, self.wake, self.solver_field, self.hull_mask))
        self.vessel.draw(view, pose)
        others = self.sim.other_poses()
        for layer, other in zip(self.others, others):
            layer.draw(view, other)
        if self.load is not None:
            self._draw_lift(view, pose)
        if self.hawsers:
            self._draw_hawsers(view, pose, others)
        helicopter = None
        if self.helicopter is not None:
            row = self.sim.helicopter.sample(np.array([self.sim.time]))
            helicopter = Pose(row["x"][0], row["y"][0], compass_to_math(row["heading_deg"][0]),
                              (0.0, 0.0, row["z"][0], 0.0, 0.0, 0.0))
            self.helicopter.draw(view, helicopter)
        if self.spray is not None:
            self.spray_layer.draw(view, self.spray.puffs, size[1])
        self.nav_lights.draw(view, pose, size[1])
        for layer, other in zip(self.others_lights, others):
            layer.draw(view, other, size[1])
        if helicopter is not None:
            self.helicopter_lights.draw(view, helicopter, size[1])
        self.rain.draw(view, self.sim.time)

    def _draw_lift(self, view: View, pose) -> None:
        """The crane's boom, slewed, and its load (a container, along own-ship) hanging on its wire from the tip."""
        row = self.sim.lift.sample(np.array([self.sim.time]))
        load = np.array([row["load_x_m"][0], row["load_y_m"][0], row["load_z_m"][0]])
        tip = np.array([row["tip_x_m"][0], row["tip_y_m"][0], row["tip_z_m"][0]])
        heading = pose.heading + pose.motion[5]
        self.load.draw(view, Pose(load[0], load[1], heading, (0.0, 0.0, load[2], 0.0, 0.0, 0.0)))
        self.wire.replace(wire_mesh(tip, load + np.array([0.0, 0.0, CONTAINER_M[2]])))
        self.wire.draw(view, Pose())
        slew = float(row["slew_deg"][0])
        if slew != self._boom_slew:  # the boom is rebuilt only when it slews
            crane = self.sim.lift.crane
            self.boom.replace(boom_mesh(np.add(crane.pedestal_m, (0.0, 0.0, 1.2)), crane.tip(slew)))
            self._boom_slew = slew
        self.boom.draw(view, pose)

    def _made_fast(self, line) -> tuple[int, np.ndarray] | None:
        """The body at rest whose drawn hull holds ``line``'s fixed point (within 2 m), and that point in its body
        frame (x forward, y to port, z up, m): (index in :attr:`Simulation.bodies`, (3,)); None: none does."""
        fixed = np.array([line.anchor[1], line.anchor[0], line.anchor_height_m])
        for index, (body, layer) in enumerate(zip(self.sim.bodies, self.others)):
            if body.route.speed > 0.0:
                continue
            rest = body.path(np.array([0.0]))
            dx, dy = fixed[0] - rest.x[0], fixed[1] - rest.y[0]
            c, s = np.cos(rest.heading[0]), np.sin(rest.heading[0])
            point = np.array([dx * c + dy * s, -dx * s + dy * c, fixed[2]])
            lo, hi = layer.mesh.positions.min(axis=0) - 2.0, layer.mesh.positions.max(axis=0) + 2.0
            if np.all((point >= lo) & (point <= hi)):
                return index, point
        return None

    def _draw_hawsers(self, view: View, pose: Pose, others: list[Pose]) -> None:
        """Own-ship's hawsers still fast, each sagging under its weight by ``w s^2 / (8 T)`` at mid-span (s its span,
        T its tension now); the far end rides on the body it is made fast to (its tension is the fixed point's)."""
        voyage, t = self.sim.voyage, self.sim.time
        station, faults = voyage.ship, voyage.orders_at(t).faults
        tensions = station.line_tensions(voyage.state(t), faults)
        for index, layer, fast in self.hawsers:
            line = station.moorings.lines[index]
            if f"line:{line.name}" in faults:
                continue
            x, y, z = line.fairlead  # body axes, y to starboard: the pose's y is to port
            fairlead = pose.world(np.array([[x, -y, z]]))[0]
            fixed = (np.array([line.anchor[1], line.anchor[0], line.anchor_height_m]) if fast is None
                     else others[fast[0]].world(fast[1][None])[0])
            span = float(np.linalg.norm(fixed - fairlead))
            layer.replace(hawser_mesh(fairlead, fixed, line.weight_n_m * span**2 / (8.0 * max(tensions[index], 1e3))))
            layer.draw(view, Pose())

    def release(self) -> None:
        if self.synthesis is not None:
            self.synthesis.release()
        for layer in (self.sky, self.cascades, self.foam, self.wake, self.solver_field, self.hull_mask, self.ocean,
                      self.vessel, self.nav_lights, self.rain, self.spray_layer, *self.others, *self.others_lights,
                      *((self.load, self.wire, self.boom) if self.load is not None else ()),
                      *(layer for _, layer, _ in self.hawsers),
                      *((self.helicopter, self.helicopter_lights) if self.helicopter is not None else ())):
            layer.release()


def _lights_of(other) -> str:
    """The lights another body shows: a ship's and an FPSO's as the scenario says, a moored body's, a buoy's and a
    platform's an all-round light (as an anchor light)."""
    return other.nav_lights if other.kind in ("ship", "fpso") else "anchored"
