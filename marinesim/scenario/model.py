"""The scenario file's schema: one pydantic model that validates a TOML scenario, holds every key's
type, unit, range and default, words the errors, and writes the scenario reference (docs/SCENARIOS.md).

Each numeric key carries one :class:`Quantity` (unit and range); the loader
(:mod:`marinesim.scenario.schema`) builds the sea, the vessel and the run from the validated model.
"""

from __future__ import annotations

import json
import math
from collections.abc import Callable
from dataclasses import dataclass
from datetime import timedelta
from pathlib import Path
from typing import Annotated, Any, Literal, TypeVar, get_args, get_origin

from pydantic import (AfterValidator, AwareDatetime, BaseModel, ConfigDict, Field, ValidationError, WrapValidator,
                      model_validator)
from pydantic_core import PydanticCustomError, core_schema

from marinesim.angles import wave_beta_from_compass
from marinesim.constants import G
from marinesim.criteria.monitor import (CAUTION, MAX_WINDOW_ROWS, Criterion, check_point, default_name,
                                       parse_condition, watched)
from marinesim.criteria.quantities import CRANE_QUANTITIES, QUANTITIES, STATION_QUANTITIES
from marinesim.criteria.sickness import MAX_WF_DT_S
from marinesim.errors import FileFormatError, ParameterError, ScenarioError
from marinesim.formats import check_file, extensions, formats
from marinesim.hull.mesh import UNITS
from marinesim.views import CAMERAS
from marinesim.manoeuvring.actuators import TELEGRAPH
from marinesim.sea.seastate import SeaState
from marinesim.sea.kinds import (CHOPPINESS_RANGE, FETCH_LIMITED, MAX_DEPTH_M, MAX_FETCH_KM, MAX_HS_M, MAX_RESOLUTION,
                                 MAX_U10_M_S, MAX_WAVE_HEIGHT_M, MAX_WAVE_SYSTEMS, PERIOD_RANGE_S, SPECTRUM_TYPES,
                                 SPREADING_TYPES, misplaced, wind_sea_refusal)
from marinesim.vessel.wamit import ULEN_RANGE_M
from marinesim.wake.compute import MAX_SPEEDS

MAX_SPEED_KN = 40.0
"""The fastest a vessel goes in a scenario or in the viewer (kn)."""
MAX_DURATION_S = 7 * 24 * 3600.0
"""The longest run (s): a week."""
MIN_DT_S = 1e-3
"""The shortest time step (s): a millisecond resolves any wave or ship motion many times over."""
MAX_ROWS = 10**8
"""The most time steps in one run (and rows in one export): some 30 GB of CSV."""
CHANGE_RAMP_S = 10.0
"""Time over which a change blends in unless told otherwise (s): an event's default, the viewer's keys."""
MAX_RAMP_S = 3600.0
"""The longest blend of a change (s)."""
MAX_EVENTS = 1000
MAX_POINTS = 64
"""The most named points on board (each adds its columns to every row of an export)."""
MAX_ON_BOARD_M = 1000.0
"""The farthest a point of the vessel (a named point, the centre of gravity, the visual mesh's origin) lies from the
body frame's origin along any axis (m): twice the longest ship ever built (458 m)."""
MAX_CRITERIA = 64
MAX_MESSAGE = 500
"""The most characters in an event's message."""
MAX_RAIN_MM_H = 200.0
FOOTPRINT_M = 5.0
"""The footprint the plots draw when a scenario gives none (m)."""
MAX_CURRENT_M_S = 5.0
"""The strongest current a scenario may set (m/s: 10 kn, beyond any tidal race a vessel keeps station in)."""
"""The heaviest rain drawn (mm/h): cloudburst."""
MIN_VISIBILITY_M, MAX_VISIBILITY_M = 50.0, 200_000.0
"""The range of the meteorological visibility (m): thick fog to the clearest air."""
NAV_LIGHTS = ("underway", "restricted", "anchored", "none")
"""The navigation lights a vessel shows (COLREG): making way (masthead lights, sidelights, sternlight), restricted
in her ability to manoeuvre (those and red-white-red all round), at anchor (all-round white forward and aft), or
none drawn."""
HELICOPTER_DECISIONS = ("permit", "hold", "wave_off")
"""What the deck tells a helicopter (:mod:`marinesim.offshore.helicopter`)."""
WEATHER = ("visibility_m", "cloud_cover_oktas", "wind_speed_m_s", "rain_mm_h")
"""The ``[environment]`` keys an event or the instructor may change during a run."""
ORDERS = ("speed_kn", "heading_deg", "rudder_deg", "engine", "autopilot", "set_north_m", "set_east_m", "fault",
          "hoist_m_s", "slew_deg_s", "helicopter")
"""The ``[[events]]`` keys that are orders to the ship."""
SHIP_ORDERS = ("heading_deg", "speed_kn", "rudder_deg", "engine", "autopilot")
"""The orders an event may give another ship (``vessel``)."""


@dataclass(frozen=True)
class Quantity:
    """A numeric key's unit and range (bounds ``ge``/``gt``/``le``/``lt``, optional ``test`` named by
    ``what``); as pydantic metadata it refuses values outside the range, for a list every item."""

    unit: str = ""
    ge: float | None = None
    gt: float | None = None
    le: float | None = None
    lt: float | None = None
    what: str = ""
    test: Callable[[float], bool] | None = None

    def __get_pydantic_core_schema__(self, source: Any, handler: Callable[[Any], Any]) -> Any:
        return core_schema.no_info_wrap_validator_function(self._check, handler(source))

    def contains(self, value: float) -> bool:
        return ((self.ge is None or value >= self.ge) and (self.gt is None or value > self.gt)
                and (self.le is None or value <= self.le) and (self.lt is None or value < self.lt)
                and (self.test is None or self.test(value)))

    def span(self, unit: bool = True) -> str:
        """The range in words, e.g. ``in 0..40 kn``, ``> 0 m``, ``in 0..100 % (100 excluded)``."""
        low, high = _first(self.ge, self.gt), _first(self.le, self.lt)
        unit = f" {self.unit}" if unit and self.unit else ""
        if low is not None and high is not None:
            excluded = [f"{bound:g}" for bound in (self.gt, self.lt) if bound is not None]
            text = f"in {low:g}..{high:g}{unit}" + (f" ({' and '.join(excluded)} excluded)" if excluded else "")
        elif low is not None:
            text = f"{'>=' if self.ge is not None else '>'} {low:g}{unit}"
        elif high is not None:
            text = f"{'<=' if self.le is not None else '<'} {high:g}{unit}"
        else:
            text = ""
        return " ".join(part for part in (self.what, text) if part)

    def _check(self, given: Any, handler: Callable[[Any], Any]) -> Any:
        """The typed value, if within range; the message quotes the value as the file gives it."""
        value = handler(given)
        if isinstance(value, list):
            if not all(self.contains(v) for v in value):
                raise PydanticCustomError("range", f"expected {self.span()}, got {given!r}")
        elif value is not None and not self.contains(value):
            raise PydanticCustomError("range", f"must be {self.span()}, got {given!r}")
        return value


def _first(*values: float | None) -> float | None:
    return next((v for v in values if v is not None), None)


def _expecting(what: str) -> WrapValidator:
    """Word any refusal of the value as ``expected <what>, got <value>``."""
    def wrap(value: Any, handler: Callable[[Any], Any]) -> Any:
        try:
            return handler(value)
        except ValidationError:
            raise PydanticCustomError("expected", f"expected {what}, got {value!r}") from None
    return WrapValidator(wrap)


def _identifier(name: str) -> str:
    if not name.isidentifier():
        raise PydanticCustomError("name", "a point name must be a plain identifier (letters, digits, _)")
    return name


def _power_of_two(n: float) -> bool:
    return int(n) & (int(n) - 1) == 0


def _refuse(key: str, message: str) -> PydanticCustomError:
    """An error of a cross-key rule, reported at ``key`` of the section that raises it."""
    return PydanticCustomError("rule", message, {"key": key})


Point = Annotated[list[float], Quantity("m", ge=-MAX_ON_BOARD_M, le=MAX_ON_BOARD_M, what="coordinates on board"),
                  Field(min_length=3, max_length=3),
                  _expecting(f"[x, y, z] in metres (body frame), each in -{MAX_ON_BOARD_M:g}..{MAX_ON_BOARD_M:g} m "
                             "(twice the longest ship)")]
def _finite_rows(rows: list[list[float]]) -> list[list[float]]:
    if not all(math.isfinite(v) for row in rows for v in row):
        raise PydanticCustomError("finite", "a matrix of finite numbers (SI)")
    return rows


Matrix6 = Annotated[list[Annotated[list[float], Field(min_length=6, max_length=6)]], Field(min_length=6, max_length=6),
                    AfterValidator(_finite_rows),
                    _expecting("6 rows of 6 numbers (SI: N/m, N m/rad; N s/m, N m s/rad)")]
HULL_OPTIONS = {"hull_units": "units", "hull_scale": "scale", "hull_axes": "axes", "hull_draft_m": "draft",
                "hull_trim_deg": "trim_deg"}
"""Scenario key -> :func:`~marinesim.hull.load_hull` option."""
VISUAL_MESH_OPTIONS = {"visual_mesh_units": "units", "visual_mesh_scale": "scale", "visual_mesh_axes": "axes",
                       "visual_mesh_offset_m": "offset"}
"""Scenario key -> :func:`~marinesim.hull.load_visual_mesh` option."""


class Section(BaseModel):
    """Strict TOML types (ints accepted for floats, no bools for numbers, no NaN or inf), no unknown keys."""

    model_config = ConfigDict(strict=True, extra="forbid", allow_inf_nan=False, frozen=True)


class OceanOptions(Section):
    """``[ocean]``: the FFT cascades that carry the sea."""

    depth_m: Annotated[float | None, Quantity("m", gt=0.0, le=MAX_DEPTH_M)] = Field(
        None, description="water depth, deeper than the hull's draft; absent: deep water")
    tiles: Annotated[int, Quantity(ge=1, le=8)] = Field(4, description="FFT cascades (tiles)")
    resolution: Annotated[int, Quantity(ge=16, le=MAX_RESOLUTION, what="a power of two", test=_power_of_two)] = Field(
        256, description="samples per tile side")
    choppiness: Annotated[float, Quantity(ge=CHOPPINESS_RANGE[0], le=CHOPPINESS_RANGE[1])] = Field(
        1.0, description="horizontal displacement factor (0: none)")


class SeaOptions(Section):
    """``[[sea]]``: one wave system (a spectrum from a direction, or a regular wave)."""

    type: Literal[SPECTRUM_TYPES] = Field(description="spectrum: jonswap, pm, tma, or a regular wave")
    from_deg: Annotated[float, Quantity("deg", ge=0.0, le=360.0, what="a compass direction")] = Field(
        description="compass direction the waves come from")
    hs_m: Annotated[float | None, Quantity("m", gt=0.0, le=MAX_HS_M)] = Field(
        None, description="significant wave height (jonswap, pm, tma)")
    tp_s: Annotated[float | None, Quantity("s", ge=PERIOD_RANGE_S[0], le=PERIOD_RANGE_S[1])] = Field(
        None, description="peak period (jonswap, pm, tma)")
    gamma: Annotated[float | None, Quantity(ge=1.0, le=20.0)] = Field(
        None, description="JONSWAP peak enhancement (jonswap, tma); absent: DNV's from hs_m, tp_s")
    u10_m_s: Annotated[float | None, Quantity("m/s", gt=0.0, le=MAX_U10_M_S)] = Field(
        None, description="wind speed at 10 m: a JONSWAP from wind and fetch instead of hs_m, tp_s (g fetch / u10^2 "
                          f"at least {FETCH_LIMITED[0]:g}; beyond {FETCH_LIMITED[1]:g} the sea is fully developed)")
    fetch_km: Annotated[float | None, Quantity("km", gt=0.0, le=MAX_FETCH_KM)] = Field(
        None, description="fetch, with u10_m_s")
    spreading: Literal[SPREADING_TYPES] | None = Field(
        None, description="directional spreading; absent: cos2s with spreading_s, else long-crested")
    spreading_s: Annotated[float | None, Quantity(gt=0.0, le=1000.0)] = Field(
        None, description="spreading exponent s (n for cos2n-halfplane)")
    height_m: Annotated[float | None, Quantity("m", gt=0.0, le=MAX_WAVE_HEIGHT_M)] = Field(
        None, description="wave height (regular)")
    period_s: Annotated[float | None, Quantity("s", ge=PERIOD_RANGE_S[0], le=PERIOD_RANGE_S[1])] = Field(
        None, description="wave period (regular)")
    phase_deg: Annotated[float, Quantity("deg")] = Field(0.0, description="phase at the origin (regular)")

    @model_validator(mode="after")
    def _keys_fit_the_type(self) -> SeaOptions:
        given = {WAVE_PARAMETERS[key]: key for key in self.model_fields_set if key in WAVE_PARAMETERS}
        wrong = misplaced(self.type, given)
        if wrong is not None:
            raise _refuse(given[wrong[0]], wrong[1].replace("u10", "u10_m_s"))
        if self.u10_m_s is not None and self.fetch_km is not None:
            why = wind_sea_refusal(self.u10_m_s, self.fetch_km, ("u10_m_s", "fetch_km"))
            if why is not None:
                raise _refuse("u10_m_s", why)
        return self


WAVE_PARAMETERS = {"hs_m": "hs", "tp_s": "tp", "gamma": "gamma", "u10_m_s": "u10", "fetch_km": "fetch_km",
                   "spreading": "spreading", "spreading_s": "spreading_s", "height_m": "height",
                   "period_s": "period", "phase_deg": "phase_deg"}
"""``[[sea]]`` key -> the parameter of :func:`~marinesim.sea.build.wave_system` it gives."""


class VesselOptions(Section):
    """``[vessel]``: the RAO table, hull and visual mesh (paths relative to the scenario), course, points."""

    rao: str = Field(description="RAO file (" + ", ".join(f"{f.name} {' '.join(f.extensions) or 'by content'}"
                                                          for f in formats("rao")) + ")")
    rao_speeds_kn: Annotated[list[Annotated[float, Quantity("kn", ge=0.0, le=MAX_SPEED_KN)]] | None,
                             Field(min_length=1, max_length=100)] = Field(
        None, description="the RAO table's speeds to use, each one of the table's (absent: all): leave out a speed "
                          "whose data are screened as non-physical, and say why in a comment")
    speed_kn: Annotated[float, Quantity("kn", ge=0.0, le=MAX_SPEED_KN)] = Field(
        0.0, description="speed, within the RAO table's speeds if it has several")
    heading_deg: Annotated[float, Quantity("deg", ge=0.0, le=360.0, what="a compass heading")] = Field(
        0.0, description="compass heading the bow points to")
    ulen_m: Annotated[float | None, Quantity("m", ge=ULEN_RANGE_M[0], le=ULEN_RANGE_M[1])] = Field(
        None, description="WAMIT length scale ULEN; absent: from the .gdf beside the .4")
    roll_damping_pct: Annotated[float, Quantity("% of critical", ge=0.0, lt=100.0)] = Field(
        0.0, description="extra linear roll damping (Capytaine datasets)")
    rao_body: str | None = Field(None, description="the body whose motions to read from a Capytaine dataset of "
                                                   "several (solved coupled, every body free) or a WAMIT run of "
                                                   "several (its number, or its .gdf file's name in the .pot)")
    accept_resonance: bool = Field(False, description="accept a lightly damped resonance of the RAO table beyond "
                                                      "the plausibility limits (a moored body's surge) as real")
    mass_kg: Annotated[float | None, Quantity("kg", gt=0.0, le=1e10)] = Field(
        None, description="the vessel's mass, with cog_m and radii_of_gyration_m: replaces the file's for RAOs "
                          "solved here (WAMIT .1/.3/.hst and .out, Capytaine)")
    cog_m: Point | None = Field(None, description="centre of gravity, [x, y, z] in the body frame")
    radii_of_gyration_m: Annotated[list[float] | None, Quantity("m", gt=0.0), Field(min_length=3, max_length=3)] = (
        Field(None, description="roll, pitch, yaw radii of gyration about the centre of gravity"))
    external_stiffness: Matrix6 | None = Field(
        None, description="6 x 6 stiffness added to the hydrostatic (moorings), about the reference point")
    external_damping: Matrix6 | None = Field(None, description="6 x 6 linear damping added to the radiation damping")
    hull: str | None = Field(None, description=f"hull mesh ({', '.join(extensions('mesh'))}): the wake")
    hull_units: Literal[tuple(UNITS)] = Field("m", description="the hull mesh's length units")
    hull_scale: Annotated[float, Quantity(gt=0.0)] = Field(1.0, description="geometric scale (50 for a 1:50 model)")
    hull_axes: str = Field("x,y,z", description='mesh axes that become body x, y, z (e.g. "x,-z,y")')
    hull_draft_m: Annotated[float | None, Quantity("m", gt=0.0)] = Field(
        None, description="draft: keel at z = -draft; absent: the mesh's z = 0 is the waterline")
    hull_trim_deg: Annotated[float, Quantity("deg", gt=-30.0, lt=30.0)] = Field(0.0, description="trim, bow down")
    wake_speeds_kn: Annotated[list[float], Quantity("kn", gt=0.0, le=MAX_SPEED_KN, what="speeds"),
                              Field(max_length=MAX_SPEEDS)] = Field(
        default_factory=list, description=f"more speeds to precompute the Kelvin wake for (needs hull; at most "
                                          f"{MAX_SPEEDS})")
    manoeuvring: str | None = Field(
        None, description='her manoeuvring model, steering gear, engine and autopilot: a shipped vessel by name '
                          '("kvlcc2", "s175", "supply", "tanker": configs/vessels), a manoeuvring file (.toml), or '
                          '"station" (held on station: position kept, heading by order); absent: a model from the '
                          "hull's main particulars, without a hull a steady course and speed")
    visual_mesh: str | None = Field(None, description="mesh drawn instead of the hull (may be open)")
    topsides_rgb: Annotated[list[int] | None, Quantity("", ge=0, le=255, what="colour levels"),
                            Field(min_length=3, max_length=3)] = Field(
        None, description="hull colour above the boot-top, [r, g, b] 0..255, when the ship is drawn from its hull "
                          "(no visual_mesh)")
    deck_layout: Literal["flat", "hatches"] = Field(
        "flat", description="the deck of a ship drawn from its hull: flat (tanker, supply) or hatch covers (bulk, "
                            "container)")
    nav_lights: Literal[NAV_LIGHTS] = Field("underway", description="the navigation lights it shows at night and in "
                                       "restricted visibility (COLREG): underway, restricted (in her ability to "
                                       "manoeuvre: red-white-red added), anchored (all-round white) or none")
    visual_mesh_units: Literal[tuple(UNITS)] = Field("m", description="the visual mesh's length units")
    visual_mesh_scale: Annotated[float, Quantity(gt=0.0)] = Field(1.0, description="its geometric scale")
    visual_mesh_axes: str = Field("x,y,z", description="its axes that become body x, y, z")
    visual_mesh_offset_m: Annotated[list[float], Quantity("m", ge=-MAX_ON_BOARD_M, le=MAX_ON_BOARD_M,
                                                          what="coordinates on board")] = Field(
        default_factory=lambda: [0.0, 0.0, 0.0], description="its origin in the body frame, [x, y, z]")
    points: Annotated[dict[Annotated[str, AfterValidator(_identifier)], Point], Field(max_length=MAX_POINTS)] = Field(
        default_factory=dict, description=f"named points on board (at most {MAX_POINTS}), [x, y, z] in the body "
                                          "frame (x forward, y port, z up)")

    @model_validator(mode="after")
    def _mass_comes_whole(self) -> VesselOptions:
        given = [key for key in ("mass_kg", "cog_m", "radii_of_gyration_m") if getattr(self, key) is not None]
        if given and len(given) < 3:
            missing = [key for key in ("mass_kg", "cog_m", "radii_of_gyration_m") if key not in given]
            raise _refuse(given[0], f"needs {' and '.join(missing)} too (a mass, where it is and how it is spread)")
        return self

    @model_validator(mode="after")
    def _options_need_their_mesh(self) -> VesselOptions:
        for mesh, options in (("hull", ("wake_speeds_kn", *HULL_OPTIONS)), ("visual_mesh", VISUAL_MESH_OPTIONS)):
            given = [key for key in options if key in self.model_fields_set]
            if given and getattr(self, mesh) is None:
                raise _refuse(given[0], f"given without vessel.{mesh}")
        return self



class RunOptions(Section):
    """``[run]``: how long, how fine, which seed."""

    duration_s: Annotated[float, Quantity("s", gt=0.0, le=MAX_DURATION_S)] = Field(600.0, description="run length")
    dt_s: Annotated[float, Quantity("s", what=f"in {MIN_DT_S:g}..duration_s", test=lambda dt: dt >= MIN_DT_S)] = Field(
        0.1, description=f"time step; at most {MAX_ROWS:.0e} steps per run")
    seed: Annotated[int, Quantity(ge=0)] = Field(0, description="random seed of the wave amplitudes")

    @model_validator(mode="after")
    def _step_within_run(self) -> RunOptions:
        if self.dt_s > self.duration_s:
            raise _refuse("dt_s", f"must be <= duration_s ({self.duration_s:g} s), got {self.dt_s!r}")
        if self.steps > MAX_ROWS:
            raise _refuse("dt_s", f"{self.duration_s:g} s at {self.dt_s!r} s is {self.steps:.3g} steps, more than "
                                  f"{MAX_ROWS:.0e}: give a larger dt_s or a shorter duration_s")
        return self

    @property
    def steps(self) -> int:
        """Time steps in the run, both ends included."""
        return round(self.duration_s / self.dt_s) + 1


class EnvironmentOptions(Section):
    """``[environment]``: the light and the air the picture is drawn in, and the wind and current a vessel keeping
    station feels (``[station]``; a vessel on passage does not see them). The sun
    is placed by ``time_utc`` at the position, where it and the moon move as the run goes on, or fixed by
    ``sun_azimuth_deg`` and ``sun_elevation_deg``."""

    time_utc: AwareDatetime | None = Field(
        None, description="date and time of the run's start, with its offset (TOML 2026-11-25T15:30:00Z): the sun "
                          "and the moon at latitude_deg, longitude_deg; instead of the sun's keys")
    latitude_deg: Annotated[float | None, Quantity("deg", ge=-90.0, le=90.0)] = Field(
        None, description="where the run is, north positive: the sun's place with time_utc, and the position "
                          "--nmea and --dis give")
    longitude_deg: Annotated[float | None, Quantity("deg", ge=-180.0, le=180.0)] = Field(
        None, description="where the run is, east positive (as latitude_deg)")
    sun_azimuth_deg: Annotated[float, Quantity("deg", ge=0.0, lt=360.0)] = Field(
        200.0, description="compass bearing of the sun (without time_utc)")
    sun_elevation_deg: Annotated[float, Quantity("deg", ge=-90.0, le=90.0)] = Field(
        30.0, description="height of the sun above the horizon (without time_utc): below -18 it is night")
    cloud_cover_oktas: Annotated[float, Quantity("oktas", ge=0.0, le=8.0)] = Field(
        0.0, description="eighths of the sky covered by cloud (8: overcast, no direct sun)")
    wind_speed_m_s: Annotated[float | None, Quantity("m/s", ge=0.0, le=MAX_U10_M_S)] = Field(
        None, description="wind at 10 m, which lays foam in streaks from Beaufort 7 (13.9 m/s); absent: the first "
                          "wave system's u10_m_s, else the wind of a fully developed sea of its Tp")
    wind_from_deg: Annotated[float | None, Quantity("deg", ge=0.0, le=360.0, what="a compass bearing")] = Field(
        None, description="where the wind comes from; absent: the first wave system's from_deg")
    rain_mm_h: Annotated[float, Quantity("mm/h", ge=0.0, le=MAX_RAIN_MM_H)] = Field(
        0.0, description="rain rate drawn as falling streaks (2.5 light, 10 heavy, 50 violent showers); the "
                         "visibility is its own key")
    current_speed_m_s: Annotated[float, Quantity("m/s", ge=0.0, le=MAX_CURRENT_M_S)] = Field(
        0.0, description="a uniform current (pushes a vessel keeping station: [station])")
    current_to_deg: Annotated[float, Quantity("deg", ge=0.0, le=360.0, what="a compass bearing")] = Field(
        0.0, description="where the current sets TO (as mariners give a current, unlike wind and waves)")
    wind_gusts: bool = Field(True, description="the wind on a vessel keeping station gusts (NPD / ISO 19901-1 "
                                               "spectrum) about its mean")
    visibility_m: Annotated[float, Quantity("m", ge=MIN_VISIBILITY_M, le=MAX_VISIBILITY_M)] = Field(
        40_000.0, description="meteorological visibility: where a dark object's contrast against the horizon "
                              "falls to 0.05 (Koschmieder; 1 km is fog, 10 km moderate, 40 km very good)")

    @model_validator(mode="after")
    def _one_way_to_place_the_sun(self) -> EnvironmentOptions:
        position = {"latitude_deg", "longitude_deg"} & self.model_fields_set
        sun = {"sun_azimuth_deg", "sun_elevation_deg"} & self.model_fields_set
        if self.time_utc is not None and len(position) < 2:
            raise PydanticCustomError("environment", "time_utc needs latitude_deg and longitude_deg")
        if len(position) == 1:
            raise PydanticCustomError("environment", "latitude_deg and longitude_deg go together")
        if self.time_utc is not None and sun:
            raise PydanticCustomError("environment", "give time_utc (the sun from the date) or the sun's keys, "
                                                     "not both")
        return self

    def changed(self, hours: float = 0.0, **keys: float) -> EnvironmentOptions:
        """This environment ``hours`` later (with ``time_utc``) and with some keys replaced, validated as the
        scenario's are (a :class:`~marinesim.errors.ParameterError` names a value out of range)."""
        values = self.model_dump(exclude_unset=True) | keys
        if isinstance(hours, bool) or not isinstance(hours, (int, float)) or not abs(hours) <= MAX_DURATION_S / 3600:
            raise ParameterError(f"hours: expected a number of hours within a week, got {hours!r}")
        if hours:
            if self.time_utc is None:
                raise ParameterError("the sun is fixed by the scenario's sun keys: only a time_utc moves it")
            try:
                values["time_utc"] = self.time_utc + timedelta(hours=hours)
            except OverflowError:
                raise ParameterError(f"time_utc {self.time_utc} moved {hours:g} h leaves the calendar") from None
        try:
            return EnvironmentOptions.model_validate(values)
        except ValidationError as error:
            first = error.errors()[0]
            raise ParameterError(f"environment.{'.'.join(map(str, first['loc']))}: {first['msg']}") from None


PIERSON_MOSKOWITZ = 0.877
"""wp U19.5 / g of a fully developed sea (Pierson & Moskowitz 1964)."""
U19_5_TO_U10 = 1.075
"""The wind at 19.5 m over the wind at 10 m (the neutral log profile over the sea)."""


def wind_of(environment: EnvironmentOptions, sea: SeaState | None) -> tuple[float, float, float]:
    """The wind (unit vector it blows towards, E frame x and y, and speed at 10 m in m/s): the environment's, else
    from the first wave system of ``sea`` (none without one): what the picture's foam and spray and a vessel keeping
    station feel."""
    first = next(iter(sea.systems), None) if sea is not None else None
    speed, towards = environment.wind_speed_m_s, None
    if environment.wind_from_deg is not None:
        towards = wave_beta_from_compass(environment.wind_from_deg)  # blowing from a bearing, as waves come
    if first is not None:
        towards = first.beta if towards is None else towards
        if speed is None:
            spectrum = getattr(first, "spectrum", None)
            u10 = getattr(spectrum, "u10", None)
            period = spectrum.tp if spectrum is not None else first.period
            speed = u10 if u10 is not None else PIERSON_MOSKOWITZ * G * period / (2.0 * math.pi) / U19_5_TO_U10
    if speed is None or towards is None:
        return (0.0, 0.0, 0.0)
    return (math.cos(towards), math.sin(towards), float(speed))


def _at_least_one(systems: list[SeaOptions]) -> list[SeaOptions]:
    if not systems:
        raise PydanticCustomError("required", "at least one [[sea]] wave system is required")
    return systems


def _condition(text: str) -> str:
    try:
        parse_condition(text)
    except ParameterError as error:
        raise PydanticCustomError("condition", str(error)) from None
    return text


class EventOptions(Section):
    """``[[events]]``: a change of sea, orders to the ship (helm, telegraph, autopilot), weather and/or a message, at
    a time or on a condition."""

    at_s: Annotated[float | None, Quantity("s", ge=0.0, le=MAX_DURATION_S)] = Field(
        None, description="when it happens; events with at_s come in time order")
    when: Annotated[str | None, AfterValidator(lambda t: t if t is None else _condition(t))] = Field(
        None, description='instead of at_s: the first evaluation at which a criterion\'s value (or a '
                          '"[point.]quantity") meets a comparison, e.g. "bridge.vertical_acc_rms_m_s2 > 1.0"')
    ramp_s: Annotated[float, Quantity("s", ge=0.0, le=MAX_RAMP_S)] = Field(
        CHANGE_RAMP_S, description="how long the change blends in, weather too (> 0 for a sea change)")
    sea: Annotated[list[SeaOptions] | None, Field(max_length=MAX_WAVE_SYSTEMS)] = Field(
        None, description=f"1 to {MAX_WAVE_SYSTEMS} wave systems that replace the sea (as [[sea]])")
    speed_kn: Annotated[float | None, Quantity("kn", ge=0.0, le=MAX_SPEED_KN)] = Field(
        None, description="the engine set for this speed (the rpm that holds it in calm water)")
    heading_deg: Annotated[float | None, Quantity("deg", ge=0.0, le=360.0, what="a compass heading")] = Field(
        None, description="course ordered to the autopilot (it takes the helm)")
    rudder_deg: Annotated[float | None, Quantity("deg", ge=-45.0, le=45.0)] = Field(
        None, description="rudder order by hand, positive to starboard (the autopilot lets go of the helm)")
    engine: Literal[TELEGRAPH] | None = Field(None, description="telegraph order")
    autopilot: bool | None = Field(None, description="the autopilot on (on the present heading) or off")
    message: Annotated[str | None, Field(max_length=MAX_MESSAGE)] = Field(
        None, description="shown in the viewer and the log when the event happens")
    visibility_m: Annotated[float | None, Quantity("m", ge=MIN_VISIBILITY_M, le=MAX_VISIBILITY_M)] = Field(
        None, description="new visibility (fog rolling in, clearing)")
    cloud_cover_oktas: Annotated[float | None, Quantity("oktas", ge=0.0, le=8.0)] = Field(
        None, description="new cloud cover")
    wind_speed_m_s: Annotated[float | None, Quantity("m/s", ge=0.0, le=MAX_U10_M_S)] = Field(
        None, description="new wind speed (the foam streaks; the sea changes only by sea)")
    rain_mm_h: Annotated[float | None, Quantity("mm/h", ge=0.0, le=MAX_RAIN_MM_H)] = Field(
        None, description="new rain rate (a squall; 0 ends it)")
    set_north_m: Annotated[float | None, Quantity("m", ge=-500.0, le=500.0)] = Field(
        None, description="a vessel on DP: her position set point north of where she started (with heading_deg: "
                          "her heading's)")
    set_east_m: Annotated[float | None, Quantity("m", ge=-500.0, le=500.0)] = Field(
        None, description="... and east of it")
    hoist_m_s: Annotated[float | None, Quantity("m/s", ge=-5.0, le=5.0)] = Field(
        None, description="the crane's hoist: positive up, negative lowering, 0 stopped (within its hoist speed)")
    slew_deg_s: Annotated[float | None, Quantity("deg/s", ge=-10.0, le=10.0)] = Field(
        None, description="the crane's slew: positive to port (anticlockwise from above), 0 stopped")
    helicopter: Literal[HELICOPTER_DECISIONS] | None = Field(
        None, description="the deck's word to the helicopter: permit (GREEN: land), hold (RED: hold in the hover) or "
                          "wave_off")
    vessel: Annotated[str | None, Field(min_length=1, max_length=40)] = Field(
        None, description="the name of a ship of [[vessels]] under her manoeuvring model: the helm, engine and "
                          "autopilot orders (heading_deg, speed_kn, rudder_deg, engine, autopilot) are hers, not "
                          "own-ship's, and from then she answers them, not her route (the instructor drives her)")
    fault: Annotated[str | None, Field(min_length=1, max_length=80)] = Field(
        None, description='an instructor\'s fault on a vessel keeping station: "thruster:NAME" lost, '
                          '"drive-off:NAME" stuck at full thrust, "reference drift" (the position reference walks '
                          'off), "line:NAME" parted')

    @model_validator(mode="after")
    def _one_trigger_and_an_action(self) -> EventOptions:
        if (self.at_s is None) == (self.when is None):
            raise _refuse("at_s", "give exactly one of at_s and when")
        if self.sea is not None:
            if not self.sea:
                raise _refuse("sea", "an empty list: give at least one wave system, or leave sea out")
            if self.ramp_s == 0.0:
                raise _refuse("ramp_s", "a sea change blends in over ramp_s > 0 s, got 0")
        if all(getattr(self, key) is None for key in ("sea", *ORDERS, "message", *WEATHER)):
            raise _refuse("message", "an event needs something to do: sea, " + ", ".join(ORDERS) + ", "
                                     "visibility_m, cloud_cover_oktas, wind_speed_m_s, rain_mm_h or message")
        if self.heading_deg is not None and self.autopilot is False:
            raise _refuse("autopilot", "heading_deg is a course for the autopilot: it cannot come with "
                                       "autopilot = false")
        if self.vessel is not None:
            helm = [key for key in SHIP_ORDERS if getattr(self, key) is not None]
            other = [key for key in ORDERS if key not in SHIP_ORDERS and getattr(self, key) is not None]
            if not helm or other:
                raise _refuse("vessel", "orders to another ship are her helm, engine and autopilot: give "
                                        + ", ".join(SHIP_ORDERS) + (f", not {other[0]}" if other else ""))
        if self.rudder_deg is not None and (self.heading_deg is not None or self.autopilot):
            raise _refuse("rudder_deg", "a rudder order by hand takes the helm from the autopilot: give it without "
                                        "heading_deg or autopilot = true")
        return self


SCRIPTED_SHARE = 0.8
"""The least share of seeds in which an exercise's scripted outcome must hold (``[[criteria]] scripted``)."""


class CriterionOptions(Section):
    """``[[criteria]]``: a quantity of the motions, at a point or of the vessel, against a limit."""

    name: Annotated[str | None, Field(min_length=1, max_length=80)] = Field(
        None, description="what the panel and the report call it; absent: point.quantity")
    point: str | None = Field(None, description="a [vessel.points] name; absent for the vessel's own motions")
    quantity: Literal[tuple(QUANTITIES)] = Field(
        description="what is measured (docs/FORMULAS.md: How the criteria are computed)")
    limit: Annotated[float, Quantity(gt=0.0)] = Field(description="upper limit, in the quantity's unit")
    window_s: Annotated[float | None, Quantity("s", ge=10.0, le=MAX_DURATION_S)] = Field(
        None, description="running window; absent: 600 s, helideck quantities 1200 s")
    caution: Annotated[float, Quantity(gt=0.0, le=1.0)] = Field(
        CAUTION, description="fraction of the limit that raises a caution")
    threshold_m: Annotated[float | None, Quantity("m", gt=0.0)] = Field(
        None, description="relative_motion_exceedance: freeboard (green water) or draft (the forefoot's emergence); "
                          "slamming_probability: draft at the point")
    threshold_velocity_m_s: Annotated[float | None, Quantity("m/s", gt=0.0)] = Field(
        None, description="slamming_probability: relative velocity of a slam; absent: Ochi's 0.093 sqrt(g L), L the "
                          "ship's length")
    tipping_coefficient: Annotated[float | None, Quantity(gt=0.0, le=2.0)] = Field(
        None, description="mii_per_min: l/h of a standing person; absent: 0.25")
    scripted: Literal["exceeded", "within"] | None = Field(
        None, description=f"what the exercise is built to show with no action from the trainee: the criterion above "
                          f"its limit, or within it, in at least {SCRIPTED_SHARE:.0%} of seeds (the assessment's "
                          f"chance says how likely in the sea met)")

    @model_validator(mode="after")
    def _options_fit_the_quantity(self) -> CriterionOptions:
        if self.name is not None and any(op in self.name for op in "<>"):
            raise _refuse("name", "a criterion's name cannot hold < or > (conditions compare names)")
        takes = QUANTITIES[self.quantity].options
        for key in ("threshold_m", "tipping_coefficient", "threshold_velocity_m_s"):
            if getattr(self, key) is not None and key not in takes:
                raise _refuse(key, f"{self.quantity} takes no {key}")
        if "threshold_m" in takes and self.threshold_m is None:
            raise _refuse("threshold_m", f"required by {self.quantity}")
        return self


DECISIONS = {
    "acknowledge": "every alarm of its criteria (of all criteria if it names none) acknowledged within within_s",
    "act_before": "a course or speed order given before the expectation of one of its criteria (the median of "
                  "its window's value in the sea she meets) passes the limit",
    "give_way": "COLREG Rules 8, 15 and 16: her heading 10 deg off or her speed a quarter down while the time to the "
                "closest point of approach to vessel is still within_s or more, and own-ship passing vessel at "
                "passing_m or more",
}
"""The decisions an objective may judge, in words."""


class ObjectiveOptions(Section):
    """One of ``[briefing] objectives``: what the trainee is to achieve, judged by the criteria it names (met: none
    exceeded), or a decision the trainee is to take, judged from the session's journal (:data:`DECISIONS`)."""

    text: Annotated[str, Field(min_length=1, max_length=400)] = Field(description="the objective, as briefed")
    criteria: Annotated[list[str], Field(max_length=MAX_CRITERIA)] = Field(
        default_factory=list, description="names of [[criteria]] that judge it (met: none exceeded); for a "
                                          "decision, the criteria it is about")
    decision: Literal[tuple(DECISIONS)] | None = Field(
        None, description="judge a decision instead: " + "; ".join(f"{k}: {v}" for k, v in DECISIONS.items()))
    within_s: Annotated[float | None, Quantity("s", gt=0.0, le=3600.0)] = Field(
        None, description="acknowledge: the longest an alarm may wait for its acknowledgement; give_way: the least "
                          "time to the closest point of approach at which to act (early action, Rule 16)")
    vessel: str | None = Field(None, description="give_way: the [[vessels]] name of the vessel to keep out of the "
                                                 "way of")
    passing_m: Annotated[float | None, Quantity("m", gt=0.0, le=20_000.0)] = Field(
        None, description="give_way: the least distance to pass her at (1 nm is 1852 m)")

    @model_validator(mode="after")
    def _decision_has_what_it_needs(self) -> ObjectiveOptions:
        if self.decision == "acknowledge" and self.within_s is None:
            raise _refuse("within_s", "required by decision = 'acknowledge' (the longest an alarm may wait)")
        if self.decision == "give_way" and (self.within_s is None or self.vessel is None or self.passing_m is None):
            raise _refuse("decision", "decision = 'give_way' needs vessel, passing_m and within_s")
        if self.decision != "give_way" and (self.vessel is not None or self.passing_m is not None):
            raise _refuse("vessel" if self.vessel is not None else "passing_m", "only decision = 'give_way' takes it")
        if self.decision not in ("acknowledge", "give_way") and self.within_s is not None:
            raise _refuse("within_s", "only decisions 'acknowledge' and 'give_way' take it")
        if self.decision == "act_before" and not self.criteria:
            raise _refuse("criteria", "decision = 'act_before' needs the criteria whose expectation it is about")
        return self


class HelicopterOptions(Section):
    """``[helicopter]``: a helicopter's approach to own-ship's helideck, into the wind on the offshore landing
    profile (:mod:`marinesim.offshore.helicopter`): at the hover alongside it waits for the deck's word (events'
    ``helicopter``: permit, hold, wave_off), crosses over the deck and lands, or waves off."""

    deck_point: str = Field(description="the helideck's centre: one of [vessel.points]")
    start_s: Annotated[float, Quantity("s", ge=0.0, le=MAX_DURATION_S)] = Field(
        0.0, description="when it is at the start of the final approach (0.75 nm out)")
    approach_speed_kn: Annotated[float, Quantity("kn", gt=10.0, le=120.0)] = Field(
        60.0, description="closing speed on the approach")
    glide_angle_deg: Annotated[float, Quantity("deg", ge=2.0, le=15.0)] = Field(6.0, description="the glide path")
    hover_height_ft: Annotated[float, Quantity("ft", gt=0.0, le=200.0)] = Field(
        30.0, description="the hover's height above the deck")
    deck_side: Literal["left", "right"] = Field("right", description="the side of the helicopter the deck is on "
                                                                     "at the hover (the commander's)")


class CraneOptions(Section):
    """``[crane]``: own-ship's pedestal crane and its load on the wire, a spherical pendulum on an elastic wire that
    goes slack (:mod:`marinesim.offshore.crane`), driven by her motions at the boom tip; the load may rest on and be
    set down on a deck: one of her points (her cargo deck, heaving with her) or a fixed deck's height (a platform's).
    Hoist and slew are orders (events' ``hoist_m_s`` and ``slew_deg_s``, the crane operator's keys)."""

    pedestal_m: Point = Field(description="the top of the pedestal, [x, y, z] in the body frame (z above the water)")
    boom_height_m: Annotated[float, Quantity("m", gt=0.0, le=200.0)] = Field(description="boom tip above the pedestal")
    radius_m: Annotated[float, Quantity("m", ge=0.0, le=200.0)] = Field(description="outreach from the slew axis")
    slew_deg: Annotated[float, Quantity("deg", ge=-180.0, le=180.0)] = Field(
        0.0, description="where the boom points at the start, from the bow, positive to port")
    hoist_speed_m_s: Annotated[float, Quantity("m/s", gt=0.0, le=5.0)] = Field(0.5, description="the fastest hoist")
    slew_rate_deg_s: Annotated[float, Quantity("deg/s", gt=0.0, le=10.0)] = Field(2.0, description="the fastest slew")
    max_wire_m: Annotated[float, Quantity("m", gt=0.0, le=3000.0)] = Field(description="the wire on the drum")
    min_wire_m: Annotated[float, Quantity("m", gt=0.0, le=100.0)] = Field(
        1.0, description="the shortest wire below the tip (hook block at the top)")
    load_chart: Annotated[list[Annotated[list[float], Field(min_length=2, max_length=2)]],
                          Field(min_length=1, max_length=64)] = Field(
        description="[[radius m, safe working load t], ...], radius increasing")
    load_t: Annotated[float, Quantity("t", gt=0.0, le=10_000.0)] = Field(description="the load on the hook")
    wire_ea_n: Annotated[float, Quantity("N", gt=0.0, le=1e11)] = Field(
        1.0e8, description="the wire's axial stiffness EA (a 40 mm steel wire rope about 1e8 N)")
    wire_damping_pct: Annotated[float, Quantity("% of critical", ge=0.0, lt=100.0)] = Field(
        5.0, description="damping of the wire's axial mode")
    tag_lines_pct: Annotated[float, Quantity("% of critical", ge=0.0, lt=100.0)] = Field(
        0.0, description="damping of the load's swing by the deck crew's tag lines (0: none, the load swings free)")
    wire_m: Annotated[float, Quantity("m", gt=0.0, le=3000.0)] = Field(description="wire paid out at the start")
    landing_point: str | None = Field(
        None, description="the deck the load rests on and is set down on: one of [vessel.points] (it heaves)")
    landing_deck_m: Annotated[float | None, Quantity("m", ge=-100.0, le=300.0)] = Field(
        None, description="... or a fixed deck's height above the still water (a platform's)")

    @model_validator(mode="after")
    def _one_deck(self) -> CraneOptions:
        if self.landing_point is not None and self.landing_deck_m is not None:
            raise _refuse("landing_deck_m", "give landing_point or landing_deck_m, not both")
        return self


class StationOptions(Section):
    """``[station]``: the vessel keeps station under wind, current and waves, on dynamic positioning or moorings
    (:mod:`marinesim.station`); the set point is where she starts, on her heading."""

    vessel: str = Field(description='her station-keeping file: a shipped one by name ("supply", "semisub": '
                                    'configs/station) or a file (.toml)')
    mode: Literal["dp", "moored"] = Field("dp", description="on dynamic positioning (with moorings, if given: her "
                                                            "thrusters assist them), or held by moorings")
    moorings: str | None = Field(None, description='the mooring file, a shipped one by name ("semisub_8_chain": '
                                                   'configs/moorings) or a file (.toml): required when moored')
    turn_about: str | None = Field(
        None, description="on DP with moorings, a line's name: heading orders turn her about its far end, which "
                          "keeps its place in her body frame (a shuttle tanker's DP weathervaning about the FPSO's "
                          "stern, where her hawser is made fast); absent: she turns about her origin")
    pull_kn: Annotated[float, Quantity("kN", ge=0.0, le=5000.0)] = Field(
        0.0, description="moored: a constant pull astern on her own engines, as a shuttle tanker keeps her hawser "
                         "taut (20 to 50 t)")
    footprint_m: Annotated[float | None, Quantity("m", gt=0.0, le=500.0)] = Field(
        None, description='the alarm radius around the set point: a criterion "footprint" (offset_max_m) unless '
                          f"the scenario names one; absent: no alarm, the plots' circle {FOOTPRINT_M:g} m")

    @model_validator(mode="after")
    def _moorings_when_moored(self) -> StationOptions:
        if self.mode == "moored" and self.moorings is None:
            raise _refuse("moorings", "required by mode = \"moored\"")
        if self.turn_about is not None and (self.mode != "dp" or self.moorings is None):
            raise _refuse("turn_about", "a line to turn about needs mode = \"dp\" and her moorings")
        if self.pull_kn and self.mode != "moored":
            raise _refuse("pull_kn", "a pull astern is a moored vessel's: on DP her thrusters hold her")
        return self


MAX_VESSELS = 16
"""Other vessels and structures in one scenario."""
MAX_RANGE_M = 100_000.0
"""How far from own-ship's start another body may be placed (m)."""
BODY_KINDS = ("ship", "fpso", "moored", "platform", "buoy")
Position = Annotated[list[float], Quantity("m", ge=-MAX_RANGE_M, le=MAX_RANGE_M, what="metres east and north"),
                     Field(min_length=2, max_length=2)]


class OtherVesselOptions(Section):
    """``[[vessels]]``: another body in the same sea. A ``ship`` sails her route (straight on at ``speed_kn``, or
    through ``waypoints_m`` with turns of ``turn_radius_m``) and responds through her own RAO table; an ``fpso``
    lies on her turret at ``position_m``, her head to the waves; a ``moored`` body (a semisubmersible rig) lies at its
    position on its heading and responds through its RAO table; a ``platform`` stands on the sea bed (drawn from
    its ``visual_mesh``); a ``buoy`` follows the water's surface. Positions are in metres east and north of
    own-ship's start. Bodies do not shelter one another from the waves."""

    name: Annotated[str, AfterValidator(_identifier), Field(max_length=40)] = Field(
        description="what the record's columns (NAME_east_m, ...), the chart and the radar call it")
    kind: Literal[BODY_KINDS] = Field(description="ship, fpso, moored, platform or buoy")
    position_m: Position = Field(description="where she starts (a ship) or lies, [east, north] from own-ship's start")
    rao: str | None = Field(None, description="RAO file of a ship, an FPSO or a moored body (as vessel.rao)")
    heading_deg: Annotated[float | None, Quantity("deg", ge=0.0, le=360.0, what="a compass heading")] = Field(
        None, description="compass heading of the bow (absent: a ship's first leg; an FPSO's head to the first "
                          "wave system; a platform's 0)")
    speed_kn: Annotated[float, Quantity("kn", ge=0.0, le=MAX_SPEED_KN)] = Field(0.0, description="a ship's speed")
    waypoints_m: Annotated[list[Position], Field(max_length=64)] = Field(
        default_factory=list, description="a ship's route after position_m, [[east, north], ...] (m)")
    turn_radius_m: Annotated[float, Quantity("m", gt=10.0, le=10_000.0)] = Field(
        500.0, description="the radius of a ship's turns at her waypoints")
    manoeuvring: str | None = Field(
        None, description='a ship\'s manoeuvring model, a shipped one by name ("tanker", "s175", "kvlcc2", '
                          '"supply": configs/vessels) or a file (.toml): her autopilot steers her route from each '
                          "wheel-over point, and the instructor may drive her (events' vessel); absent: she sails "
                          "the route exactly")
    hull: str | None = Field(None, description="a hull mesh in metres and body axes: a ship drawn from it")
    visual_mesh: str | None = Field(None, description="a mesh in metres and body axes drawn for the body")
    topsides_rgb: Annotated[list[int] | None, Quantity("", ge=0, le=255, what="colour levels"),
                            Field(min_length=3, max_length=3)] = Field(
        None, description="hull colour of a ship drawn from her hull, [r, g, b] 0..255")
    nav_lights: Literal[NAV_LIGHTS] = Field("underway", description="the navigation lights she shows (as vessel's)")

    @model_validator(mode="after")
    def _what_each_kind_takes(self) -> OtherVesselOptions:
        moves = self.kind in ("ship", "fpso", "moored")
        if moves and self.rao is None:
            raise _refuse("rao", f"a {self.kind} responds to the waves through her RAO file: give rao")
        if not moves and self.rao is not None:
            raise _refuse("rao", f"a {self.kind} has no RAO table: leave rao out")
        if self.kind != "ship":
            for key in ("speed_kn", "waypoints_m", "turn_radius_m", "manoeuvring"):
                if key in self.model_fields_set:
                    raise _refuse(key, f"a {self.kind} does not sail: {key} is a ship's")
        if self.manoeuvring is not None and self.speed_kn <= 0.0:
            raise _refuse("manoeuvring", "a ship under her manoeuvring model sails her route: give speed_kn > 0")
        if self.waypoints_m and self.heading_deg is not None:
            raise _refuse("heading_deg", "a ship on waypoints heads along her first leg: leave heading_deg out")
        if self.kind == "platform" and self.visual_mesh is None:
            raise _refuse("visual_mesh", "a platform is drawn from its mesh: give visual_mesh")
        if moves and self.hull is None and self.visual_mesh is None:
            raise _refuse("hull", f"a {self.kind} is drawn from her hull or her visual_mesh: give one")
        return self


CAMERA_BODIES = ("ownship",)
"""What a camera can be mounted on."""
MAX_CAMERAS = 16


class CameraOptions(Section):
    """``[[cameras]]``: a named viewpoint on board own-ship or another body (``[[vessels]]``), moving with its six
    degrees of freedom: the crane operator's cab looking at the lift, the helideck officer at the deck's edge, the
    FPSO's loading master watching the tanker come in. The viewer's key 4 goes through them in turn;
    ``--camera NAME`` starts on one. It looks at ``target``, or along ``look_azimuth_deg`` and
    ``look_elevation_deg``."""

    name: Annotated[str, Field(min_length=1, max_length=40)] = Field(description="what the viewer calls it")
    body: Annotated[str, Field(min_length=1, max_length=40)] = Field(
        "ownship", description="what it is mounted on: ownship, or the name of one of [[vessels]]")
    position_m: Point = Field(description="where the eye is, [x, y, z] in its body's frame (x forward, y port, z up)")
    target: str | Point | None = Field(
        None, description="what it looks at: [x, y, z] in its body's frame, or (on ownship) a [vessel.points] name")
    look_azimuth_deg: Annotated[float | None, Quantity("deg", ge=-180.0, le=180.0)] = Field(
        None, description="without target: where it looks, from the bow, positive to starboard (absent: 0)")
    look_elevation_deg: Annotated[float | None, Quantity("deg", ge=-89.0, le=89.0)] = Field(
        None, description="without target: above the body's horizontal, negative down (absent: -10)")
    fov_deg: Annotated[float, Quantity("deg", ge=5.0, le=120.0)] = Field(60.0, description="vertical field of view")

    @model_validator(mode="after")
    def _one_way_to_look(self) -> CameraOptions:
        if self.name in CAMERAS:
            raise _refuse("name", f"{self.name!r} is the viewer's own camera: give another name")
        if self.target is not None and {"look_azimuth_deg", "look_elevation_deg"} & self.model_fields_set:
            raise _refuse("target", "give a target or the look angles, not both")
        return self


class BriefingOptions(Section):
    """``[briefing]``: what the trainees are told before the exercise, and its objectives."""

    text: Annotated[str, Field(min_length=1, max_length=4000)] = Field(description="the briefing")
    objectives: Annotated[list[ObjectiveOptions], Field(max_length=MAX_CRITERIA)] = Field(
        default_factory=list, description="the exercise's objectives (list of tables)")


class ScenarioFile(Section):
    """A whole scenario file."""

    ocean: OceanOptions = Field(default_factory=OceanOptions, description="the FFT cascades")
    sea: Annotated[list[SeaOptions], Field(max_length=MAX_WAVE_SYSTEMS), AfterValidator(_at_least_one)] = Field(
        default_factory=list, validate_default=True, description=f"1 to {MAX_WAVE_SYSTEMS} wave systems")
    vessel: VesselOptions | None = Field(None, description="the vessel; absent: a sea only")
    run: RunOptions = Field(default_factory=RunOptions, description="the run")
    environment: EnvironmentOptions = Field(default_factory=EnvironmentOptions, description="light and air")
    events: Annotated[list[EventOptions], Field(max_length=MAX_EVENTS)] = Field(
        default_factory=list, description="the exercise's timeline")
    criteria: Annotated[list[CriterionOptions], Field(max_length=MAX_CRITERIA)] = Field(
        default_factory=list, description="motion limits evaluated live and by marinesim assess")
    briefing: BriefingOptions | None = Field(None, description="the exercise's briefing and objectives")
    station: StationOptions | None = Field(None, description="station keeping: DP or moorings under the weather")
    crane: CraneOptions | None = Field(None, description="own-ship's crane and its load on the wire")
    helicopter: HelicopterOptions | None = Field(None, description="a helicopter approaching own-ship's helideck")
    cameras: Annotated[list[CameraOptions], Field(max_length=MAX_CAMERAS)] = Field(
        default_factory=list, description="named viewpoints on board (viewer key 4, --camera NAME)")
    vessels: Annotated[list[OtherVesselOptions], Field(max_length=MAX_VESSELS)] = Field(
        default_factory=list, description=f"other ships, an FPSO, platforms and buoys (at most {MAX_VESSELS})")

    @model_validator(mode="after")
    def _station_has_a_vessel_at_rest(self) -> ScenarioFile:
        if self.station is not None:
            if self.vessel is None:
                raise _refuse("station", "station keeping needs a [vessel]")
            if self.vessel.speed_kn > 0.0:
                raise _refuse("vessel.speed_kn", f"a vessel keeping station has no speed, got {self.vessel.speed_kn:g}")
            if self.vessel.manoeuvring not in (None, "station"):
                raise _refuse("vessel.manoeuvring", "a vessel keeping station ([station]) is steered by her DP or "
                                                    "held by her lines: leave manoeuvring out")
        bodies = [body.name for body in self.vessels]
        for i, body in enumerate(self.vessels):
            if self.vessel is None:
                raise _refuse(f"vessels[{i}]", "other vessels sail around own-ship: the scenario needs a [vessel]")
            if bodies.index(body.name) != i:
                raise _refuse(f"vessels[{i}].name", f"{body.name!r} names an earlier vessel too")
            if body.name in self.vessel.points or body.name in (*CAMERA_BODIES, "crane", "helicopter"):
                raise _refuse(f"vessels[{i}].name", f"{body.name!r} is taken (ownship, crane, helicopter or one of "
                                                    "[vessel.points]: the record's columns begin with it)")
        if self.crane is not None:
            if self.vessel is None:
                raise _refuse("crane", "a crane stands on a [vessel]")
            if self.crane.landing_point is not None and self.crane.landing_point not in self.vessel.points:
                raise _refuse("crane.landing_point", f"{self.crane.landing_point!r} is not one of [vessel.points] "
                                                     f"({', '.join(self.vessel.points) or 'none'})")
        for i, event in enumerate(self.events):
            if (event.hoist_m_s is not None or event.slew_deg_s is not None) and self.crane is None:
                raise _refuse(f"events[{i}].{'hoist_m_s' if event.hoist_m_s is not None else 'slew_deg_s'}",
                              "hoist and slew are orders to a crane: the scenario has no [crane]")
        deck = self.helicopter.deck_point if self.helicopter is not None else None
        if deck is not None and (self.vessel is None or deck not in self.vessel.points):
            raise _refuse("helicopter.deck_point", f"{self.helicopter.deck_point!r} is not one of [vessel.points] "
                                                   f"({', '.join(self.vessel.points) if self.vessel else 'none'})")
        if self.helicopter is not None and self.helicopter.start_s >= self.run.duration_s:
            raise _refuse("helicopter.start_s", f"{self.helicopter.start_s:g} s is not before the run's end "
                                                f"(run.duration_s {self.run.duration_s:g} s)")
        for i, event in enumerate(self.events):
            if event.helicopter is not None and self.helicopter is None:
                raise _refuse(f"events[{i}].helicopter", "the scenario has no [helicopter]")
            driven = [o.name for o in self.vessels if o.manoeuvring is not None]
            if event.vessel is not None and event.vessel not in driven:
                raise _refuse(f"events[{i}].vessel", f"{event.vessel!r} is not a ship of [[vessels]] under her "
                                                     f"manoeuvring model ({', '.join(driven) or 'none'})")
        for i, criterion in enumerate(self.criteria):
            if criterion.quantity in CRANE_QUANTITIES and self.crane is None:
                raise _refuse(f"criteria[{i}].quantity", f"{criterion.quantity} is a crane's load's: the scenario has "
                                                         "no [crane]")
        names = [camera.name for camera in self.cameras]
        for i, camera in enumerate(self.cameras):
            if self.vessel is None:
                raise _refuse(f"cameras[{i}].body", "a camera on board needs a [vessel]")
            if names.index(camera.name) != i:
                raise _refuse(f"cameras[{i}].name", f"{camera.name!r} names an earlier camera too")
            if camera.body not in (*CAMERA_BODIES, *bodies):
                raise _refuse(f"cameras[{i}].body", f"{camera.body!r} is not 'ownship' or one of [[vessels]] "
                                                    f"({', '.join(bodies) or 'none'})")
            if isinstance(camera.target, str) and camera.body not in CAMERA_BODIES:
                raise _refuse(f"cameras[{i}].target", f"{camera.target!r}: a point's name is own-ship's; on "
                                                      f"{camera.body!r} give [x, y, z] in its frame or the look angles")
            if isinstance(camera.target, str) and camera.target not in self.vessel.points:
                raise _refuse(f"cameras[{i}].target", f"{camera.target!r} is not one of [vessel.points] "
                                                      f"({', '.join(self.vessel.points) or 'none'})")
        for i, criterion in enumerate(self.criteria):
            if criterion.quantity in STATION_QUANTITIES and self.station is None:
                raise _refuse(f"criteria[{i}].quantity", f"{criterion.quantity} is a vessel keeping station's: the "
                                                         "scenario has no [station]")
        for i, event in enumerate(self.events):
            if (event.fault is not None or event.set_north_m is not None or event.set_east_m is not None) \
                    and self.station is None:
                key = "fault" if event.fault is not None else "set_north_m" if event.set_north_m is not None \
                    else "set_east_m"
                raise _refuse(f"events[{i}].{key}", "faults and set points are a station-keeping vessel's: the "
                                                    "scenario has no [station]")
        return self

    @model_validator(mode="after")
    def _criteria_and_events_fit(self) -> ScenarioFile:
        points = self.vessel.points if self.vessel is not None else {}
        names: set[str] = set()
        for i, criterion in enumerate(self.criteria):
            where = f"criteria[{i}]"
            if self.vessel is None:
                raise _refuse(where, "criteria need a [vessel]")
            try:
                check_point(criterion.quantity, criterion.point, points)
            except ParameterError as error:
                raise _refuse(f"{where}.point", str(error)) from None
            name = criterion.name or default_name(criterion.quantity, criterion.point)
            if name in names:
                raise _refuse(f"{where}.name", f"{name!r} names two criteria")
            names.add(name)
            window = criterion.window_s or QUANTITIES[criterion.quantity].window_s
            if window / self.run.dt_s > MAX_WINDOW_ROWS:
                raise _refuse(f"{where}.window_s", f"{window:g} s at run.dt_s {self.run.dt_s:g} s is more than "
                                                   f"{MAX_WINDOW_ROWS} rows")
            if QUANTITIES[criterion.quantity].dose is not None and self.run.dt_s > MAX_WF_DT_S:
                raise _refuse(where, f"{criterion.quantity} filters the acceleration up to 0.63 Hz: it needs "
                                     f"run.dt_s <= {MAX_WF_DT_S:g} s, got {self.run.dt_s:g}")
        for i, objective in enumerate(self.briefing.objectives if self.briefing else []):
            if objective.vessel is not None and objective.vessel not in [body.name for body in self.vessels]:
                raise _refuse(f"briefing.objectives[{i}].vessel", f"{objective.vessel!r} names none of [[vessels]]")
            for name in objective.criteria:
                if name not in names:
                    raise _refuse(f"briefing.objectives[{i}].criteria", f"{name!r} names no criterion "
                                                                        f"(known: {', '.join(sorted(names)) or 'none'})")
        previous = 0.0
        for i, event in enumerate(self.events):
            where = f"events[{i}]"
            if event.at_s is not None:
                if event.at_s < previous:
                    raise _refuse(f"{where}.at_s", f"{event.at_s:g} s comes before the event before it "
                                                   f"({previous:g} s): give events in time order")
                if event.at_s > self.run.duration_s:
                    raise _refuse(f"{where}.at_s", f"{event.at_s:g} s is after the run's end "
                                                   f"(run.duration_s {self.run.duration_s:g} s)")
                previous = event.at_s
            if self.vessel is None and any(getattr(event, key) is not None for key in ORDERS):
                raise _refuse(where, f"{', '.join(ORDERS)} are orders to a [vessel]: the scenario has none")
            if event.when is not None:
                if self.vessel is None:
                    raise _refuse(f"{where}.when", "a condition watches the vessel's motions: it needs a [vessel]")
                try:
                    watched(parse_condition(event.when), [Criterion(c.quantity, point=c.point, name=c.name)
                                                          for c in self.criteria], points)
                except ParameterError as error:
                    raise _refuse(f"{where}.when", str(error)) from None
        return self


M = TypeVar("M", bound=BaseModel)


def read_small_file(path: Path, what: str) -> bytes:
    """The bytes of the ``what`` at ``path`` (a regular file within the size limit
    :data:`~marinesim.formats.SIZE_LIMITS` gives ``what``: a scenario's side file, read whole), or
    :class:`ScenarioError` naming it."""
    try:
        check_file(path, what)
        return path.read_bytes()
    except (FileFormatError, OSError) as error:
        raise ScenarioError(str(error)) from None


def validate(model: type[M], data: Any, where: str = "") -> M:
    """``data`` as ``model``, or :class:`ScenarioError` with the first error's key path (under ``where``)."""
    try:
        return model.model_validate(data)
    except ValidationError as error:
        raise ScenarioError(_message(model, error.errors()[0], where)) from None


_TYPES = {"float_type": "float", "int_type": "int", "string_type": "str", "list_type": "list",
          "dict_type": "a table", "model_type": "a table", "model_attributes_type": "a table",
          "finite_number": "a finite number"}


def _message(model: type[BaseModel], error: dict, where: str) -> str:
    """One line: the key path, then what is wrong with the value there."""
    loc = [part for part in error["loc"] if part != "[key]"]
    kind, got = error["type"], error.get("input")
    if kind == "rule":
        loc.append(error["ctx"]["key"])
    if kind == "missing":
        text = "required"
    elif kind == "extra_forbidden":
        text = f"unknown key (known: {', '.join(_section(model, loc[:-1]).model_fields)})"
    elif kind in _TYPES:
        text = f"expected {_TYPES[kind]}, got {got!r}"
    elif kind == "literal_error":
        text = f"expected {error['ctx']['expected']}, got {got!r}"
    elif kind == "too_long":
        count = error["ctx"].get("actual_length")
        text = f"at most {error['ctx']['max_length']} entries, got {count if count is not None else 'more'}"
    else:
        text = error["msg"]
    return f"{_path([where, *loc] if where else loc)}: {text}"


def _path(loc: list[str | int]) -> str:
    text = ""
    for part in loc:
        text += f"[{part}]" if isinstance(part, int) else (f".{part}" if text else str(part))
    return text


def _section(model: type[BaseModel], loc: list[str | int]) -> type[BaseModel]:
    """The model class at ``loc`` (keys and list indices) inside ``model``."""
    for part in loc:
        if isinstance(part, str):
            model = _model_in(model.model_fields[part].annotation)
    return model


def _model_in(annotation: Any) -> Any:
    """The model class an annotation holds (``M``, ``M | None``, ``list[M]``, ``Annotated[...]``)."""
    if isinstance(annotation, type) and issubclass(annotation, BaseModel):
        return annotation
    return next((m for m in map(_model_in, get_args(annotation)) if m is not None), None)


def reference() -> str:
    """The scenario keys as a markdown table, generated from the model (docs/SCENARIOS.md)."""
    rows = ["| section | key | type | unit | range | default | meaning |", "|---|---|---|---|---|---|---|"]
    for name, section_field in ScenarioFile.model_fields.items():
        title = f"[[{name}]]" if get_origin(section_field.annotation) is list else f"[{name}]"
        for key, field in _model_in(section_field.annotation).model_fields.items():
            where, shown = (f"[{name}.{key}]", "*name*") if get_origin(field.annotation) is dict else (title, key)
            rows.append(_row(where, shown, field))
            inner = [a for a in get_args(field.annotation) if isinstance(a, type) and issubclass(a, BaseModel)]
            for sub_key, sub_field in (inner[0].model_fields.items() if inner else ()):  # a list of tables
                rows.append(_row(f"{title} {key}[]", sub_key, sub_field))
    return "\n".join(rows) + "\n"


def _row(where: str, key: str, field: Any) -> str:
    """One key's row of :func:`reference`."""
    quantity = _quantity([*field.metadata, field.annotation])
    kind, choices = _type_name(field.annotation)
    span = (quantity.span(unit=False).removeprefix("in ") or "any") if quantity else choices
    return (f"| `{where}` | `{key}` | {kind} | {quantity.unit if quantity else ''} | {span} | {_default(field)} | "
            f"{field.description} |")


def _quantity(items: Any) -> Quantity | None:
    """The :class:`Quantity` among ``items`` or inside their type arguments."""
    for item in items:
        found = item if isinstance(item, Quantity) else _quantity(get_args(item))
        if found is not None:
            return found
    return None


def _type_name(annotation: Any) -> tuple[str, str]:
    """(type in words, the choices of a string key or '')."""
    origin, args = get_origin(annotation), [a for a in get_args(annotation) if a is not type(None)]
    if origin is Literal:
        return "str", ", ".join(args)
    if origin is list:
        inner = _type_name(args[0])[0]
        return "list of " + ("tables" if inner == "table" else inner), ""
    if origin is dict:
        return _type_name(args[1])[0], ""
    if args:
        return _type_name(args[0])
    if isinstance(annotation, type) and issubclass(annotation, BaseModel):
        return "table", ""
    if annotation is AwareDatetime:
        return "date-time", ""
    return annotation.__name__, ""


def _default(field: Any) -> str:
    if field.is_required():
        return "required"
    value = field.get_default(call_default_factory=True)
    return "absent" if value is None else f"`{json.dumps(value)}`"


MARKERS = ("<!-- scenario-reference:start -->\n", "<!-- scenario-reference:end -->")


def with_reference(readme: str) -> str:
    """``readme`` with the text between the scenario-reference :data:`MARKERS` replaced by :func:`reference`."""
    start, end = readme.index(MARKERS[0]) + len(MARKERS[0]), readme.index(MARKERS[1])
    return readme[:start] + reference() + readme[end:]

