"""The window's frame clock: the wall time between drawn frames and the real-time factor, as the HUD shows them.

Both are measured, not asked for: the frame time is the wall time between successive draws and the
real-time factor is the simulated time that passed over the wall time it took, each over the last
:data:`WINDOW_S` of wall time and at least :data:`MIN_DRAWS` draws (a window may draw twice between two steps
of the run: over those two alone the run would seem stopped). A frame advances the run by at most
``controls.MAX_FRAME_S``, so a window drawing 3 frames/s runs at a quarter of real time whatever the ``time x1``
asked for; this is the line that says so. Headless renders keep no clock: nothing measured goes into their pictures.
"""

from __future__ import annotations

from collections import deque

WINDOW_S = 1.0
"""The figures are averages over this much wall time (s)..."""
MIN_DRAWS = 6
"""... and over this many draws at least (slow frames: over a second each)."""


class FrameClock:
    """Draws noted at wall times (s, any monotonic clock) with the simulation's time (s) at each."""

    def __init__(self, window_s: float = WINDOW_S) -> None:
        self.window_s = window_s
        self._draws: deque[tuple[float, float]] = deque()

    def draw(self, wall_s: float, sim_s: float) -> None:
        """Note a frame drawn at ``wall_s`` showing the simulation at ``sim_s``."""
        self._draws.append((wall_s, sim_s))
        while len(self._draws) > MIN_DRAWS and wall_s - self._draws[1][0] >= self.window_s:
            self._draws.popleft()

    def restart(self) -> None:
        """Forget the draws so far (a new scene, a seek: the simulated time jumped)."""
        self._draws.clear()

    @property
    def frame_s(self) -> float | None:
        """Mean wall time between the draws of the window (s); None before two draws."""
        if len(self._draws) < 2:
            return None
        return (self._draws[-1][0] - self._draws[0][0]) / (len(self._draws) - 1)

    @property
    def real_time_factor(self) -> float | None:
        """Simulated over wall time across the window; None before two draws."""
        if len(self._draws) < 2:
            return None
        wall = self._draws[-1][0] - self._draws[0][0]
        return (self._draws[-1][1] - self._draws[0][1]) / wall if wall > 0 else None

    def line(self) -> str:
        """The HUD's clock line: frame time, frames/s and real-time factor, or that they are being measured."""
        frame, factor = self.frame_s, self.real_time_factor
        if frame is None or factor is None or frame <= 0:
            return "frame --"
        return f"frame {1000 * frame:5.1f} ms ({1 / frame:4.0f} frames/s)   real time x{factor:.2f}"
