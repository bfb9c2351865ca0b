"""A vessel's station-keeping file (``configs/station/*.toml``): her low-frequency mass and damping, her thrusters,
her DP's tuning, her wind areas and coefficients and her wave drift table, validated as a scenario is (one pydantic
model; errors name the file and the key).

The mass and damping are given in SI (``mass_matrix``, ``damping_matrix``: 3 x 3 in surge, sway, yaw about her
origin, body axes x forward, y to starboard) or in Fossen's bis system (``mass_bis``, ``damping_bis``: made
dimensional with ``mass_t`` and ``length_m``: ``M = m T M'' T``, ``D = m sqrt(g / L) T D'' T``, ``T =
diag(1, 1, L)``; Fossen 2021, app. D).
"""

from __future__ import annotations

import functools
import hashlib
import math
import tomllib
from pathlib import Path
from typing import Annotated, Literal

import numpy as np
from pydantic import Field, model_validator

from marinesim.constants import G
from marinesim.errors import MarinesimError, ScenarioError
from marinesim.scenario.model import Quantity, Section, _refuse, read_small_file, validate
from marinesim.station.dp import Tuning
from marinesim.station.thrusters import KINDS, Thruster, Thrusters

MAX_THRUSTERS = 16

Matrix3 = Annotated[list[Annotated[list[float], Field(min_length=3, max_length=3)]], Field(min_length=3,
                                                                                          max_length=3)]


class ThrusterOptions(Section):
    """``[[thrusters]]``: one thruster."""

    name: Annotated[str, Field(min_length=1, max_length=40)] = Field(description="what the panel calls it")
    kind: Literal[KINDS] = Field(description="tunnel (sideways), main (fore and aft) or azimuth (any direction)")
    x_m: Annotated[float, Quantity("m", ge=-500.0, le=500.0)] = Field(description="forward of her origin")
    y_m: Annotated[float, Quantity("m", ge=-200.0, le=200.0)] = Field(description="to starboard of her origin")
    max_thrust_kn: Annotated[float, Quantity("kN", gt=0.0, le=5000.0)] = Field(description="its rating")
    astern_fraction: Annotated[float, Quantity(ge=0.0, le=1.0)] = Field(
        0.7, description="a main propeller's thrust astern as a fraction of ahead")
    time_constant_s: Annotated[float, Quantity("s", gt=0.0, le=60.0)] = Field(
        2.0, description="how fast its thrust follows its order (first order)")


class WindOptions(Section):
    """``[wind]``: her windage."""

    vessel_type: str | None = Field(None, description="Blendermann (1994) coefficients of this vessel type")
    file: str | None = Field(None, description="instead: a coefficient file (CSV angle_deg,cx,cy,cn), relative to "
                                               "this file")
    frontal_area_m2: Annotated[float, Quantity("m^2", gt=0.0, le=1e5)] = Field(description="projected ahead")
    lateral_area_m2: Annotated[float, Quantity("m^2", gt=0.0, le=1e5)] = Field(description="projected abeam")
    lateral_centroid_m: Annotated[float, Quantity("m", ge=-500.0, le=500.0)] = Field(
        0.0, description="the lateral area's centroid forward of her origin")

    @model_validator(mode="after")
    def _one_source(self) -> WindOptions:
        if (self.vessel_type is None) == (self.file is None):
            raise _refuse("vessel_type", "give exactly one of vessel_type (Blendermann) and file")
        return self


class DpOptions(Section):
    """``[dp]``: the DP computer's tuning."""

    periods_s: Annotated[list[Annotated[float, Quantity("s", ge=20.0, le=600.0)]],
                         Field(min_length=3, max_length=3)] = Field(
        [100.0, 100.0, 80.0], description="the closed loop's natural periods in surge, sway and yaw")
    damping: Annotated[float, Quantity(gt=0.2, le=2.0)] = Field(0.9, description="its relative damping")
    wave_period_s: Annotated[float, Quantity("s", ge=3.0, le=25.0)] = Field(
        9.0, description="the observer's wave model's peak period")


class StationFile(Section):
    """A vessel's station-keeping file."""

    name: str = Field(description="the vessel, for people")
    source: str = Field(description="where the figures come from")
    length_m: Annotated[float, Quantity("m", gt=0.0, le=500.0)] = Field(description="her length")
    mass_t: Annotated[float | None, Quantity("t", gt=0.0, le=1e7)] = Field(None, description="her mass (bis)")
    mass_bis: Matrix3 | None = None
    damping_bis: Matrix3 | None = None
    mass_matrix: Matrix3 | None = Field(None, description="low-frequency mass with added mass (kg, kg m, kg m^2)")
    damping_matrix: Matrix3 | None = Field(None, description="linear damping (N s/m, N s, N m s)")
    wind: WindOptions
    drift: str | None = Field(None, description="mean drift table (WAMIT .8 or .9, AQWA .lis, NEMOH OUT_QTFM_N.dat), "
                                                "relative to this file; absent: her RAO set's own where it has one")
    drift_ulen_m: Annotated[float | None, Quantity("m", gt=0.0, le=1000.0)] = Field(
        None, description="a WAMIT table's ULEN; absent: the .gdf's beside it")
    drift_axisymmetric: bool = Field(False, description="an AQWA or NEMOH table of a few headings of a body symmetric "
                                                        "about the vertical (a buoy, a spar): turned round the circle")
    thrusters: Annotated[list[ThrusterOptions], Field(max_length=MAX_THRUSTERS)] = Field(default_factory=list)
    dp: DpOptions = Field(default_factory=DpOptions)

    @model_validator(mode="after")
    def _one_way_to_give_the_mass(self) -> StationFile:
        bis = [k for k in ("mass_t", "mass_bis", "damping_bis") if getattr(self, k) is not None]
        si = [k for k in ("mass_matrix", "damping_matrix") if getattr(self, k) is not None]
        if bis and si:
            raise _refuse(si[0], "give the mass and damping in SI (mass_matrix, damping_matrix) or in the bis "
                                 "system (mass_t, mass_bis, damping_bis), not both")
        if len(bis) not in (0, 3) or len(si) not in (0, 2) or not (bis or si):
            missing = [k for k in (("mass_t", "mass_bis", "damping_bis") if bis else ("mass_matrix", "damping_matrix"))
                       if getattr(self, k) is None]
            raise _refuse(missing[0], "required")
        names = [t.name for t in self.thrusters]
        if len(set(names)) < len(names):
            raise _refuse("thrusters", "two thrusters of the same name")
        if self.thrusters and np.linalg.matrix_rank(self.thruster_set().b * [[1.0], [1.0], [1.0 / self.length_m]],
                                                    tol=1e-9) < 3:
            raise _refuse("thrusters", "they cannot push her ahead, sideways and turn her independently: no "
                                       "position and heading can be held (add a tunnel or azimuth thruster)")
        return self

    def matrices(self) -> tuple[np.ndarray, np.ndarray]:
        """(M, D) (3, 3) in SI."""
        if self.mass_matrix is not None:
            m, d = np.array(self.mass_matrix, float), np.array(self.damping_matrix, float)
        else:
            t = np.diag([1.0, 1.0, self.length_m])
            mass = self.mass_t * 1e3
            m = mass * t @ np.array(self.mass_bis, float) @ t
            d = mass * math.sqrt(G / self.length_m) * t @ np.array(self.damping_bis, float) @ t
        if np.any(np.linalg.eigvalsh(0.5 * (m + m.T)) <= 0.0):
            raise ScenarioError("mass: the low-frequency mass matrix is not positive definite")
        return m, d

    def thruster_set(self) -> Thrusters | None:
        if not self.thrusters:
            return None
        return Thrusters(tuple(Thruster(t.name, t.kind, t.x_m, t.y_m, t.max_thrust_kn * 1e3, t.astern_fraction,
                                        t.time_constant_s) for t in self.thrusters), self.length_m)

    def tuning(self) -> Tuning:
        return Tuning(periods_s=tuple(self.dp.periods_s), zeta=self.dp.damping,
                      wave_omega=2.0 * math.pi / self.dp.wave_period_s)


def load_station(path: str | Path) -> StationFile:
    """Read and validate the station-keeping file ``path``; errors (:class:`ScenarioError`) name the file and the
    key."""
    path = Path(path)
    data = read_small_file(path, "station-keeping file")
    return _load(str(path), hashlib.sha256(data).hexdigest(), data)


@functools.lru_cache(maxsize=16)
def _load(path: str, digest: str, data: bytes) -> StationFile:
    try:
        file = validate(StationFile, tomllib.loads(data.decode("utf-8-sig")))
        file.matrices()
    except (UnicodeDecodeError, tomllib.TOMLDecodeError) as error:
        raise ScenarioError(f"{path}: not valid TOML: {error}") from None
    except MarinesimError as error:
        raise ScenarioError(f"{path}: {error}") from None
    return file
