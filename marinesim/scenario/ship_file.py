"""A vessel's manoeuvring file (``configs/vessels/*.toml``): her manoeuvring model and its coefficients, steering
gear, engine telegraph and autopilot, validated as a scenario is (one pydantic model; errors name the key), and the
:class:`~marinesim.manoeuvring.ship.Ship` built from it.

A model that goes unstable at hard-over (its speed, rate of turn or heel running away in a 35 deg turn from its
approach speed, :func:`marinesim.manoeuvring.trials.hard_over`) is refused here, once per file.
"""

from __future__ import annotations

import functools
import hashlib
import math
import tomllib
from pathlib import Path
from typing import Annotated, Literal

from pydantic import Field, model_validator

from marinesim.constants import KNOT, G
from marinesim.hull import Hull, hydrostatics
from marinesim.errors import MarinesimError, ParameterError, ScenarioError
from marinesim.manoeuvring.actuators import SOLAS_RUDDER_DEG, SOLAS_RUDDER_RATE_DEG_S, TELEGRAPH, Engine, SteeringGear
from marinesim.manoeuvring.autopilot import tuned
from marinesim.manoeuvring.clarke import Clarke
from marinesim.manoeuvring.container import SonNomotoContainer
from marinesim.manoeuvring.mmg import Mmg
from marinesim.manoeuvring.ship import Ship
from marinesim.manoeuvring.trials import hard_over
from marinesim.scenario.model import MAX_SPEED_KN, Quantity, Section, _refuse, read_small_file, validate

AHEAD_FRACTIONS = {"half_ahead": 0.75, "slow_ahead": 0.55, "dead_slow_ahead": 0.35}
ASTERN_FRACTIONS = {"dead_slow_astern": 0.35, "slow_astern": 0.5, "half_astern": 0.6, "full_astern": 0.7}
"""Telegraph orders not given, as fractions of full ahead's rpm (astern: usual for a fixed-pitch propeller on a
reversing diesel, which turns slower astern)."""

Coefficient = Annotated[float, Quantity()]
Negative = Annotated[float, Quantity(lt=0.0, what="a damping derivative")]
Fraction = Annotated[float, Quantity(ge=0.0, lt=1.0)]
Positive = Annotated[float, Quantity(gt=0.0)]
Length = Annotated[float, Quantity("m", gt=0.0, le=1000.0)]


class SteeringOptions(Section):
    """``[steering]``: the steering gear."""

    max_rudder_deg: Annotated[float, Quantity("deg", gt=0.0, le=45.0)] = Field(
        SOLAS_RUDDER_DEG, description="hard over, either side")
    rudder_rate_deg_s: Annotated[float, Quantity("deg/s", gt=0.0, le=20.0)] = Field(
        SOLAS_RUDDER_RATE_DEG_S, description="how fast the rudder turns (SOLAS: 35 to 30 deg in 28 s)")


class EngineOptions(Section):
    """``[engine]``: the telegraph's rpm and how fast the propeller follows."""

    full_ahead_rpm: Annotated[float, Quantity("rpm", gt=0.0, le=3000.0)] = Field(description="full ahead")
    half_ahead_rpm: Annotated[float | None, Quantity("rpm", gt=0.0, le=3000.0)] = None
    slow_ahead_rpm: Annotated[float | None, Quantity("rpm", gt=0.0, le=3000.0)] = None
    dead_slow_ahead_rpm: Annotated[float | None, Quantity("rpm", gt=0.0, le=3000.0)] = None
    dead_slow_astern_rpm: Annotated[float | None, Quantity("rpm", gt=0.0, le=3000.0)] = None
    slow_astern_rpm: Annotated[float | None, Quantity("rpm", gt=0.0, le=3000.0)] = None
    half_astern_rpm: Annotated[float | None, Quantity("rpm", gt=0.0, le=3000.0)] = None
    full_astern_rpm: Annotated[float | None, Quantity("rpm", gt=0.0, le=3000.0)] = None
    astern: bool = Field(True, description="whether the engine can go astern")
    astern_kt: Annotated[list[float], Quantity(ge=0.0, le=2.0), Field(min_length=2, max_length=2)] = Field(
        default_factory=lambda: [0.2, 0.25], description="backing thrust K_T = a0 + a1 J, [a0, a1]")
    time_constant_s: Annotated[float, Quantity("s", gt=0.0, le=600.0)] = Field(
        20.0, description="the propeller's rate follows an order with this lag")

    @model_validator(mode="after")
    def _telegraph_in_order(self) -> EngineOptions:
        rpm = self.telegraph()
        ahead = [rpm[name] for name in TELEGRAPH[4:] if name in rpm]
        astern = [rpm[name] for name in TELEGRAPH[:4] if name in rpm]
        if ahead != sorted(ahead) or astern != sorted(astern):
            raise _refuse("full_ahead_rpm", "the telegraph's rpm must grow from dead slow to full, ahead and astern")
        return self

    def telegraph(self) -> dict[str, float]:
        """Telegraph order -> rpm (astern negative), the orders not given from :data:`AHEAD_FRACTIONS` and
        :data:`ASTERN_FRACTIONS`."""
        full = self.full_ahead_rpm
        out = {"stop": 0.0, "full ahead": full}
        for key, fraction in AHEAD_FRACTIONS.items():
            out[key.replace("_", " ")] = getattr(self, f"{key}_rpm") or fraction * full
        if self.astern:
            for key, fraction in ASTERN_FRACTIONS.items():
                out[key.replace("_", " ")] = -(getattr(self, f"{key}_rpm") or fraction * full)
        return out


class AutopilotOptions(Section):
    """``[autopilot]``: the heading autopilot's limits (its gains come from the model by pole placement)."""

    rudder_limit_deg: Annotated[float, Quantity("deg", gt=0.0, le=45.0)] = Field(
        20.0, description="the most rudder it gives")
    rate_of_turn_deg_min: Annotated[float, Quantity("deg/min", gt=0.0, le=600.0)] = Field(
        30.0, description="the fastest it turns the ship to a new course")


class MmgOptions(Section):
    """``[mmg]``: the MMG standard method's particulars and coefficients (Yasukawa & Yoshimura 2015, their names)."""

    lpp_m: Length
    breadth_m: Length
    draft_m: Length
    volume_m3: Annotated[float, Quantity("m^3", gt=0.0, le=1e7)]
    x_g_m: Annotated[float, Quantity("m")] = 0.0
    k_zz: Annotated[float, Quantity(gt=0.0, le=1.0)] = 0.25
    m_x: Positive
    m_y: Positive
    j_z: Positive
    r_0: Positive
    x_vv: Coefficient
    x_vr: Coefficient
    x_rr: Coefficient
    x_vvvv: Coefficient
    y_v: Negative
    y_r: Coefficient
    y_vvv: Coefficient
    y_vvr: Coefficient
    y_vrr: Coefficient
    y_rrr: Coefficient
    n_v: Coefficient
    n_r: Negative
    n_vvv: Coefficient
    n_vvr: Coefficient
    n_vrr: Coefficient
    n_rrr: Coefficient
    d_p_m: Length
    t_p: Fraction
    w_p0: Fraction
    k_0: Positive
    k_1: Coefficient
    k_2: Coefficient
    x_p: Coefficient
    a_r_m2: Annotated[float, Quantity("m^2", gt=0.0, le=1e4)]
    h_r_m: Length
    t_r: Fraction
    a_h: Annotated[float, Quantity(ge=0.0, le=2.0)]
    x_h: Coefficient
    x_r: Coefficient
    gamma_r_port: Annotated[float, Quantity(gt=0.0, le=2.0)]
    gamma_r_starboard: Annotated[float, Quantity(gt=0.0, le=2.0)]
    l_r: Coefficient
    epsilon: Positive
    kappa: Annotated[float, Quantity(ge=0.0, le=2.0)]
    f_alpha: Positive
    c_1: Annotated[float, Quantity(ge=0.0, le=20.0)] = 2.0
    c_2_plus: Annotated[float, Quantity(gt=0.0, le=5.0)] = 1.6
    c_2_minus: Annotated[float, Quantity(gt=0.0, le=5.0)] = 1.1

    def model(self, astern_kt: tuple[float, float]) -> Mmg:
        keys = self.model_dump()
        renamed = {"lpp": "lpp_m", "breadth": "breadth_m", "draft": "draft_m", "volume": "volume_m3", "x_g": "x_g_m",
                   "d_p": "d_p_m", "a_r": "a_r_m2", "h_r": "h_r_m"}
        for new, old in renamed.items():
            keys[new] = keys.pop(old)
        return Mmg(**keys, astern_kt=astern_kt)


class SonNomotoOptions(Section):
    """``[son_nomoto]``: the S175 container ship of Son & Nomoto (1981) as MSS carries it; its coefficients are in
    :mod:`marinesim.manoeuvring.container`."""

    gm_m: Annotated[float, Quantity("m", gt=0.0, le=10.0)] = Field(0.3, description="metacentric height")


class ClarkeOptions(Section):
    """``[clarke]``: main particulars, for a ship without published coefficients."""

    length_m: Length
    breadth_m: Length
    draft_m: Length
    cb: Annotated[float, Quantity(ge=0.35, le=0.95)]
    x_g_m: Annotated[float, Quantity("m")] = 0.0
    k_zz: Annotated[float, Quantity(gt=0.0, le=1.0)] = 0.25
    rudder_area_m2: Annotated[float, Quantity("m^2", ge=0.0, le=1e4)] = Field(0.0, description="0: L T / 60")


class ShipFile(Section):
    """A vessel's manoeuvring file."""

    name: Annotated[str, Field(min_length=1, max_length=80)]
    source: Annotated[str, Field(min_length=1, max_length=2000)] = Field(description="where the coefficients come from")
    model: Literal["mmg", "son_nomoto", "clarke"]
    approach_speed_kn: Annotated[float, Quantity("kn", gt=0.0, le=MAX_SPEED_KN)] = Field(
        description="the speed of the trials (IMO: at least 90 % of the speed at 85 % MCR)")
    steering: SteeringOptions = Field(default_factory=SteeringOptions)
    engine: EngineOptions
    autopilot: AutopilotOptions = Field(default_factory=AutopilotOptions)
    mmg: MmgOptions | None = None
    son_nomoto: SonNomotoOptions | None = None
    clarke: ClarkeOptions | None = None

    @model_validator(mode="after")
    def _the_model_given(self) -> ShipFile:
        for name in ("mmg", "son_nomoto", "clarke"):
            given = getattr(self, name) is not None
            if given != (name == self.model):
                raise _refuse(name, f"a [{name}] table with model = {self.model!r}: its coefficients go in "
                                    f"[{self.model}]" if given
                              else f"model = {self.model!r} needs its [{self.model}] table")
        if self.autopilot.rudder_limit_deg > self.steering.max_rudder_deg:
            raise _refuse("autopilot", f"rudder_limit_deg {self.autopilot.rudder_limit_deg:g} is more than the "
                                       f"steering gear's max_rudder_deg {self.steering.max_rudder_deg:g}")
        return self


def build_ship(file: ShipFile) -> Ship:
    """The :class:`Ship` a validated file describes, its autopilot tuned at the approach speed."""
    kt = (file.engine.astern_kt[0], file.engine.astern_kt[1])
    if file.model == "mmg":
        model = file.mmg.model(kt)
    elif file.model == "son_nomoto":
        model = SonNomotoContainer(gm_m=file.son_nomoto.gm_m, astern_kt=kt)
    else:
        c = file.clarke
        model = Clarke(c.length_m, c.breadth_m, c.draft_m, c.cb, c.x_g_m, c.k_zz, c.rudder_area_m2, kt)
    return ship_with(file.name, model, file.steering, file.engine, file.autopilot, file.approach_speed_kn * KNOT)


def ship_with(name: str, model, steering: SteeringOptions, engine: EngineOptions, autopilot: AutopilotOptions,
              speed: float) -> Ship:
    """A :class:`Ship` of ``model`` with its gear, engine and an autopilot tuned at ``speed`` (m/s)."""
    telegraph = {order: rpm / 60.0 for order, rpm in engine.telegraph().items()}
    gear = SteeringGear(math.radians(steering.max_rudder_deg), math.radians(steering.rudder_rate_deg_s))
    motor = Engine(max(telegraph.values()), -min(telegraph.values()), engine.time_constant_s, telegraph)
    ship = Ship(name, model, gear, motor, approach_speed=speed)
    authority = ship.yaw_authority(speed)
    return ship.with_autopilot(tuned(authority, math.radians(autopilot.rudder_limit_deg),
                                     math.radians(autopilot.rate_of_turn_deg_min / 60.0), ship.length_m, speed))


SERVICE_FROUDE = 0.15
"""A ship made from her hull has full ahead at the speed of this Froude number on her waterline length, or 10 %
above the scenario's speed if faster (the rpm rounded up to a tenth)."""


def ship_from_hull(name: str, hull: Hull, speed: float) -> Ship:
    """A ship from ``hull``'s main particulars (:class:`~marinesim.manoeuvring.clarke.Clarke`: waterline length
    and beam, draft, block coefficient), full ahead at :data:`SERVICE_FROUDE` or 10 % above ``speed`` (m/s), the
    rest of the telegraph, the SOLAS steering gear and the autopilot as a manoeuvring file's defaults."""
    key = (name, hull.content_hash(), speed)
    if key not in _FROM_HULLS:
        if len(_FROM_HULLS) >= 16:
            _FROM_HULLS.pop(next(iter(_FROM_HULLS)))
        _FROM_HULLS[key] = _from_hull(name, hull, speed)
    return _FROM_HULLS[key]


_FROM_HULLS: dict[tuple[str, str, float], Ship] = {}
"""Ships made from hulls, by name, the hull's content and the speed (the hard-over check runs once)."""


def _from_hull(name: str, hull: Hull, speed: float) -> Ship:
    statics = hydrostatics(hull)
    length, breadth, draft = statics.waterline_length_m, statics.waterline_beam_m, statics.draft_m
    if min(length, breadth, draft) <= 0.0:
        raise ParameterError("the hull does not cross the waterline: no main particulars for a manoeuvring model")
    cb = min(max(statics.volume_m3 / (length * breadth * draft), 0.35), 0.95)
    model = Clarke(length, breadth, draft, cb)
    service = max(1.1 * speed, SERVICE_FROUDE * math.sqrt(G * length))
    probe = Ship(name, model, SteeringGear(), Engine(1e3, 0.0, 1.0))
    engine = EngineOptions(full_ahead_rpm=math.ceil(600.0 * probe.rps_for_speed(service)) / 10.0)  # to 0.1 rpm
    ship = ship_with(name, model, SteeringOptions(), engine, AutopilotOptions(), service)
    hard_over(ship, service)
    return ship


def load_ship(path: str | Path) -> tuple[ShipFile, Ship]:
    """Read, validate and build the manoeuvring file ``path``; a model unstable at hard-over from its approach speed
    is refused. Errors (:class:`ScenarioError`) name the file and the key."""
    path = Path(path)
    data = read_small_file(path, "manoeuvring file")
    return _load(str(path), hashlib.sha256(data).hexdigest(), data)


@functools.lru_cache(maxsize=16)
def _load(path: str, digest: str, data: bytes) -> tuple[ShipFile, Ship]:
    try:
        text = data.decode("utf-8-sig")
        file = validate(ShipFile, tomllib.loads(text))
    except (UnicodeDecodeError, tomllib.TOMLDecodeError) as error:
        raise ScenarioError(f"{path}: not valid TOML: {error}") from None
    except ScenarioError as error:
        raise ScenarioError(f"{path}: {error}") from None
    try:
        ship = build_ship(file)
        speed = file.approach_speed_kn * KNOT
        ship.rps_for_speed(speed)
        hard_over(ship, speed)
    except MarinesimError as error:
        raise ScenarioError(f"{path}: {file.model}: {error}") from None
    return file, ship
