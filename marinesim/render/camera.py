"""Cameras: where the eye is and where it looks, as OpenGL matrices.

World space is the Earth frame of CONVENTIONS (x east, y north, z up, m). Each camera turns the
vessel's pose into an :class:`Eye`; :meth:`Eye.view_projection` gives the column-major-ready
4 x 4 matrix the shaders take (``clip = M @ [x, y, z, 1]``, OpenGL clip space, depth -1..1).

- :class:`OrbitCamera` circles the vessel's track point (the steady position, so the vessel's
  motions show against a calm frame), its azimuth measured from the stern so it turns with the ship.
- :class:`BridgeCamera` sits on a point on board and moves with all six degrees of freedom: the
  horizon tilts when the ship rolls, as a trainee on the bridge sees it.
- :class:`FreeCamera` flies anywhere (mouse look, WASD).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from marinesim.pose import Pose

NEAR_M = 0.5
FAR_M = 40_000.0
NAKED_EYE_FOV_DEG = 60.0
"""The bridge camera's vertical field of view without magnification (deg)."""
BINOCULAR_POWER = 7.0


def binocular_fov_deg() -> float:
    """The vertical field of view through 7x binoculars: the naked eye's, magnified 7 times (about 9.4 deg)."""
    return math.degrees(2.0 * math.atan(math.tan(math.radians(NAKED_EYE_FOV_DEG) / 2.0) / BINOCULAR_POWER))


@dataclass(frozen=True)
class Eye:
    """A camera placement: position (m, E frame), unit forward and up vectors, vertical field of view."""

    position: np.ndarray
    forward: np.ndarray
    up: np.ndarray
    fov_y_deg: float = 50.0

    def view(self) -> np.ndarray:
        """World -> eye (OpenGL: the eye looks down -z)."""
        f = _unit(self.forward)
        s = _unit(np.cross(f, self.up))
        u = np.cross(s, f)
        out = np.eye(4)
        out[0, :3], out[1, :3], out[2, :3] = s, u, -f
        out[:3, 3] = -out[:3, :3] @ self.position
        return out

    def projection(self, aspect: float) -> np.ndarray:
        """Perspective projection for a viewport of ``aspect`` = width / height."""
        t = 1.0 / math.tan(math.radians(self.fov_y_deg) / 2.0)
        n, f = NEAR_M, FAR_M
        out = np.zeros((4, 4))
        out[0, 0], out[1, 1] = t / aspect, t
        out[2, 2], out[2, 3] = (f + n) / (n - f), 2.0 * f * n / (n - f)
        out[3, 2] = -1.0
        return out

    def view_projection(self, aspect: float) -> np.ndarray:
        return self.projection(aspect) @ self.view()

    def project(self, points: np.ndarray, size: tuple[int, int]) -> np.ndarray:
        """World points (n, 3) -> pixel coordinates (n, 2), origin top-left, and depth w (n,)."""
        width, height = size
        clip = np.c_[points, np.ones(len(points))] @ self.view_projection(width / height).T
        ndc = clip[:, :2] / clip[:, 3:4]
        pixels = np.c_[(ndc[:, 0] + 1.0) * 0.5 * width, (1.0 - ndc[:, 1]) * 0.5 * height]
        return np.c_[pixels, clip[:, 3]]


@dataclass
class OrbitCamera:
    """Around the track point: ``azimuth_deg`` from astern (0 = looking along the bow), elevation, range."""

    azimuth_deg: float = 35.0
    elevation_deg: float = 18.0
    distance_m: float = 400.0

    def eye(self, pose: Pose) -> Eye:
        bearing = pose.heading + math.pi + math.radians(self.azimuth_deg)  # from the target to the eye
        elevation = math.radians(self.elevation_deg)
        offset = self.distance_m * np.array([math.cos(elevation) * math.cos(bearing),
                                             math.cos(elevation) * math.sin(bearing), math.sin(elevation)])
        target = np.array([pose.x, pose.y, 0.0])
        return Eye(target + offset, -offset, np.array([0.0, 0.0, 1.0]))

    def drag(self, dx: float, dy: float) -> None:
        """Mouse drag in pixels turns the view."""
        self.azimuth_deg = (self.azimuth_deg - 0.3 * dx) % 360.0
        self.elevation_deg = float(np.clip(self.elevation_deg + 0.3 * dy, 2.0, 89.0))

    def zoom(self, steps: float) -> None:
        self.distance_m = float(np.clip(self.distance_m * 0.9 ** steps, 5.0, 20_000.0))


@dataclass
class BridgeCamera:
    """On board at ``point`` (body frame, m), looking ahead; ``look_*`` turn the head (deg); the eye's vertical
    field of view ``fov_y_deg`` narrows with the scroll wheel, to a seventh of the naked eye's through the
    ``binoculars`` (7 x 50, the watchkeeper's)."""

    point: tuple[float, float, float]
    look_yaw_deg: float = 0.0
    look_pitch_deg: float = -5.0
    fov_y_deg: float = NAKED_EYE_FOV_DEG
    binoculars: bool = False
    widest_deg: float = NAKED_EYE_FOV_DEG
    """The widest field of view the scroll wheel gives back (deg): a named camera's own, where it is wider."""

    @property
    def magnification(self) -> float:
        """How much larger things look than with the naked eye's field of view."""
        fov = binocular_fov_deg() if self.binoculars else self.fov_y_deg
        return math.tan(math.radians(NAKED_EYE_FOV_DEG) / 2.0) / math.tan(math.radians(fov) / 2.0)

    def eye(self, pose: Pose) -> Eye:
        to_world = pose.matrix()
        yaw, pitch = math.radians(self.look_yaw_deg), math.radians(self.look_pitch_deg)
        look = np.array([math.cos(pitch) * math.cos(yaw), math.cos(pitch) * math.sin(yaw), math.sin(pitch)])
        rotation = to_world[:3, :3]
        fov = binocular_fov_deg() if self.binoculars else self.fov_y_deg
        return Eye(to_world[:3, :3] @ np.asarray(self.point, float) + to_world[:3, 3], rotation @ look,
                   rotation @ np.array([0.0, 0.0, 1.0]), fov_y_deg=fov)

    def drag(self, dx: float, dy: float) -> None:
        """Mouse drag in pixels turns the head, slower the more the view is magnified (the scene follows the
        pointer)."""
        turn = 0.2 / self.magnification
        self.look_yaw_deg = (self.look_yaw_deg - turn * dx + 180.0) % 360.0 - 180.0
        self.look_pitch_deg = float(np.clip(self.look_pitch_deg + turn * dy, -80.0, 80.0))

    def zoom(self, steps: float) -> None:
        """Narrow (or widen) the field of view: the eye stays at the point."""
        self.fov_y_deg = float(np.clip(self.fov_y_deg * 0.9 ** steps, binocular_fov_deg(), self.widest_deg))


@dataclass
class FreeCamera:
    """Free flight: position (m, E frame), yaw (math angle, deg) and pitch (deg)."""

    position: tuple[float, float, float] = (-300.0, -300.0, 60.0)
    yaw_deg: float = 45.0
    pitch_deg: float = -10.0

    def _forward(self) -> np.ndarray:
        yaw, pitch = math.radians(self.yaw_deg), math.radians(self.pitch_deg)
        return np.array([math.cos(pitch) * math.cos(yaw), math.cos(pitch) * math.sin(yaw), math.sin(pitch)])

    def eye(self, pose: Pose) -> Eye:
        return Eye(np.asarray(self.position, float), self._forward(), np.array([0.0, 0.0, 1.0]))

    def drag(self, dx: float, dy: float) -> None:
        self.yaw_deg = (self.yaw_deg - 0.2 * dx) % 360.0
        self.pitch_deg = float(np.clip(self.pitch_deg + 0.2 * dy, -89.0, 89.0))

    def zoom(self, steps: float) -> None:
        self.move(forward=10.0 * steps)

    def move(self, forward: float = 0.0, right: float = 0.0, up: float = 0.0) -> None:
        """Fly ``forward`` along the view, ``right`` sideways and ``up`` (m)."""
        f = self._forward()
        s = _unit(np.cross(f, [0.0, 0.0, 1.0]))
        p = np.asarray(self.position, float) + forward * f + right * s + np.array([0.0, 0.0, up])
        self.position = (float(p[0]), float(p[1]), max(float(p[2]), 1.0))


Camera = OrbitCamera | BridgeCamera | FreeCamera


def _unit(v: np.ndarray) -> np.ndarray:
    v = np.asarray(v, dtype=float)
    return v / np.linalg.norm(v)
