"""A helicopter's approach to a ship's helideck, kinematic, on the offshore landing profile.

The profile (EASA/UK Air Ops GM1 CAT.POL.H.310(c) & CAT.POL.H.325(c), (k) standard and (l) offset landing profiles;
the offshore final approach as flown on the S-92 and AW139):

- **approach**: into wind (the final approach track is the direction the wind comes from), on a steady glide path
  of ``glide_angle_deg`` (default 6 deg) from ``start_range_nm`` (default 0.75 nm, the decision range of the
  offshore airborne radar approach, about 500 ft above the deck on a 6 deg path) at ``approach_speed_kn`` closing
  speed over the deck (default 60 kn), decelerating at :data:`DECELERATION_M_S2` (0.5 m/s^2: 60 kn to the hover over
  the last half mile) on the same path into
- **hover**: the offset profile's hover, about 90 deg off the landing point: alongside the deck, ``hover_offset_m``
  (default 20 m: half an S-92's D-value of 20.9 m plus half its 17.2 m rotor and a metre, so the rotor tips clear the
  deck edge) to the side of the deck's centre, square to the approach track, ``hover_height_ft`` above the deck
  (default 30 ft, the usual offshore figure; the GM leaves it to the type). The deck is on the commander's side
  (``deck_side``, default right: the commander's seat in the S-92 and AW139). It holds there until the deck is GREEN,
- **crossing**: sideways over the deck edge to over the deck's centre at the hover height in ``crossing_s``,
- **landing**: settling onto the deck in ``settling_s``, the descent blended into the deck's own (wave-moved) height,
- **on_deck**: carried by the deck, at its centre and its height, turning with it.
- **wave_off**: the go-around, from wherever it is ordered before touchdown: climbing at :data:`GO_AROUND_CLIMB_FT_MIN`
  (collective up over :data:`GO_AROUND_COLLECTIVE_S`) and accelerating to :data:`GO_AROUND_SPEED_KN` over
  :data:`GO_AROUND_ACCELERATION_S` on a track turned :data:`GO_AROUND_TURN_DEG` from the wind away from the deck.

Decisions act from their time, like orders: :meth:`HelicopterApproach.permit` (deck GREEN), :meth:`hold` (deck RED),
:meth:`wave_off`. The deck is RED until first permitted. A RED deck holds the helicopter in the hover; once the crossing
has begun a RED deck is a wave-off (the helideck status lights' flashing red: do not land, CAP 437). A wave-off is
final; decisions after touchdown change nothing. At equal times decisions act in the order given.

Frames (docs/CONVENTIONS.md): E frame, x east, y north, z up (m). The sampled point is the bottom of the helicopter's
landing gear (the origin of :mod:`marinesim.render.aircraft`'s mesh), so on deck its height is the deck's. The
approach's speed and glide angle are relative to the deck's mean track (the closing speed and the path the pilot flies
to a moving deck; over the ground add the deck's velocity). Every blend is a smoothstep ``3 s^2 - 2 s^3`` (or its
integral) or the constant deceleration: position and velocity are continuous from the start to touchdown and into the
wave-off, and the state at a time depends on the decisions alone, not on what was sampled before.
"""

from __future__ import annotations

import math
from collections.abc import Callable

import numpy as np

from marinesim.angles import compass_to_math
from marinesim.constants import KNOT, NAUTICAL_MILE
from marinesim.errors import ParameterError, require_finite, require_positive, require_within
from marinesim.sea.ocean import smoothstep

FOOT_M = 0.3048
PHASES = ("approach", "hover", "crossing", "landing", "on_deck", "wave_off")
"""The phases in the order a landing goes through them (a wave-off may follow any before on_deck)."""
DECELERATION_M_S2 = 0.5
"""The deceleration on the glide path to the hover (m/s^2): 60 kn to the hover in the last half mile."""
GO_AROUND_SPEED_KN = 60.0
"""The go-around's ground speed (kn): an assumption, between a medium twin's take-off safety speed and its Vy."""
GO_AROUND_CLIMB_FT_MIN = 1000.0
"""The go-around's rate of climb (ft/min)."""
GO_AROUND_TURN_DEG = 30.0
"""The go-around's track off the wind, away from the deck (deg)."""
GO_AROUND_COLLECTIVE_S = 4.0
"""Time to the go-around's rate of climb (s): collective raised."""
GO_AROUND_ACCELERATION_S = 20.0
"""Time to the go-around's speed (s): about 0.24 g at its peak from a hover."""
DECK_STEP_S = 1e-3
"""The step of the central differences that give the deck's and the profile's velocity at a wave-off (s)."""

DeckTrack = Callable[[np.ndarray], tuple[np.ndarray, np.ndarray]]
DeckHeight = Callable[[np.ndarray], np.ndarray]


def blend(s: np.ndarray) -> np.ndarray:
    """The sea's :func:`~marinesim.sea.ocean.smoothstep` of ``s`` clipped to 0..1: from 0 to 1 with zero slope at both
    ends."""
    return smoothstep(np.clip(s, 0.0, 1.0))


def smoothstep_integral(s: np.ndarray) -> np.ndarray:
    """The integral of :func:`blend` from 0 to ``s`` (0 below 0; ``s - 1/2`` above 1)."""
    c = np.clip(s, 0.0, 1.0)
    return c**3 - 0.5 * c**4 + np.maximum(s - 1.0, 0.0)


class HelicopterApproach:
    """A helicopter approaching, landing on or waving off from the helideck that ``deck`` carries.

    ``deck(times (n,)) -> (positions (n, 3), heading (n,))``: the deck's centre (E frame, m) as the ship's mean track
    carries it, no wave motion, and the ship's heading (compass deg); ``deck_z(times (n,)) -> (n,)``: the deck centre's
    actual (wave-moved) height (m), used for the landing's settling, on deck and for the height above the deck;
    ``wind_from_deg``: the wind's direction (compass deg, coming from). The profile's parameters are as in the module's
    docstring; the approach begins at ``start_s`` (s) at ``start_range_nm`` from the hover point, and before it the
    helicopter is on the same path further out."""

    def __init__(self, deck: DeckTrack, deck_z: DeckHeight, wind_from_deg: float, *,
                 approach_speed_kn: float = 60.0, glide_angle_deg: float = 6.0, start_range_nm: float = 0.75,
                 hover_height_ft: float = 30.0, hover_offset_m: float = 20.0, crossing_s: float = 12.0,
                 settling_s: float = 10.0, deck_side: str = "right", start_s: float = 0.0) -> None:
        if not callable(deck) or not callable(deck_z):
            raise ParameterError("deck and deck_z must be callables of times (n,)")
        if deck_side not in ("left", "right"):
            raise ParameterError(f"deck_side must be 'left' or 'right', got {deck_side!r}")
        self.deck, self.deck_z = deck, deck_z
        self.wind_from_deg = require_finite("wind_from_deg", wind_from_deg) % 360.0
        self.speed = require_positive("approach_speed_kn", approach_speed_kn) * KNOT
        self.glide = math.radians(require_within("glide_angle_deg", glide_angle_deg, 2.0, 15.0, "deg"))
        self.start_range = require_positive("start_range_nm", start_range_nm) * NAUTICAL_MILE
        self.hover_height = require_positive("hover_height_ft", hover_height_ft) * FOOT_M
        self.hover_offset = require_positive("hover_offset_m", hover_offset_m)
        self.crossing_s = require_positive("crossing_s", crossing_s)
        self.settling_s = require_positive("settling_s", settling_s)
        self.start_s = require_finite("start_s", start_s)
        self.braking = self.speed**2 / (2.0 * DECELERATION_M_S2)
        """The distance over which the approach slows to the hover (m)."""
        if self.start_range <= self.braking:
            raise ParameterError(f"start_range_nm must be > {self.braking / NAUTICAL_MILE:.3g} nm (the distance to "
                                 f"slow from {approach_speed_kn:g} kn to the hover), got {start_range_nm!r}")
        track = compass_to_math(self.wind_from_deg)
        self.ahead = np.array([math.cos(track), math.sin(track)])
        """Unit vector into wind (E frame, x and y): the final approach track."""
        self.side = 1.0 if deck_side == "right" else -1.0
        """+1: the hover point is to the left of the deck (the deck on the right), the crossing to the right."""
        left = np.array([-self.ahead[1], self.ahead[0]])
        self.offset = self.side * self.hover_offset * left
        """The hover point from the deck's centre (E frame, x and y, m)."""
        self.arrival_s = self.start_s + (self.start_range - self.braking) / self.speed + 2.0 * self.braking / self.speed
        """When the approach reaches the hover (s)."""
        self._decisions: list[tuple[float, int, str]] = []

    # -- decisions --------------------------------------------------------------------------------

    def permit(self, t: float) -> None:
        """Deck GREEN from ``t`` (s): land when at the hover."""
        self._decide(t, "permit")

    def hold(self, t: float) -> None:
        """Deck RED from ``t`` (s): hold in the hover (a wave-off once the crossing has begun)."""
        self._decide(t, "hold")

    def wave_off(self, t: float) -> None:
        """Abort at ``t`` (s): the go-around, unless already on deck."""
        self._decide(t, "wave_off")

    def _decide(self, t: float, kind: str) -> None:
        t = require_finite(f"{kind} time", t)
        self._decisions.append((t, len(self._decisions), kind))

    def plan(self) -> tuple[float | None, float | None]:
        """(when the crossing starts, when the wave-off is flown) from the decisions given (s; None: never)."""
        green_since, crossing, wave = None, None, None
        for t, _, kind in sorted(self._decisions):
            if crossing is None and green_since is not None and max(self.arrival_s, green_since) < t:
                crossing = max(self.arrival_s, green_since)
            touchdown = math.inf if crossing is None else crossing + self.crossing_s + self.settling_s
            if t >= touchdown:
                break
            if kind == "wave_off" or (kind == "hold" and crossing is not None):
                wave = t
                break
            if kind == "hold":
                green_since = None
            elif green_since is None:
                green_since = t
        if wave is None and crossing is None and green_since is not None:
            crossing = max(self.arrival_s, green_since)
        return crossing, wave

    # -- sampling ---------------------------------------------------------------------------------

    def sample(self, times: np.ndarray) -> dict[str, np.ndarray]:
        """The helicopter at ``times`` (n,) s: ``x``, ``y``, ``z`` (E frame, m; the landing gear's bottom),
        ``heading_deg`` (compass), ``phase`` (one of :data:`PHASES`), ``height_above_deck_m`` (above the deck's
        actual height)."""
        t = np.atleast_1d(np.asarray(times, float))
        if t.ndim != 1 or not np.all(np.isfinite(t)):
            raise ParameterError("times must be a 1-D array of finite numbers (s)")
        crossing, wave = self.plan()
        centre, heading = self._deck(t)
        actual = self._deck_height(t)
        position, phase = self._flown(t, centre, actual, crossing)
        compass = np.full(len(t), self.wind_from_deg)
        if crossing is not None:
            touchdown = crossing + self.crossing_s + self.settling_s
            on = (phase == PHASES.index("on_deck"))
            if np.any(on):
                _, at_touchdown = self._deck(np.array([touchdown]))
                compass[on] = self.wind_from_deg + (heading[on] - at_touchdown[0])
        if wave is not None:
            late = t >= wave
            if np.any(late):
                position[late], compass[late] = self._go_around(t[late], wave, crossing)
                phase[late] = PHASES.index("wave_off")
        return {"x": position[:, 0], "y": position[:, 1], "z": position[:, 2], "heading_deg": compass % 360.0,
                "phase": np.array(PHASES)[phase], "height_above_deck_m": position[:, 2] - actual}

    def _deck(self, t: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """The deck's centre (n, 3) and heading (n,) at ``t``, checked."""
        centre, heading = self.deck(t)
        centre, heading = np.asarray(centre, float), np.asarray(heading, float)
        if centre.shape != (len(t), 3) or heading.shape != (len(t),):
            raise ParameterError(f"deck(times) must give positions ({len(t)}, 3) and heading ({len(t)},), got "
                                 f"{centre.shape} and {heading.shape}")
        if not (np.all(np.isfinite(centre)) and np.all(np.isfinite(heading))):
            raise ParameterError("deck(times) must give finite positions (m) and heading (deg)")
        return centre, heading

    def _deck_height(self, t: np.ndarray) -> np.ndarray:
        """The deck's actual height (n,) at ``t``, checked."""
        z = np.asarray(self.deck_z(t), float)
        if z.shape != (len(t),) or not np.all(np.isfinite(z)):
            raise ParameterError(f"deck_z(times) must give ({len(t)},) finite heights (m), got shape {z.shape}")
        return z

    def _flown(self, t: np.ndarray, centre: np.ndarray, actual: np.ndarray, crossing: float | None
               ) -> tuple[np.ndarray, np.ndarray]:
        """Positions (n, 3) and phase indices (n,) at ``t`` without a wave-off, the deck's centre ``centre`` (n, 3)
        and its actual height ``actual`` (n,) there; ``crossing``: when the crossing starts (None: never)."""
        # distance still to go to the hover point along the path (m): steady, then slowing at a constant rate
        steady_end = self.start_s + (self.start_range - self.braking) / self.speed
        slowing = np.clip(1.0 - (t - steady_end) * self.speed / (2.0 * self.braking), 0.0, 1.0)
        remaining = np.where(t < steady_end, self.braking + self.speed * (steady_end - t), self.braking * slowing**2)
        position = centre.copy()
        position[:, :2] += self.offset - remaining[:, None] * self.ahead
        position[:, 2] += self.hover_height + remaining * math.tan(self.glide)
        phase = np.where(t < self.arrival_s, PHASES.index("approach"), PHASES.index("hover"))
        if crossing is None:
            return position, phase
        across = blend((t - crossing) / self.crossing_s)
        settle_start = crossing + self.crossing_s
        down = blend((t - settle_start) / self.settling_s)
        moving = t >= crossing
        position[moving, :2] = centre[moving, :2] + (1.0 - across[moving, None]) * self.offset
        above = centre[:, 2] + self.hover_height
        position[moving, 2] = (above + down * (actual - above))[moving]
        phase[moving] = PHASES.index("crossing")
        phase[t >= settle_start] = PHASES.index("landing")
        on_deck = t >= settle_start + self.settling_s
        phase[on_deck] = PHASES.index("on_deck")
        position[on_deck] = np.c_[centre[on_deck, :2], actual[on_deck]]
        return position, phase

    def _go_around(self, t: np.ndarray, wave: float, crossing: float | None) -> tuple[np.ndarray, np.ndarray]:
        """Positions (n, 3) and compass headings (n,) at ``t`` >= ``wave`` on the go-around begun at ``wave`` (s),
        from the position and velocity the profile had then."""
        around = np.array([wave - DECK_STEP_S, wave, wave + DECK_STEP_S])
        centre, _ = self._deck(around)
        flown, _ = self._flown(around, centre, self._deck_height(around), crossing)
        start, velocity = flown[1], (flown[2] - flown[0]) / (2.0 * DECK_STEP_S)
        track = math.atan2(self.ahead[1], self.ahead[0]) + self.side * math.radians(GO_AROUND_TURN_DEG)
        target = np.array([GO_AROUND_SPEED_KN * KNOT * math.cos(track), GO_AROUND_SPEED_KN * KNOT * math.sin(track),
                           GO_AROUND_CLIMB_FT_MIN * FOOT_M / 60.0])
        spans = np.array([GO_AROUND_ACCELERATION_S, GO_AROUND_ACCELERATION_S, GO_AROUND_COLLECTIVE_S])
        elapsed = (t - wave)[:, None]
        position = start + velocity * elapsed + (target - velocity) * spans * smoothstep_integral(elapsed / spans)
        turned = blend((t - wave) / GO_AROUND_ACCELERATION_S)
        return position, self.wind_from_deg - self.side * GO_AROUND_TURN_DEG * turned
