"""Headless renders through EGL: a video of a scenario (with its motion CSV beside it) or a screenshot.

Frames are drawn by the same :class:`~marinesim.render.scene.Scene` the window uses, into an
offscreen framebuffer, at fixed simulated times ``k / fps``, with the ocean transformed by numpy.fft
(:class:`~marinesim.render.renderer.RenderOptions` ``reproducible``) and no measured times in the
HUD: the same scenario and seed give the same frames, whatever the FFTW plans in the cache. Videos
are H.264 MP4 through the ffmpeg that ``imageio-ffmpeg`` ships, written to a temporary file and
renamed when complete. The CSV beside a video is ``marinesim export`` of the
scenario over the video's length (same columns, same rows, same numbers).
"""

from __future__ import annotations

from dataclasses import dataclass, replace
from pathlib import Path

import numpy as np

from marinesim.atomic import atomic_path
from marinesim.errors import ParameterError
from marinesim.gl import standalone_context
from marinesim.render.camera import FAR_M, NEAR_M
from marinesim.render.layers.foam import FOAM_TAU_S
from marinesim.render.renderer import RenderOptions
from marinesim.progress import task
from marinesim.render.scene import Scene, solver_wanted
from marinesim.scenario import Scenario
from marinesim.session.export import export_motions

MAX_PIXELS = 7680 * 4320
WARMUP_STEP_S = 0.25
"""Foam has memory: a screenshot at time T first steps through the last 3 foam lifetimes at this step."""


@dataclass(frozen=True)
class VideoResult:
    video: Path
    motions: Path | None  # None for a scenario without a vessel
    frames: int
    fps: float
    solver: bool
    gpu_cascades: bool  # the ocean's waves synthesised on the GPU (else on the CPU)


def parse_size(text: str) -> tuple[int, int]:
    """``"1280x720"`` -> (1280, 720); even sizes (the video's colour subsampling needs them)."""
    try:
        width, height = (int(part) for part in text.lower().split("x"))
    except ValueError:
        raise ParameterError(f"--size must be WIDTHxHEIGHT in pixels, e.g. 1280x720, got {text!r}") from None
    if width < 16 or height < 16 or width * height > MAX_PIXELS or width % 2 or height % 2:
        raise ParameterError(f"--size must be even numbers of pixels, at least 16 and at most 7680x4320, got {text!r}")
    return width, height


class Offscreen:
    """An EGL context with a scene and a framebuffer of ``size`` to draw it into."""

    def __init__(self, scenario: Scenario, size: tuple[int, int], camera: str = "orbit", solver: str = "auto",
                 options: RenderOptions = RenderOptions()) -> None:
        self.ctx = standalone_context()
        self.size = size
        self.scene = Scene(self.ctx, scenario, camera, replace(options, solver=solver_wanted(self.ctx, solver)))
        self._fbo = self._framebuffer(size)

    def _framebuffer(self, size: tuple[int, int]):
        return self.ctx.framebuffer(color_attachments=[self.ctx.renderbuffer(size)],
                                    depth_attachment=self.ctx.depth_renderbuffer(size))

    def resize(self, size: tuple[int, int]) -> None:
        """Draw at ``size`` (w, h) px from now on (a window being resized)."""
        old, self._fbo, self.size = self._fbo, self._framebuffer(size), size
        self._fbo.use()  # never release the bound framebuffer
        old.release()

    def bind(self) -> None:
        """Make the offscreen framebuffer the target of the next draw."""
        self._fbo.use()

    @property
    def solver_on(self) -> bool:
        return self.scene.sim.solver is not None

    def frame(self, hud: bool = True) -> np.ndarray:
        """The current frame as (h, w, 3) uint8 RGB, top row first."""
        self.bind()
        self.scene.draw(self.size, hud)
        data = self._fbo.read(components=3, alignment=1)
        return np.frombuffer(data, np.uint8).reshape(self.size[1], self.size[0], 3)[::-1].copy()

    def depth_m(self) -> np.ndarray:
        """The last frame's distance from the eye's plane to what each pixel shows (m; (h, w), top row first):
        the depth buffer made linear again (:data:`~marinesim.render.camera.NEAR_M`, ``FAR_M``)."""
        data = self._fbo.read(components=1, attachment=-1, dtype="f4", alignment=1)
        depth = np.frombuffer(data, np.float32).reshape(self.size[1], self.size[0])[::-1].astype(float)
        ndc = 2.0 * depth - 1.0
        return 2.0 * FAR_M * NEAR_M / (FAR_M + NEAR_M - ndc * (FAR_M - NEAR_M))

    def go_to(self, t: float) -> None:
        """Advance to ``t`` (s) stepping the last three foam lifetimes, so foam and charts are as in a live run."""
        sim = self.scene.sim
        warm_from = max(t - 3.0 * FOAM_TAU_S, sim.time)
        if warm_from > sim.time:
            self.scene.exercise.seek(warm_from)
        self.scene.prefill_history()
        self.scene.renderer.update()
        while sim.time < t - 1e-9:
            self.scene.step(min(WARMUP_STEP_S, t - sim.time))

    def release(self) -> None:
        self._fbo.release()
        self.scene.release()
        self.ctx.release()

    def __enter__(self) -> Offscreen:
        return self

    def __exit__(self, *exc) -> None:
        self.release()


def screenshot(scenario: Scenario, out: Path, at_s: float = 0.0, size: tuple[int, int] = (1280, 720),
               camera: str = "orbit", solver: str = "auto", options: RenderOptions = RenderOptions()) -> Path:
    """Write a PNG of the scenario at ``at_s`` seconds (atomically)."""
    from PIL import Image

    if not 0.0 <= at_s <= scenario.run.duration_s:
        raise ParameterError(f"--time must be within the run, 0..{scenario.run.duration_s:g} s, got {at_s!r}")
    with Offscreen(scenario, size, camera, solver, replace(options, reproducible=True)) as view:
        view.go_to(at_s)
        image = view.frame()
    with atomic_path(out) as temp:
        Image.fromarray(image).save(temp, format="PNG")
    return out


def render_video(scenario: Scenario, out: Path, seconds: float = 20.0, size: tuple[int, int] = (1280, 720),
                 fps: float = 30.0, camera: str = "orbit", solver: str = "auto",
                 options: RenderOptions = RenderOptions(), motions: bool = True) -> VideoResult:
    """Write ``out`` (MP4, ``round(seconds * fps)`` frames at t = k / fps) and, with a vessel and
    ``motions``, the motions over ``[0, seconds]`` at the scenario's dt to ``out`` with the suffix ``.csv``."""
    import imageio_ffmpeg

    if not (0.0 < seconds <= scenario.run.duration_s):
        raise ParameterError(f"--seconds must be within the run, (0, {scenario.run.duration_s:g}] s, got {seconds!r}")
    if not (1.0 <= fps <= 240.0):
        raise ParameterError(f"--fps must be within 1..240, got {fps!r}")
    frames = int(round(seconds * fps))
    table = None
    with Offscreen(scenario, size, camera, solver, replace(options, reproducible=True)) as view, \
            atomic_path(out) as temp:
        writer = imageio_ffmpeg.write_frames(str(temp), size, fps=fps, codec="libx264", quality=7,
                                             macro_block_size=2, ffmpeg_log_level="error")
        writer.send(None)
        try:
            view.go_to(0.0)
            with task(f"render {out.name}", frames, "frame") as bar:
                for k in range(frames):
                    if k:
                        view.scene.step(k / fps - view.scene.sim.time)
                    writer.send(view.frame())
                    bar.update(1)
        finally:
            writer.close()
        solver_on, gpu_cascades = view.solver_on, view.scene.renderer.synthesis is not None
        if motions and scenario.vessel is not None:
            table = export_motions(view.scene.sim.assembly, out.with_suffix(".csv"), duration_s=seconds).table
    return VideoResult(out, table, frames, fps, solver_on, gpu_cascades)
