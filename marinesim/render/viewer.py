"""The interactive viewer: a pyglet window with a moderngl context drawing a :class:`~marinesim.render.scene.Scene`.

:func:`open_window` raises :class:`NoDisplay` when there is no display to open a window on; the
``run`` command then renders headless instead (:mod:`marinesim.render.offscreen`).
"""

from __future__ import annotations

import os
import sys
import time

from marinesim.errors import MarinesimError
from marinesim.gl import GL_VERSION, GraphicsError
from marinesim.render.controls import HELP, Controls
from marinesim.render.renderer import RenderOptions
from marinesim.render.scene import Scene, solver_wanted
from marinesim.scenario import Scenario


class NoDisplay(MarinesimError):
    """No display to open a window on (no $DISPLAY / $WAYLAND_DISPLAY, or the window failed)."""


def open_window(size: tuple[int, int], caption: str, headless: bool = False):
    """A resizable pyglet window with an OpenGL 4.3 core context; ``headless`` uses pyglet's EGL
    headless mode (for tests). Raises :class:`NoDisplay` when no window can be made."""
    import pyglet

    pyglet.options["debug_gl"] = False  # moderngl draws; pyglet's per-call error checks only slow it
    if headless:
        pyglet.options["headless"] = True
    elif sys.platform.startswith("linux") and not (os.environ.get("DISPLAY") or os.environ.get("WAYLAND_DISPLAY")):
        raise NoDisplay("no display ($DISPLAY and $WAYLAND_DISPLAY are unset)")
    major, minor = GL_VERSION // 100, GL_VERSION // 10 % 10
    config = pyglet.gl.Config(major_version=major, minor_version=minor, forward_compatible=True,
                              depth_size=24, double_buffer=True)
    try:
        return pyglet.window.Window(*size, caption=caption, resizable=True, config=config, vsync=True)
    except Exception as error:  # noqa: BLE001 (pyglet raises display and context errors of several kinds)
        raise NoDisplay(f"no window could be opened ({error})") from None


class Viewer:
    """A window, its scene and its controls; :meth:`tick` is one frame (pyglet calls it)."""

    def __init__(self, scenario: Scenario, camera: str = "orbit", solver: str = "auto",
                 size: tuple[int, int] = (1280, 720), headless: bool = False, options: RenderOptions = RenderOptions()):
        from dataclasses import replace

        import moderngl
        import pyglet

        self.window = open_window(size, f"marinesim - {scenario.name}", headless)
        try:
            self.window.switch_to()
            self.ctx = moderngl.create_context(require=GL_VERSION)
        except Exception as error:  # noqa: BLE001
            self.window.close()
            raise GraphicsError(f"the window has no OpenGL {GL_VERSION / 100:.1f} context ({error})") from None
        options = replace(options, solver=solver_wanted(self.ctx, solver))
        self.scene = Scene(self.ctx, scenario, camera, options, log=print)
        self.controls = Controls(self.scene)
        self.held: set[str] = set()
        self._last = time.perf_counter()
        key = pyglet.window.key

        @self.window.event
        def on_draw() -> None:
            self.draw()

        @self.window.event
        def on_key_press(symbol: int, modifiers: int) -> bool | None:
            name = key.symbol_string(symbol)
            if name == "ESCAPE":
                self.close()
                return pyglet.event.EVENT_HANDLED
            self.held.add(name)
            self.controls.press(name)
            return None

        @self.window.event
        def on_key_release(symbol: int, modifiers: int) -> None:
            self.held.discard(key.symbol_string(symbol))

        @self.window.event
        def on_mouse_drag(x: int, y: int, dx: int, dy: int, buttons: int, modifiers: int) -> None:
            self.scene.camera.drag(dx, dy)

        @self.window.event
        def on_mouse_scroll(x: int, y: int, scroll_x: float, scroll_y: float) -> None:
            self.scene.camera.zoom(scroll_y)

        @self.window.event
        def on_close() -> None:
            self.close()

    def tick(self, dt: float | None = None) -> None:
        """Advance by the wall time since the last tick (or ``dt`` s) and redraw."""
        now = time.perf_counter()
        wall = now - self._last if dt is None else dt
        self._last = now
        self.controls.frame(wall, self.held)
        self.scene.frame_seconds = wall

    def draw(self) -> None:
        self.ctx.screen.use()
        size = self.window.get_framebuffer_size()
        self.ctx.screen.viewport = (0, 0, *size)
        self.scene.draw(size, help_lines=HELP if self.controls.show_help else None)

    def run(self) -> None:
        import pyglet

        pyglet.clock.schedule_interval(self._on_clock, 1.0 / 60.0)
        pyglet.app.run()

    def _on_clock(self, dt: float) -> None:
        self.tick()

    def close(self) -> None:
        import pyglet

        if self.controls.recorder is not None:
            self.controls.toggle_recording()
            print(self.controls.message)
        pyglet.clock.unschedule(self._on_clock)
        self.scene.release()
        _ = self.ctx.error  # reading clears a pending GL error, which pyglet's close would raise
        self.window.close()
        pyglet.app.exit()
