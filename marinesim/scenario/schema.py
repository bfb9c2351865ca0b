"""Loading a scenario file: the TOML validated by :mod:`marinesim.scenario.model`, then the sea, the
vessel (RAO table, meshes) and the run built from it. Errors name the file and the key's path."""

from __future__ import annotations

import math
import re
import tomllib
from collections.abc import Callable
import dataclasses
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np

from marinesim import formats
from marinesim.angles import compass_to_math, math_to_compass, wave_compass_from_beta
from marinesim.constants import KNOT
from marinesim.criteria.interruptions import DEFAULT_TIPPING_COEFFICIENT
from marinesim.criteria.monitor import Condition, Criterion, parse_condition
from marinesim.criteria.quantities import QUANTITIES, STATION_QUANTITIES, Options, ochi_threshold_velocity
from marinesim.errors import FileFormatError, MarinesimError, ScenarioError
from marinesim.hull import Hull, VisualMesh, hydrostatics, load_hull, load_visual_mesh
from marinesim.manoeuvring.ship import Ship
from marinesim.manoeuvring.station import StationKeeping
from marinesim.offshore.crane import Crane, Lift, Load
from marinesim.offshore.route import Route
from marinesim.resources import resource_dir
from marinesim.scenario import examples
from marinesim.scenario.ship_file import load_ship, ship_from_hull
from marinesim.scenario.model import (FOOTPRINT_M, HULL_OPTIONS, VISUAL_MESH_OPTIONS, WAVE_PARAMETERS, WEATHER,
                                      CameraOptions, CraneOptions, CriterionOptions, EnvironmentOptions, EventOptions,
                                      HelicopterOptions, OceanOptions, OtherVesselOptions, RunOptions, ScenarioFile,
                                      SeaOptions, StationOptions, VesselOptions, validate, wind_of)
from marinesim.scenario.moorings_file import load_moorings
from marinesim.scenario.station_file import StationFile, load_station
from marinesim.station.dp import Dp
from marinesim.station.moorings import Moorings
from marinesim.station.vessel import Calm, Station
from marinesim.station.wind import WindLoads
from marinesim.vessel.drift import DriftTable
from marinesim.vessel.aqwa_drift import has_drift
from marinesim.sea.build import wave_system
from marinesim.sea.seastate import SeaState
from marinesim.vessel.body import RigidBody
from marinesim.vessel.rao import RaoTable, one_speed_note
from marinesim.vessel.read import read_rao


FOOTPRINT = "footprint"
"""The criterion a vessel keeping station gets from ``station.footprint_m`` when the scenario names none."""


@dataclass(frozen=True)
class Vessel:
    """The vessel of a scenario: its RAO table (read and checked), hull file, course, points, visual mesh."""

    rao_path: Path
    rao: RaoTable
    hull_path: Path | None
    hull: Hull | None                       # in the body frame, waterline at z = 0
    speed_m_s: float
    heading_deg: float                      # compass, where the bow points
    points: dict[str, tuple[float, float, float]]
    ship: Ship | StationKeeping = None      # her manoeuvring (:mod:`marinesim.manoeuvring`)
    wake_speeds_m_s: tuple[float, ...] = ()  # the vessel's speed (if > 0) and the extra wake speeds
    visual: VisualMesh | None = None        # drawn instead of the hull, body frame
    nav_lights: str = "underway"            # one of NAV_LIGHTS
    topsides_rgb: tuple[int, int, int] | None = None  # a ship drawn from its hull: its hull colour, 0..255
    deck_layout: str = "flat"               # ... and its deck: "flat" or "hatches"

    @property
    def speed_kn(self) -> float:
        return self.speed_m_s / KNOT


@dataclass(frozen=True)
class OtherVessel:
    """Another body of the scenario (``[[vessels]]``): its kind, its route (a ship's; the others lie at rest on
    theirs, at their position and heading), its RAO table (a ship's, an FPSO's), what is drawn of it."""

    name: str
    kind: str                               # one of model.BODY_KINDS
    route: Route                            # E frame, from own-ship's start
    rao_path: Path | None = None
    rao: RaoTable | None = None
    hull: Hull | None = None                # drawn from it (a ship), body frame
    visual: VisualMesh | None = None        # drawn instead, body frame
    topsides_rgb: tuple[int, int, int] | None = None
    nav_lights: str = "underway"
    ship: Ship | None = None                # a ship's manoeuvring model: she sails her route under it
    ship_path: Path | None = None           # ... read from this file

    @property
    def files(self) -> dict[str, Path]:
        """The files read for it, by role: a session log keeps their sha256."""
        return {f"{self.name} {role}": path for role, path in (("rao", self.rao_path), ("manoeuvring", self.ship_path))
                if path is not None}


DECK_ORDERS = ("hoist_m_s", "slew_deg_s", "helicopter")
"""The orders that go to the crane and the helicopter, not to the ship."""


@dataclass(frozen=True)
class Lifting:
    """Own-ship's crane and its load (``[crane]``): the wire paid out at the start (m), the landing deck: one of her
    points (body frame, m; the deck a plane at its height, everywhere under the load) or a fixed deck's height (m
    above the still water), or neither."""

    crane: Crane
    load: Load
    wire_m: float
    landing_point: tuple[float, float, float] | None = None
    landing_deck_m: float | None = None


@dataclass(frozen=True)
class Event:
    """A scripted change and/or message: at ``at_s`` (s) or when ``condition`` first holds. A sea change blends in
    over ``ramp_s`` (s); the orders (:attr:`orders`: ``None`` leaves that one as it is) act at once."""

    at_s: float | None
    condition: Condition | None
    ramp_s: float
    sea: SeaState | None = None
    speed_m_s: float | None = None
    heading_deg: float | None = None      # compass course for the autopilot
    message: str | None = None
    weather: dict[str, float] = field(default_factory=dict)
    """``[environment]`` keys it changes at once (:data:`~marinesim.scenario.model.WEATHER`)."""
    rudder_deg: float | None = None       # by hand, positive to starboard
    engine: str | None = None             # a telegraph order
    autopilot: bool | None = None
    fault: str | None = None              # an instructor's fault on a vessel keeping station
    set_north_m: float | None = None      # a DP's position set point, from the start
    set_east_m: float | None = None
    hoist_m_s: float | None = None        # the crane's hoist, positive up
    slew_deg_s: float | None = None       # the crane's slew, positive to port
    helicopter: str | None = None         # the deck's word to the helicopter (model.HELICOPTER_DECISIONS)
    vessel: str | None = None             # the orders are this other ship's (a [[vessels]] name)

    @property
    def orders(self) -> dict[str, float | str | bool]:
        """The orders to the ship (to ``vessel`` where named), as :meth:`Simulation.order`'s keywords."""
        asked = {"vessel": self.vessel, "speed_kn": None if self.speed_m_s is None else self.speed_m_s / KNOT,
                 "course_deg": self.heading_deg,
                 "rudder_deg": self.rudder_deg, "engine": self.engine, "autopilot": self.autopilot,
                 "set_north_m": self.set_north_m, "set_east_m": self.set_east_m, "fault": self.fault,
                 "hoist_m_s": self.hoist_m_s, "slew_deg_s": self.slew_deg_s, "helicopter": self.helicopter}
        return {key: value for key, value in asked.items() if value is not None}

    @property
    def changes(self) -> bool:
        return self.sea is not None or bool(self.orders)

    def describe(self) -> str:
        """The event in a few words, e.g. ``at 300 s: sea Hs 4.00 m Tp 9.0 s over 30 s; rudder 20 deg``."""
        parts = []
        if self.sea is not None:
            parts.append(f"sea Hs {self.sea.hs:.2f} m Tp {self.sea.tp:.1f} s over {self.ramp_s:g} s")
        first_order = len(parts)
        if self.speed_m_s is not None:
            parts.append(f"speed {self.speed_m_s / KNOT:.3g} kn")
        if self.heading_deg is not None:
            parts.append(f"course {self.heading_deg:g} deg")
        if self.rudder_deg is not None:
            side = "to starboard" if self.rudder_deg > 0 else "to port" if self.rudder_deg < 0 else "midships"
            parts.append(f"rudder {abs(self.rudder_deg):g} deg {side}")
        if self.engine is not None:
            parts.append(self.engine)
        if self.autopilot is not None:
            parts.append(f"autopilot {'on' if self.autopilot else 'off'}")
        if self.set_north_m is not None or self.set_east_m is not None:
            parts.append(f"set point {self.set_north_m or 0.0:g} m N {self.set_east_m or 0.0:g} m E")
        if self.fault is not None:
            parts.append(f"fault {self.fault}")
        if self.vessel is not None and len(parts) > first_order:
            parts[first_order] = f"{self.vessel}: {parts[first_order]}"
        change = ", ".join(parts)
        words = {"visibility_m": "visibility {:g} m", "cloud_cover_oktas": "cloud {:g} oktas",
                 "wind_speed_m_s": "wind {:g} m/s", "rain_mm_h": "rain {:g} mm/h"}
        weather = " ".join(words[key].format(value) for key, value in self.weather.items())
        change = "; ".join(p for p in (change, weather) if p)
        trigger = f"at {self.at_s:g} s" if self.at_s is not None else f"when {self.condition}"
        return f"{trigger}: " + "; ".join(p for p in (change, self.message and repr(self.message)) if p)


@dataclass(frozen=True)
class Objective:
    """An objective as briefed (``text``), the names of the criteria that judge it or that its ``decision`` is about
    (:data:`~marinesim.scenario.model.DECISIONS`; None: met while none is exceeded), and a decision's ``within_s``."""

    text: str
    criteria: tuple[str, ...] = ()
    decision: str | None = None
    within_s: float | None = None
    vessel: str | None = None               # give_way: the vessel to keep out of the way of
    passing_m: float | None = None          # give_way: the least passing distance (m)


@dataclass(frozen=True)
class Briefing:
    """What the trainees are told (``text``) and the objectives."""

    text: str
    objectives: tuple[Objective, ...] = ()


def briefing_paragraphs(text: str) -> list[list[str]]:
    """A briefing's ``text`` (wrapped by hand in its TOML string) as its paragraphs (split at blank lines), each as
    the lines to show: the wrapped lines joined, a line that starts a list item ('- ', '* ', '1. ') on its own."""
    out = []
    for block in re.split(r"\n\s*\n", text.strip()):
        lines: list[str] = []
        for line in (line.strip() for line in block.splitlines()):
            if not line:
                continue
            if lines and not re.match(r"([-*\u2022]|\d+[.)])\s", line):
                lines[-1] += " " + line
            else:
                lines.append(line)
        if lines:
            out.append(lines)
    return out


@dataclass(frozen=True)
class Camera:
    """A named camera (``[[cameras]]``) on ``body``, ``"ownship"`` or another body's name (``[[vessels]]``): the eye
    at ``point`` (that body's frame, m), looking ``look_yaw_deg`` from its bow (positive to port, as the body frame
    turns) and ``look_pitch_deg`` above its horizontal, with a vertical field of view ``fov_deg``."""

    name: str
    point: tuple[float, float, float]
    look_yaw_deg: float
    look_pitch_deg: float
    fov_deg: float
    target: tuple[float, float, float] | None = None
    """What it looks at (its body's frame, m), where the scenario names it."""
    body: str = "ownship"


def _camera(options: CameraOptions, points: dict[str, tuple[float, float, float]]) -> Camera:
    """The camera ``options`` asks for, its look turned towards its target where it names one (a name: one of
    own-ship's ``points``)."""
    eye, target = np.asarray(options.position_m, float), None
    if options.target is None:
        yaw, pitch = -(options.look_azimuth_deg or 0.0), options.look_elevation_deg
        pitch = -10.0 if pitch is None else pitch
    else:
        target = np.asarray(points[options.target] if isinstance(options.target, str) else options.target, float)
        look = target - eye
        if not np.any(look):
            raise ScenarioError(f"cameras: {options.name!r} is at its own target")
        yaw, pitch = math.degrees(math.atan2(look[1], look[0])), math.degrees(math.atan2(look[2],
                                                                                        math.hypot(*look[:2])))
    return Camera(options.name, tuple(float(v) for v in eye), float(yaw), float(pitch), options.fov_deg,
                  None if target is None else tuple(float(v) for v in target), options.body)


@dataclass(frozen=True)
class Scenario:
    """A validated scenario: the sea state, the ocean's options, the vessel (if any), the run, the
    exercise's events (in file order) and criteria; ``notes``: lines for the user on what it asks of its files (the
    RAO table's warnings, a table of one speed used far from it, :func:`_speed_notes`)."""

    path: Path
    sea: SeaState
    ocean: OceanOptions
    run: RunOptions
    vessel: Vessel | None = None
    events: tuple[Event, ...] = ()
    criteria: tuple[Criterion, ...] = ()
    briefing: Briefing | None = None
    environment: EnvironmentOptions = EnvironmentOptions()
    notes: tuple[str, ...] = ()
    station: StationSetup | None = None
    scripted: tuple[tuple[str, str], ...] = ()
    """(criterion name, "exceeded" or "within"): what the exercise is built to show (``[[criteria]] scripted``)."""
    cameras: tuple[Camera, ...] = ()
    """The named cameras on board (``[[cameras]]``)."""
    others: tuple[OtherVessel, ...] = ()
    """The other vessels and structures (``[[vessels]]``)."""
    lifting: Lifting | None = None
    """Own-ship's crane and its load (``[crane]``)."""
    helicopter: HelicopterOptions | None = None
    """A helicopter approaching her helideck (``[helicopter]``)."""

    @property
    def name(self) -> str:
        return self.path.stem

    @property
    def wind(self) -> tuple[float, float]:
        """The wind at the start (m/s at 10 m, compass deg it comes from): the environment's, else the first wave
        system's (:func:`~marinesim.scenario.model.wind_of`)."""
        x, y, speed = wind_of(self.environment, self.sea)
        return speed, (math_to_compass(math.atan2(y, x)) + 180.0) % 360.0 if speed > 0.0 else 0.0


@dataclass(frozen=True)
class StationSetup:
    """A vessel keeping station (``[station]``): her file, what it names read (wind loads, drift table), her
    moorings, and the footprint (m)."""

    options: StationOptions
    file: StationFile
    path: Path
    wind: WindLoads
    drift: DriftTable | None
    moorings: Moorings | None
    files: dict[str, Path] = field(default_factory=dict)
    """The files read, by role (station, wind, drift, moorings): a session log keeps their sha256."""

    @property
    def footprint_m(self) -> float:
        """The footprint's radius (m): the scenario's alarm radius, else the plots' :data:`FOOTPRINT_M`."""
        return self.options.footprint_m if self.options.footprint_m is not None else FOOTPRINT_M


def load_scenario(path: str | Path) -> Scenario:
    """Read and validate ``path`` (a file, or a shipped scenario by name: ``crane_lift``); raise
    :class:`ScenarioError` naming the file and the key."""
    path = examples.resolve(path)
    try:
        formats.check_file(path, "scenario file")
        data = tomllib.loads(path.read_text(encoding="utf-8-sig"))  # a byte-order mark is no TOML error
    except FileFormatError as error:
        raise ScenarioError(str(error)) from None
    except (tomllib.TOMLDecodeError, UnicodeDecodeError) as error:
        raise ScenarioError(f"{path}: not valid TOML: {error}") from None
    except RecursionError:  # tomllib reads nested arrays and tables recursively
        raise ScenarioError(f"{path}: not valid TOML: arrays or tables nested too deeply") from None
    try:
        return build_scenario(path, validate(ScenarioFile, data))
    except ScenarioError as error:
        raise ScenarioError(f"{path}: {error}") from None


def with_run(scenario: Scenario, duration: float | None = None, dt: float | None = None,
             seed: int | None = None) -> Scenario:
    """``scenario`` with its run options (s, s, -) overridden, validated as in the scenario file."""
    given = {"duration_s": duration, "dt_s": dt, "seed": seed}
    run = validate(RunOptions, scenario.run.model_dump() | {k: v for k, v in given.items() if v is not None}, "run")
    return dataclasses.replace(scenario, run=run)


def build_scenario(path: Path, file: ScenarioFile) -> Scenario:
    """The scenario of the validated ``file``, its relative paths read from the folder of ``path`` (the scenario
    file, or where a scenario made from options is saved)."""
    depth = math.inf if file.ocean.depth_m is None else file.ocean.depth_m
    vessel = None if file.vessel is None else _vessel(path, file.vessel)
    if vessel is not None:
        draft, named = ((-float(vessel.hull.vertices[:, 2].min()), "vessel.hull") if vessel.hull is not None
                        else (vessel.rao.draft, "vessel.rao"))
        if draft is not None and depth <= draft:
            raise ScenarioError(f"ocean.depth_m: {depth:g} m is not deeper than the vessel's draft ({draft:.4g} m, "
                                f"{named}): the keel would be on the sea bed")
    sea = _sea("sea", file.sea, depth, "ocean.depth_m")
    station = None
    if file.station is not None:
        station = _station(path, file.station, vessel, depth)
        vessel = dataclasses.replace(vessel, ship=_station_vessel(station, vessel))
    others = tuple(_other(path, f"vessels[{i}]", o, sea) for i, o in enumerate(file.vessels))
    events = tuple(_event(f"events[{i}]", e, depth, vessel, others) for i, e in enumerate(file.events))
    criteria = tuple(_criterion(f"criteria[{i}]", c, vessel) for i, c in enumerate(file.criteria))
    if station is not None and station.options.footprint_m is not None and not any(
            c.quantity in STATION_QUANTITIES for c in criteria):
        taken = {c.label for c in criteria}
        name = FOOTPRINT if FOOTPRINT not in taken else f"{FOOTPRINT} {station.footprint_m:g} m"
        criteria += (Criterion("offset_max_m", station.footprint_m, name=name),)
    briefing = None if file.briefing is None else Briefing(
        file.briefing.text.strip(), tuple(Objective(o.text, tuple(o.criteria), o.decision, o.within_s, o.vessel,
                                                    o.passing_m)
                                          for o in file.briefing.objectives))
    notes = () if vessel is None else vessel.rao.warnings + _speed_notes(vessel, events)
    scripted = tuple((c.label, options.scripted) for c, options in zip(criteria, file.criteria) if options.scripted)
    cameras = tuple(_camera(c, vessel.points) for c in file.cameras)
    lifting = None if file.crane is None else _checked("crane", lambda: _lifting(file.crane, vessel, depth))
    return Scenario(path.resolve(), sea, file.ocean, file.run, vessel, events, criteria, briefing, file.environment,
                    notes, station, scripted, cameras, others, lifting, file.helicopter)


def _lifting(options: CraneOptions, vessel: Vessel, depth: float) -> Lifting:
    """The crane and its load, checked against its load chart and the water's depth."""
    crane = Crane(pedestal_m=tuple(options.pedestal_m), boom_height_m=options.boom_height_m, radius_m=options.radius_m,
                  slew_deg=options.slew_deg, hoist_speed_m_s=options.hoist_speed_m_s,
                  slew_rate_deg_s=options.slew_rate_deg_s, max_wire_m=options.max_wire_m,
                  min_wire_m=options.min_wire_m, load_chart=tuple(tuple(row) for row in options.load_chart))
    load = Load(mass_kg=options.load_t * 1000.0, wire_ea_n=options.wire_ea_n,
                damping_ratio=options.wire_damping_pct / 100.0, swing_damping_ratio=options.tag_lines_pct / 100.0)
    Lift.check(crane, load, options.wire_m, None if math.isinf(depth) else depth)
    point = None if options.landing_point is None else vessel.points[options.landing_point]
    return Lifting(crane, load, options.wire_m, point, options.landing_deck_m)


def _other(path: Path, where: str, options: OtherVesselOptions, sea: SeaState) -> OtherVessel:
    """Another body: its RAO table read, its meshes loaded, its route laid (a ship's heading her first leg's; an
    FPSO's head to the first wave system)."""
    rao_path = rao = None
    if options.rao is not None:
        rao_path = _checked(f"{where}.rao", lambda: _file(path, options.rao))
        rao = _checked(f"{where}.rao", lambda: read_rao(rao_path))
        _check_speed(f"{where}.speed_kn", rao, options.speed_kn)
    heading = options.heading_deg
    if heading is None:
        heading = wave_compass_from_beta(sea.systems[0].beta) if options.kind == "fpso" else 0.0
    route = _checked(f"{where}.waypoints_m", lambda: Route(
        tuple(options.position_m), options.speed_kn * KNOT, compass_to_math(heading),
        np.array(options.waypoints_m, float).reshape(-1, 2), options.turn_radius_m))
    hull = visual = None
    if options.hull is not None:
        hull = _checked(f"{where}.hull", lambda: load_hull(_file(path, options.hull)))
    if options.visual_mesh is not None:
        visual = _checked(f"{where}.visual_mesh", lambda: load_visual_mesh(_file(path, options.visual_mesh)))
    topsides = tuple(options.topsides_rgb) if options.topsides_rgb is not None else None
    ship = ship_path = None
    if options.manoeuvring is not None:
        ship_path = _checked(f"{where}.manoeuvring", lambda: _named_file(path, options.manoeuvring, "vessels",
                                                                          "a shipped vessel"))
        _, ship = _checked(f"{where}.manoeuvring", lambda: load_ship(ship_path))
        if ship.autopilot is None:
            raise ScenarioError(f"{where}.manoeuvring: {ship.name} has no autopilot to steer her route")
        _checked(f"{where}.speed_kn", lambda: ship.rps_for_speed(options.speed_kn * KNOT))
    return OtherVessel(options.name, options.kind, route, rao_path, rao, hull, visual, topsides, options.nav_lights,
                       ship, ship_path)


def _station(path: Path, options: StationOptions, vessel: Vessel, depth: float) -> StationSetup:
    """The station-keeping vessel's file and what it names, her moorings in water ``depth`` (m)."""
    file_path = _checked("station.vessel", lambda: _named_file(path, options.vessel, "station"))
    file = _checked("station.vessel", lambda: load_station(file_path))
    files = {"station": file_path}
    wind = file.wind
    if wind.file is not None:
        files["wind"] = _checked("station.vessel", lambda: _file(file_path, wind.file))
        loads = _checked("station.vessel", lambda: WindLoads.from_file(
            files["wind"], wind.frontal_area_m2, wind.lateral_area_m2, file.length_m))
    else:
        loads = _checked("station.vessel", lambda: WindLoads.blendermann(
            wind.vessel_type, wind.frontal_area_m2, wind.lateral_area_m2, file.length_m, wind.lateral_centroid_m))
    drift_path = (_checked("station.vessel", lambda: _file(file_path, file.drift)) if file.drift is not None
                  else _checked("vessel.rao", lambda: _drift_beside(vessel.rao_path)))
    drift = None if drift_path is None else _checked("station.vessel", lambda: _read_drift(drift_path, file))
    if drift_path is not None:
        files["drift"] = drift_path
    if options.mode == "dp" and not file.thrusters:
        raise ScenarioError(f"station.mode: {file_path.name} gives no thrusters: she cannot keep station on DP")
    moorings = None
    if options.moorings is not None:
        mooring_path = _checked("station.moorings", lambda: _named_file(path, options.moorings, "moorings"))
        moorings = _checked("station.moorings", lambda: load_moorings(mooring_path, depth))
        files["moorings"] = mooring_path
        laid = math.degrees(moorings.heading) % 360.0
        # turning about a line's far end, its place in her body frame is taken on the moorings' heading: hers exactly
        if abs((laid - vessel.heading_deg + 180.0) % 360.0 - 180.0) > (1e-6 if options.turn_about else 0.5):
            raise ScenarioError(f"vessel.heading_deg: {vessel.heading_deg:g} deg, but the moorings "
                                f"({mooring_path.name}) are laid for a vessel heading {laid:g} deg")
        if options.turn_about is not None and options.turn_about not in moorings.names:
            raise ScenarioError(f"station.turn_about: {options.turn_about!r} is not a line of {mooring_path.name} "
                                f"(its lines: {', '.join(moorings.names)})")
    return StationSetup(options, file, file_path, loads, drift, moorings, files)


def _drift_beside(rao_path: Path) -> Path | None:
    """Her RAO set's own mean drift table, where it has one: a WAMIT run's .8 (momentum, better for a ship) or .9
    beside its .4, an AQWA listing's wave-drift pages, a NEMOH project's results/QTF/OUT_QTFM_N.dat."""
    suffix = rao_path.suffix.lower()
    if suffix == ".4":
        candidates = [rao_path.with_suffix(".8"), rao_path.with_suffix(".9")]
    elif suffix == ".cal":
        candidates = [rao_path.parent / "results" / "QTF" / "OUT_QTFM_N.dat"]
    elif suffix == ".lis":
        candidates = [rao_path] if has_drift(rao_path) else []
    else:
        candidates = []
    found = next((c for c in candidates if c.is_file()), None)
    if found is not None:
        formats.check_file(found)
    return found


def _read_drift(path: Path, file: StationFile) -> DriftTable:
    """The drift table at ``path`` by its format, with the station file's options for it."""
    fmt = formats.detect(path, "drift")
    given = {"ulen": file.drift_ulen_m, "axisymmetric": file.drift_axisymmetric}
    return formats.reader(fmt)(path, **{key: value for key, value in given.items() if key in fmt.options})


def _station_vessel(setup: StationSetup, vessel: Vessel) -> Station:
    """The :class:`Station` of ``setup`` in calm weather (the session gives her the scenario's)."""
    m, d = setup.file.matrices()
    thrusters = setup.file.thruster_set() if setup.options.mode == "dp" else None
    dp = None if thrusters is None else Dp(m, d, setup.file.tuning())
    return Station(setup.file.name, m, d, Calm(), thrusters, dp, setup.moorings, setup.options.pull_kn * 1e3,
                   setup.options.turn_about)


def _named_file(scenario: Path, name: str, folder: str, expected: str = "a shipped file") -> Path:
    """The side file ``name`` of a scenario: a bare name (no folder, no ``.toml``) is ``<folder>/<name>.toml`` of the
    scenario's own configuration tree (beside the scenario or its folder, as ``configs/`` ships and as ``marinesim
    examples copy`` lays out a copy, so that a copy's edits count), else of the shipped ones; anything else is a file
    relative to the scenario. ``expected`` says what a bare name may be, in the error that none is."""
    if "/" in name or "\\" in name or name.endswith(".toml"):
        return _file(scenario, name)
    here = scenario.resolve().parent
    for root in (here, here.parent, resource_dir("configs")):
        if (root / folder / f"{name}.toml").is_file():
            return root / folder / f"{name}.toml"
    shipped = sorted(p.stem for p in (resource_dir("configs") / folder).glob("*.toml"))
    raise ScenarioError(f"{name!r}: expected {expected} ({', '.join(shipped)}) or a file (.toml)")


def _sea(where: str, options: list[SeaOptions], depth: float, whole: str) -> SeaState:
    """The sea state of the wave systems ``options`` (``where`` in the file) in water ``depth`` (m);
    an error of the systems together is reported at ``whole``."""
    systems = [_checked(f"{where}[{i}]", lambda s=s: wave_system(
        s.type, from_deg=s.from_deg, depth=depth,
        **{WAVE_PARAMETERS[key]: getattr(s, key) for key in s.model_fields_set if key in WAVE_PARAMETERS}))
        for i, s in enumerate(options)]
    return _checked(whole, lambda: SeaState(tuple(systems), depth=depth))


def _event(where: str, options: EventOptions, depth: float, vessel: Vessel | None,
           others: tuple[OtherVessel, ...]) -> Event:
    sea = None if options.sea is None else _sea(f"{where}.sea", options.sea, depth, f"{where}.sea")
    speed = None if options.speed_kn is None else options.speed_kn * KNOT
    if options.vessel is not None:  # orders to another ship: hers, checked against her model and her RAO table
        other, = (o for o in others if o.name == options.vessel)
        if speed is not None:
            _check_speed(f"{where}.speed_kn", other.rao, options.speed_kn)
        vessel = dataclasses.replace(vessel, rao=other.rao, ship=other.ship, speed_m_s=other.route.speed,
                                     heading_deg=math_to_compass(other.route.pieces[0].heading))
    elif speed is not None:
        _check_speed(f"{where}.speed_kn", vessel.rao, options.speed_kn)
    condition = None if options.when is None else parse_condition(options.when)
    weather = {key: getattr(options, key) for key in WEATHER if getattr(options, key) is not None}
    event = Event(options.at_s, condition, options.ramp_s, sea, speed, options.heading_deg, options.message, weather,
                  options.rudder_deg, options.engine, options.autopilot, options.fault, options.set_north_m,
                  options.set_east_m, options.hoist_m_s, options.slew_deg_s, options.helicopter, options.vessel)
    if event.orders:  # an order the ship cannot carry out is refused now, not when it comes
        state, orders = vessel.ship.start(vessel.speed_m_s, math.radians(vessel.heading_deg))
        for key, value in event.orders.items():
            if key in DECK_ORDERS or key == "vessel":
                continue
            name = "heading_deg" if key == "course_deg" else key
            _checked(f"{where}.{name}", lambda: vessel.ship.order(orders, state, **{key: value}))
    return event


def _criterion(where: str, options: CriterionOptions, vessel: Vessel | None) -> Criterion:
    """The criterion ``options`` (at ``where`` in the file) asks for; a slamming threshold velocity not given is
    Ochi's for the ship's length (:func:`_length`)."""
    tipping = options.tipping_coefficient or DEFAULT_TIPPING_COEFFICIENT
    velocity = options.threshold_velocity_m_s
    if velocity is None and "threshold_velocity_m_s" in QUANTITIES[options.quantity].options:
        length = None if vessel is None else _length(vessel)[0]
        if length is None:
            raise ScenarioError(f"{where}.threshold_velocity_m_s: required by {options.quantity}: the ship's length L "
                                f"for Ochi's 0.093 sqrt(g L) is unknown (no vessel.hull, no length in the RAO file, "
                                f"no manoeuvring model)")
        velocity = ochi_threshold_velocity(length)
    return Criterion(options.quantity, options.limit, options.point, options.name, options.window_s, options.caution,
                     Options(options.threshold_m, tipping, velocity))


def _check_speed(where: str, rao: RaoTable, speed_kn: float) -> None:
    """Refuse a speed outside the RAO table's speeds; a table of one speed serves any (:func:`_speed_notes`
    notes one used far from its speed)."""
    low, high = rao.speed_range
    speed = speed_kn * KNOT
    if rao.speed.size > 1 and not low - 1e-6 <= speed <= high + 1e-6:
        raise ScenarioError(f"{where}: {speed_kn:g} kn is outside the RAO table's speeds "
                            f"{low / KNOT:.3g}..{high / KNOT:.3g} kn")


def _speed_notes(vessel: Vessel, events: tuple[Event, ...]) -> tuple[str, ...]:
    """Where the vessel's RAO table has one speed: a note for the vessel's speed and each event's speed order far
    from it (:func:`~marinesim.vessel.rao.one_speed_note`), each led by its key, on the ship's length
    (:func:`_length`)."""
    if vessel.rao.speed.size > 1:
        return ()
    asked = [("vessel.speed_kn", vessel.speed_m_s)] + [(f"events[{i}].speed_kn", event.speed_m_s)
                                                       for i, event in enumerate(events)
                                                       if event.speed_m_s is not None and event.vessel is None]
    length, length_from = _length(vessel)
    notes = [(where, one_speed_note(vessel.rao, speed, length, length_from)) for where, speed in asked]
    return tuple(f"{where}: {note}" for where, note in notes if note is not None)


def _length(vessel: Vessel) -> tuple[float | None, str]:
    """The ship's length for Froude numbers (m) and whose it is: the hull's (at the waterline, else overall,
    :attr:`~marinesim.hull.Hydrostatics.froude_length_m`), else the one the RAO file states, else her manoeuvring
    model's; (None, "") where none of them gives one."""
    if vessel.hull is not None:
        return hydrostatics(vessel.hull).froude_length_m, "the hull's"
    if vessel.rao.length is not None:
        return vessel.rao.length, "the RAO file's"
    if isinstance(vessel.ship, Ship):
        return vessel.ship.length_m, "the manoeuvring model's"
    return None, ""


def _rigid_body(options: VesselOptions) -> RigidBody:
    """The scenario's mass and external matrices (about the RAO table's reference point)."""
    def matrix(rows: list[list[float]] | None) -> np.ndarray | None:
        return None if rows is None else np.array(rows, dtype=float)
    return RigidBody(options.mass_kg, None if options.cog_m is None else tuple(options.cog_m),
                     None if options.radii_of_gyration_m is None else tuple(options.radii_of_gyration_m),
                     matrix(options.external_stiffness), matrix(options.external_damping))


def _vessel(path: Path, options: VesselOptions) -> Vessel:
    rao_path = _checked("vessel.rao", lambda: _file(path, options.rao))
    rao = _checked("vessel.rao", lambda: read_rao(rao_path, ulen=options.ulen_m,
                                                   roll_damping=options.roll_damping_pct / 100.0,
                                                   body=options.rao_body, rigid_body=_rigid_body(options),
                                                   accept_resonance=options.accept_resonance))
    if options.rao_speeds_kn is not None:
        rao = _checked("vessel.rao_speeds_kn", lambda: rao.at_speeds([v * KNOT for v in options.rao_speeds_kn]))
    _check_speed("vessel.speed_kn", rao, options.speed_kn)
    speed = options.speed_kn * KNOT
    hull_path, hull = _mesh(path, options, "hull", HULL_OPTIONS, load_hull)
    _, visual = _mesh(path, options, "visual_mesh", VISUAL_MESH_OPTIONS, load_visual_mesh)
    speeds_kn = ([options.speed_kn] if options.speed_kn > 0 else []) + options.wake_speeds_kn
    wake_speeds = tuple(sorted({v * KNOT for v in speeds_kn}))
    points = {name: (p[0], p[1], p[2]) for name, p in options.points.items()}
    topsides = tuple(options.topsides_rgb) if options.topsides_rgb is not None else None
    ship = _checked("vessel.manoeuvring", lambda: _ship(path, options, hull, speed))
    return Vessel(rao_path, rao, hull_path, hull, speed, options.heading_deg, points, ship, wake_speeds, visual,
                  options.nav_lights, topsides, options.deck_layout)


def _ship(path: Path, options: VesselOptions, hull: Hull | None, speed: float) -> Ship | StationKeeping:
    """The vessel's manoeuvring: her file's model, held on station, a model from the hull's main particulars, or
    (no hull) a steady course and speed; she must be able to hold the scenario's speed."""
    if options.manoeuvring == "station":
        if speed > 0.0:
            raise ScenarioError(f"a vessel held on station has no speed: vessel.speed_kn is {options.speed_kn:g}")
        return StationKeeping("the vessel")
    if options.manoeuvring is not None:
        _, ship = load_ship(_named_file(path, options.manoeuvring, "vessels", '"station", a shipped vessel'))
    elif hull is not None:
        ship = ship_from_hull(Path(options.hull).stem, hull, speed)
    else:
        return StationKeeping("the vessel", speed)
    ship.rps_for_speed(speed)
    return ship


def _mesh(path: Path, options: VesselOptions, key: str, names: dict[str, str],
          load: Callable[..., Any]) -> tuple[Path | None, Any]:
    """(file, loaded mesh) for ``vessel.<key>`` (relative to the scenario ``path``) with its options
    (scenario key -> ``load`` option), or (None, None) without it."""
    if getattr(options, key) is None:
        return None, None
    file = _checked(f"vessel.{key}", lambda: _file(path, getattr(options, key)))
    return file, _checked(f"vessel.{key}", lambda: load(file, **{names[n]: getattr(options, n) for n in names}))


def _file(scenario: Path, name: str) -> Path:
    """The file ``name`` (relative to the ``scenario`` file's folder), resolved once it is known to be a
    regular file (:func:`~marinesim.formats.check_file`)."""
    file = scenario.parent / name
    formats.check_file(file)
    return file.resolve()


def _checked(where: str, build: Callable[[], Any]) -> Any:
    try:
        return build()
    except MarinesimError as error:
        raise ScenarioError(f"{where}: {error}") from None
