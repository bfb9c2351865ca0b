"""The interactive viewer: a pyglet window with a moderngl context drawing a :class:`~marinesim.render.scene.Scene`.

:func:`open_window` raises :class:`NoDisplay` when there is no display to open a window on; the
``run`` command then renders headless instead (:mod:`marinesim.render.offscreen`). A live session
writes its log (:mod:`marinesim.session.log`) when the window closes; a replay follows a log, with
a time slider.
"""

from __future__ import annotations

import os
import sys
import time
from pathlib import Path

from marinesim.errors import MarinesimError
from marinesim.gl import GL_VERSION, GraphicsError
from marinesim.render.clock import FrameClock
from marinesim.render.controls import Controls
from marinesim.render.renderer import RenderOptions
from marinesim.render.scene import Scene, solver_wanted
from marinesim.scenario import Scenario
from marinesim.session.log import SessionLog, write_log
from marinesim.session.replay import Replay

ALARM_TONE = (0.35, 880.0)
"""The audible cue of a new alarm: seconds, Hz (where the machine has audio)."""


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
    """A window, its scene and its controls; :meth:`tick` is one frame (pyglet calls it). A live session's
    log goes to ``log_path`` when the window closes; with ``replay`` the scene follows that log instead."""

    def __init__(self, scenario: Scenario, camera: str = "orbit", solver: str = "auto",
                 size: tuple[int, int] = (1280, 720), headless: bool = False, options: RenderOptions = RenderOptions(),
                 log_path: Path | None = None, replay: SessionLog | None = None):
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
        self._scene_args = (self.ctx, scenario, camera, options)
        self.log_path, self.replay_log, self.headless = log_path, replay, headless
        self.scene = self._new_scene()
        self.controls = Controls(self.scene, restart=self._restart, on_quit=self.close)
        self.held: set[str] = set()
        self._last = time.perf_counter()
        self._alarms_heard = 0
        key = pyglet.window.key

        @self.window.event
        def on_draw() -> None:
            self.draw()

        @self.window.event
        def on_key_press(symbol: int, modifiers: int) -> bool | None:
            name = key.symbol_string(symbol)
            self.held.add(name)
            self.controls.press(name)  # every key as the keymap says, ESC (quit) too
            return pyglet.event.EVENT_HANDLED if name == "ESCAPE" else None  # not pyglet's own ESC

        @self.window.event
        def on_text(text: str) -> None:
            self.controls.text(text)

        @self.window.event
        def on_mouse_press(x: int, y: int, button: int, modifiers: int) -> None:
            self.click(x, y)

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

    def _new_scene(self) -> Scene:
        scene = Scene(*self._scene_args, log=print)
        scene.clock = FrameClock()
        scene.interactive = True
        if self.replay_log is not None:
            scene.replay = Replay(scene.exercise, self.replay_log.actions(), self.replay_log)
        return scene

    def _restart(self, t: float) -> None:
        """A replay from the beginning, moved on to ``t`` (s): a seek back."""
        old, self.scene = self.scene, self._new_scene()
        old.release()
        self.controls.scene = self.scene
        self.controls.seek(t)

    def click(self, x: int, y: int) -> None:
        """A click at window point (x, y) (pyglet's: from the bottom-left): on a replay's slider, seek there."""
        if self.scene.slider is None:
            return
        size = self.window.get_framebuffer_size()
        scale = size[0] / max(self.window.width, 1)
        px, py = x * scale, size[1] - y * scale
        left, top, width, height = self.scene.hud.slider_rect(size, bool(self.scene.charts()))
        if left - 4 <= px <= left + width + 4 and top - 8 <= py <= top + height + 8:
            self.controls.seek((px - left) / width * self.replay_log.end_s)

    def tick(self, dt: float | None = None) -> None:
        """Advance by the wall time since the last tick (or ``dt`` s) and redraw; a new alarm sounds."""
        now = time.perf_counter()
        wall = now - self._last if dt is None else dt
        self._last = now
        self.controls.frame(wall, self.held)
        alarms = len(self.scene.exercise.alarms)
        if alarms > self._alarms_heard and self.scene.replay is None:
            self._sound()
        self._alarms_heard = alarms

    def _sound(self) -> None:
        """The alarm tone, where the machine has audio (a headless window has none)."""
        if self.headless:
            return
        try:
            from pyglet.media.synthesis import Sine

            Sine(*ALARM_TONE).play()
        except Exception:  # noqa: BLE001 (no audio driver, no device: the alarm is still shown)
            pass

    def draw(self, wall_s: float | None = None) -> None:
        """Draw the frame; the clock notes it at ``wall_s`` (s; default now)."""
        self.scene.clock.draw(time.perf_counter() if wall_s is None else wall_s, self.scene.sim.time)
        self.ctx.screen.use()
        size = self.window.get_framebuffer_size()
        self.ctx.screen.viewport = (0, 0, *size)
        self.scene.draw(size, help_lines=self.controls.help_lines() if self.controls.show_help else None)

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
        if self.replay_log is None and self.log_path is not None:
            self.scene.exercise.note("end")
            try:
                print(f"session log: {write_log(self.log_path, self.scene.exercise)}")
            except MarinesimError as error:  # a full disk: say so, close anyway
                print(f"the session log could not be written: {error}")
            self.log_path = None
        pyglet.clock.unschedule(self._on_clock)
        self.scene.release()
        _ = self.ctx.error  # reading clears a pending GL error, which pyglet's close would raise
        self.window.close()
        pyglet.app.exit()
