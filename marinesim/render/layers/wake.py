"""The Kelvin wakes on the water: one texture per computed wake (:func:`~marinesim.render.wake_look.wake_appearance`)
and up to two drawn at once with their blend weights (two while a speed change blends)."""

from __future__ import annotations

import moderngl

from marinesim.render.layers.base import blank_texture
from marinesim.render.wake_look import wake_appearance
from marinesim.session.timeline import Simulation
from marinesim.wake.compute import Wake

SLOTS = 2
"""Wakes the ocean's program blends (``u_wake0``, ``u_wake1``)."""

Rect = tuple[float, float, float, float]


def wake_rect(wake: Wake) -> Rect:
    """The rect of a wake's texture: x, y of the grid's outer corner and 1 / width, 1 / height (m, vessel frame)."""
    spacing = float(wake.x[1] - wake.x[0])
    ny, nx = wake.elevation.shape
    x0, y0 = float(wake.x[0]) - 0.5 * spacing, float(wake.y[0]) - 0.5 * spacing
    return x0, y0, 1.0 / (spacing * nx), 1.0 / (spacing * ny)


class WakeLayer:
    """The wakes ``sim`` draws now (none unless ``shown``), made into textures once per wake."""

    units = SLOTS

    def __init__(self, ctx: moderngl.Context, sim: Simulation, shown: bool = True) -> None:
        self.ctx, self.sim, self.shown = ctx, sim, shown
        self._textures: dict[int, tuple[moderngl.Texture, Rect]] = {}
        self._blank = blank_texture(ctx)

    def _texture(self, wake: Wake) -> tuple[moderngl.Texture, Rect]:
        key = id(wake)
        if key not in self._textures:
            data = wake_appearance(wake)
            texture = self.ctx.texture((data.shape[1], data.shape[0]), 4, data.tobytes(), dtype="f4")
            texture.repeat_x = texture.repeat_y = False
            self._textures[key] = texture, wake_rect(wake)
        return self._textures[key]

    def bind(self, unit: int) -> dict[str, object]:
        wakes = self.sim.wakes() if self.shown else []
        values: dict[str, object] = {}
        weights = [0.0] * SLOTS
        for slot in range(SLOTS):
            texture, rect = self._blank, (0.0, 0.0, 1.0, 1.0)
            if slot < len(wakes):
                wake, weights[slot] = wakes[slot]
                texture, rect = self._texture(wake)
            texture.use(unit + slot)
            values[f"u_wake{slot}"] = unit + slot
            values[f"u_wake_rect{slot}"] = rect
        values["u_wake_weight"] = tuple(weights)
        return values

    def release(self) -> None:
        for texture, _ in self._textures.values():
            texture.release()
        self._blank.release()
