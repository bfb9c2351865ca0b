"""The wind on a vessel keeping station: the NPD gust spectrum, gusts synthesised from it, and the wind's load.

Axes as :mod:`marinesim.manoeuvring.state`: heading ``psi`` clockwise from north (rad); body x forward, y to
starboard, z down; ``u`` surge, ``v`` sway to starboard (m/s). Loads are (X N forward, Y N to starboard, N N m
turning the bow to starboard). The wind is given as scenarios give it (CONVENTIONS.md): a speed at 10 m (m/s) and
the compass bearing it comes *from* (here in rad, clockwise from north).

**Angle of attack** (Fossen 2021, sec. 10.1): the vessel's velocity relative to the air ``u_r = u - u_w``,
``v_r = v - v_w`` (``u_w, v_w`` the air's velocity in body axes), ``V_r = |(u_r, v_r)|`` and
``gamma = -atan2(v_r, u_r)`` in (-pi, pi]: 0 with the apparent wind from dead ahead, pi from astern, **+pi/2 from
the port beam** and -pi/2 from the starboard beam (with y to starboard, ``gamma`` turns the other way from a
relative bearing). With it the coefficients of a port/starboard symmetric vessel read the same whichever side the
wind is on: ``C_X < 0`` pushes her astern in a head wind, ``C_Y`` of the sign of ``gamma`` pushes her to leeward
(from port, gamma > 0, to starboard) and ``C_N`` of the sign of ``C_Y`` (centroid near midship, wind forward of
the beam) turns her bow to leeward.
The load (Fossen 2021, sec. 10.1; ``rho_a`` = :data:`RHO_AIR`)::

    X = 1/2 rho_a V_r^2 C_X(gamma) A_F,   Y = 1/2 rho_a V_r^2 C_Y(gamma) A_L,   N = 1/2 rho_a V_r^2 C_N(gamma) A_L L

``A_F`` the frontal and ``A_L`` the lateral projected wind area (m^2), ``L`` the length overall (m).
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from marinesim.compiled import compiled, read_only
from marinesim.errors import FileFormatError, ParameterError, require_finite, require_positive
from marinesim.formats import check_file

RHO_AIR = 1.226
"""Density of air (kg/m^3), as DNV-RP-C205 takes it for wind loads."""

NPD_N = 0.468
"""The exponent ``n`` of the NPD (Froya) spectrum."""
GUST_F_LOW = 1.0 / 3600.0
"""Lowest gust frequency synthesised (Hz): the NPD spectrum is the spectrum about a 1-hour mean, slower
variations being the mean's own (a weather event ramping the wind)."""
GUST_F_HIGH = 0.5
"""Highest gust frequency synthesised (Hz): a moored or DP vessel's low-frequency motion (periods of 30 s and
more) does not feel faster gusts, and the wind over her length is not coherent at them."""
GUST_COMPONENTS = 300
"""Cosines in a gust series: 300 log-spaced bins over ``GUST_F_LOW .. GUST_F_HIGH`` are 2.5 % wide each, and a
speed costs 5-10 us (four a 0.1 s step for 30,000 steps: about a second a run)."""

GUST_STREAM = 0x57494E44
"""The gusts' random stream is ``numpy.random.default_rng([seed, GUST_STREAM])`` ("WIND" in ASCII), a stream of
their own: ``default_rng(seed)`` would be the ocean's first tile's (``[seed]`` and ``[seed, 0]`` seed alike), the
gusts' phases then the waves'."""

MAX_GAP_DEG = 30.0
"""The widest gap between two angles of a coefficient table (deg): linear interpolation over more misses the
peaks of C_Y and C_N near 60..120 deg."""
HEADER = ("angle_deg", "cx", "cy", "cn")


# --- the NPD (Froya) wind -----------------------------------------------------------------------------------


def npd_spectrum(f: np.ndarray | float, u0: float, z: float = 10.0) -> np.ndarray:
    """The NPD (Froya) spectrum of the longitudinal wind speed ``S(f)`` (m^2/s^2 per Hz, one-sided in Hz) at height
    ``z`` (m) for the 1-hour mean wind ``u0`` (m/s) at 10 m; ``f`` (Hz, >= 0) any shape, the result its shape::

        S(f) = 320 (U0/10)^2 (z/10)^0.45 / (1 + f~^n)^(5/(3n)),   f~ = 172 f (z/10)^(2/3) (U0/10)^(-3/4),  n = 0.468

    ISO 19901-1 (after Andersen and Lovseth's Froya measurements; API RP 2A), DNV-RP-C205 (2010) sec. 2.3.5
    ("Froya wind spectrum"); the same constants as ``froya_1hr`` in the ndspec crate
    (https://docs.rs/crate/ndspec/latest/source/src/wind/froya.rs). At high frequency ``S ~ f^(-5/3)``.
    """
    u0 = _require_non_negative("u0", u0)
    z = require_positive("z", z)
    f = np.asarray(f, dtype=float)
    if np.any(~np.isfinite(f)) or np.any(f < 0.0):
        raise ParameterError("the frequencies f must be finite and >= 0 Hz")
    if u0 == 0.0:
        return np.zeros_like(f)
    f_tilde = 172.0 * f * (z / 10.0) ** (2.0 / 3.0) * (u0 / 10.0) ** -0.75
    return 320.0 * (u0 / 10.0) ** 2 * (z / 10.0) ** 0.45 / (1.0 + f_tilde**NPD_N) ** (5.0 / (3.0 * NPD_N))


def npd_turbulence_intensity(u0: float, z: float = 10.0) -> float:
    """The NPD turbulence intensity ``I_u = 0.06 (1 + 0.043 U0) (z/10)^-0.22`` at height ``z`` (m) for the 1-hour
    mean ``u0`` (m/s) at 10 m (ISO 19901-1; DNV-RP-C205 sec. 2.3.2)."""
    u0 = _require_non_negative("u0", u0)
    return 0.06 * (1.0 + 0.043 * u0) * (require_positive("z", z) / 10.0) ** -0.22


def npd_mean_speed(u0: float, z: float = 10.0, averaging_s: float = 3600.0) -> float:
    """The NPD mean wind speed (m/s) at height ``z`` (m) over ``averaging_s`` (s, up to the hour) for the 1-hour
    mean ``u0`` (m/s) at 10 m: ``U0 (1 + C ln(z/10)) (1 - 0.41 I_u(z) ln(T/3600))``,
    ``C = 5.73e-2 sqrt(1 + 0.148 U0)`` (ISO 19901-1; DNV-RP-C205 sec. 2.3.2). A 3 s gust at 10 m in 20 m/s is
    about 1.32 times the hourly mean."""
    u0 = _require_non_negative("u0", u0)
    z = require_positive("z", z)
    averaging_s = require_positive("averaging_s", averaging_s)
    if averaging_s > 3600.0:
        raise ParameterError(f"averaging_s must be <= 3600 s (the NPD profile's hour), got {averaging_s!r}")
    c = 5.73e-2 * math.sqrt(1.0 + 0.148 * u0)
    return u0 * (1.0 + c * math.log(z / 10.0)) * (1.0 - 0.41 * npd_turbulence_intensity(u0, z)
                                                    * math.log(averaging_s / 3600.0))


class Gusts:
    """The wind speed (m/s) at height ``height`` (m) gusting about the NPD mean, for ``0 <= t <= duration`` (s).

    The fluctuation is a sum of :data:`GUST_COMPONENTS` cosines ``sum a_i cos(2 pi f_i t + phi_i)``: the band
    :data:`GUST_F_LOW` .. :data:`GUST_F_HIGH` cut into log-spaced bins (equal relative resolution where the
    spectrum's variance lies, a few mHz), ``f_i`` drawn uniformly within bin i (so the lines are not harmonics and
    the series never repeats), ``a_i = sqrt(2 S(f_i) df_i)`` with ``S`` the :func:`npd_spectrum` of ``u0`` at
    ``height`` (the expected variance of each bin is then its integral of ``S`` exactly), ``phi_i`` uniform on
    [0, 2 pi). The stream of :data:`GUST_STREAM` for ``seed`` draws the jitters, then the phases: a seed gives one
    series, bit for bit. Each speed is evaluated from the sum, no table: its cost does not grow with the duration,
    which only bounds the times a caller may ask for (a time outside it is a mistake).

    The mean wind may change during a run (a weather event ramps it): ``speed(t, u_mean)`` scales the whole wind,
    mean and fluctuation, by ``u_mean / u0``; the spectrum's *shape* (its peak frequency, its turbulence
    intensity) stays that of ``u0``. Build it with the run's typical or largest mean.
    """

    def __init__(self, u0: float, seed: int, duration: float, height: float = 10.0,
                 components: int = GUST_COMPONENTS) -> None:
        self.u0 = require_positive("u0", u0)
        if isinstance(seed, bool) or not isinstance(seed, (int, np.integer)) or seed < 0:
            raise ParameterError(f"seed must be an integer >= 0, got {seed!r}")
        self.seed = int(seed)
        self.duration = require_positive("duration", duration)
        self.height = require_positive("height", height)
        if isinstance(components, bool) or not isinstance(components, (int, np.integer)) or components < 10:
            raise ParameterError(f"components must be an integer >= 10, got {components!r}")
        edges = np.geomspace(GUST_F_LOW, GUST_F_HIGH, int(components) + 1)
        widths = np.diff(edges)
        rng = np.random.default_rng([self.seed, GUST_STREAM])
        self.frequencies = edges[:-1] + rng.random(int(components)) * widths
        """The cosines' frequencies f_i (Hz), (components,)."""
        self.phases = rng.uniform(0.0, 2.0 * math.pi, int(components))
        """Their phases phi_i (rad), (components,)."""
        self.amplitudes = np.sqrt(2.0 * npd_spectrum(self.frequencies, self.u0, self.height) * widths)
        """Their amplitudes a_i (m/s), (components,)."""
        self.bin_edges = edges
        """The bins' edges (Hz), (components + 1,)."""
        self.mean = npd_mean_speed(self.u0, self.height)
        """The 1-hour mean at ``height`` for ``u0`` (m/s)."""
        self._omega = 2.0 * math.pi * self.frequencies
        self._slack = 1e-9 * max(1.0, self.duration)  # t = n dt may land a rounding past the end

    @property
    def variance(self) -> float:
        """The fluctuation's variance, ``sum a_i^2 / 2`` (m^2/s^2) for ``u0``."""
        return float(np.sum(self.amplitudes**2) / 2.0)

    def fluctuation(self, times: np.ndarray) -> np.ndarray:
        """The fluctuation about the mean for ``u0`` (m/s) at ``times`` (s, any shape; the result its shape)."""
        times = self._check_times(times)
        flat = times.ravel()
        out = np.empty(flat.shape)
        for start in range(0, flat.size, 4096):  # bounded memory: 4096 x components cosines at a time
            chunk = flat[start:start + 4096]
            phases = np.multiply.outer(chunk, self._omega) + self.phases
            out[start:start + chunk.size] = np.cos(phases) @ self.amplitudes
        return out.reshape(times.shape)

    def speeds(self, times: np.ndarray, u_mean: float | np.ndarray | None = None) -> np.ndarray:
        """The wind speed (m/s) at ``times`` (s, any shape): ``(u_mean / u0) (mean + fluctuation)``; ``u_mean`` the
        1-hour mean at 10 m then (m/s, >= 0, scalar or of the shape of ``times``; None: ``u0``)."""
        scale = 1.0 if u_mean is None else self._scale(u_mean)
        return scale * (self.mean + self.fluctuation(times))

    def speed(self, t: float, u_mean: float | None = None) -> float:
        """The wind speed (m/s) at ``t`` (s): :meth:`speeds` at one time (equal to it within rounding)."""
        t = require_finite("t", t)
        if not -self._slack <= t <= self.duration + self._slack:
            self._check_times(t)  # raises, naming the duration
        scale = 1.0
        if u_mean is not None:
            u_mean = require_finite("u_mean", u_mean)
            if u_mean < 0.0:
                raise ParameterError(f"u_mean must be finite and >= 0 m/s, got {u_mean!r}")
            scale = u_mean / self.u0
        return scale * (self.mean + float(np.dot(self.amplitudes, np.cos(self._omega * t + self.phases))))

    def _scale(self, u_mean: float | np.ndarray) -> float | np.ndarray:
        u_mean = np.asarray(u_mean, dtype=float)
        if np.any(~np.isfinite(u_mean)) or np.any(u_mean < 0.0):
            raise ParameterError(f"u_mean must be finite and >= 0 m/s, got {u_mean!r}")
        return u_mean / self.u0

    def _check_times(self, times: np.ndarray) -> np.ndarray:
        times = np.asarray(times, dtype=float)
        slack = self._slack
        if times.size and (not np.all(np.isfinite(times)) or times.min() < -slack
                           or times.max() > self.duration + slack):
            raise ParameterError(f"gust times must lie in 0..{self.duration:g} s (the duration the gusts were "
                                 f"built for), got {times.min():g}..{times.max():g} s")
        return times


# --- coefficients -----------------------------------------------------------------------------------------------


def _wrap(angle: float | np.ndarray) -> np.ndarray:
    """An angle (rad) wrapped to (-pi, pi]; an array of its shape (:func:`coefficients_at`: the same in floats)."""
    return np.pi - np.mod(np.pi - np.asarray(angle, dtype=float), 2.0 * np.pi)


class WindCoefficients:
    """The wind load coefficients ``C_X, C_Y, C_N`` of the angle of attack ``gamma`` (rad, the module's
    convention; any real value, wrapped), normalised as the module's load formula. ``name`` says where they come
    from."""

    name: str = "wind coefficients"

    def __call__(self, gamma: float | np.ndarray) -> np.ndarray:
        """``(C_X, C_Y, C_N)`` at ``gamma``: shape (3,) + gamma's shape."""
        return self._evaluate(_wrap(gamma))

    def c_x(self, gamma: float | np.ndarray) -> np.ndarray:
        """The surge coefficient C_X at ``gamma`` (rad): negative in a head wind."""
        return self(gamma)[0]

    def c_y(self, gamma: float | np.ndarray) -> np.ndarray:
        """The sway coefficient C_Y at ``gamma`` (rad): positive from port (0 < gamma < pi)."""
        return self(gamma)[1]

    def c_n(self, gamma: float | np.ndarray) -> np.ndarray:
        """The yaw coefficient C_N at ``gamma`` (rad)."""
        return self(gamma)[2]

    packed: tuple[np.ndarray, np.ndarray, np.ndarray]
    """What :func:`coefficients_at` reads (every subclass sets it; read-only): Blendermann's parameters (8,), or a
    table's angles (n,) and rows (3, n); the others empty."""

    def _evaluate(self, gamma: np.ndarray) -> np.ndarray:
        """The coefficients (3,) + gamma's shape at ``gamma`` wrapped to (-pi, pi]."""
        raise NotImplementedError


@dataclass(frozen=True)
class Blendermann:
    """One row of Blendermann's (1994) table as Fossen (2021, sec. 10.1.2) gives it: the transverse drag
    coefficient ``cd_t``, the longitudinal ``CD_l A_F`` for head (``cd_l_af_bow``, gamma = 0) and following
    (``cd_l_af_stern``, gamma = pi) winds, the cross-force parameter ``delta`` and the rolling-moment factor
    ``kappa`` (unused in the horizontal plane)."""

    cd_t: float
    cd_l_af_bow: float
    cd_l_af_stern: float
    delta: float
    kappa: float


BLENDERMANN = {
    "car carrier": Blendermann(0.95, 0.55, 0.60, 0.80, 1.2),
    "cargo vessel loaded": Blendermann(0.85, 0.65, 0.55, 0.40, 1.7),
    "cargo vessel container on deck": Blendermann(0.85, 0.55, 0.50, 0.40, 1.4),
    "container ship": Blendermann(0.90, 0.55, 0.55, 0.40, 1.4),
    "destroyer": Blendermann(0.85, 0.60, 0.65, 0.65, 1.1),
    "diving support vessel": Blendermann(0.90, 0.60, 0.80, 0.55, 1.7),
    "drilling vessel": Blendermann(1.00, 0.85, 0.925, 0.10, 1.7),
    "ferry": Blendermann(0.90, 0.45, 0.50, 0.80, 1.1),
    "fishing vessel": Blendermann(0.95, 0.70, 0.70, 0.40, 1.1),
    "lng tanker": Blendermann(0.70, 0.60, 0.65, 0.50, 1.1),
    "offshore supply vessel": Blendermann(0.90, 0.55, 0.80, 0.55, 1.2),
    "passenger liner": Blendermann(0.90, 0.40, 0.40, 0.80, 1.2),
    "research vessel": Blendermann(0.85, 0.55, 0.65, 0.60, 1.4),
    "speed boat": Blendermann(0.90, 0.55, 0.60, 0.60, 1.1),
    "tanker loaded": Blendermann(0.70, 0.90, 0.55, 0.40, 3.1),
    "tanker in ballast": Blendermann(0.70, 0.75, 0.55, 0.40, 2.2),
    "tender": Blendermann(0.85, 0.55, 0.55, 0.65, 1.1),
}
"""Blendermann (1994), "Parameter identification of wind loads on ships", J. Wind Eng. Ind. Aerodyn. 51, 339-351,
as tabulated in Fossen (2021), Handbook of Marine Craft Hydrodynamics and Motion Control, 2nd ed., sec. 10.1.2;
transcribed from ``BDATA`` in MSS ``LIBRARY/environment/blendermann94.m`` (github.com/cybergalactic/MSS, MIT
licence). The table gives the drilling vessel's CD_l A_F as ranges (0.70-1.00 and 0.75-1.10): their mid-points,
as MSS takes them. Names: the table's, lower case, without punctuation ("container ship" is its "container ship,
loaded")."""


def blendermann_type(vessel_type: str) -> Blendermann:
    """The :data:`BLENDERMANN` row of ``vessel_type`` (case, commas, hyphens and underscores ignored)."""
    key = " ".join(re.sub(r"[,_\-]", " ", str(vessel_type)).lower().split())
    key = {"container ship loaded": "container ship", "liquefied natural gas tanker": "lng tanker"}.get(key, key)
    if key not in BLENDERMANN:
        raise ParameterError(f"unknown vessel type {vessel_type!r} for Blendermann's wind coefficients: give one "
                             f"of {', '.join(sorted(BLENDERMANN))}")
    return BLENDERMANN[key]


class BlendermannCoefficients(WindCoefficients):
    """Blendermann's (1994) coefficients of a merchant ship or offshore vessel of ``vessel_type``
    (:data:`BLENDERMANN`) with frontal and lateral projected areas ``frontal_area``, ``lateral_area`` (m^2),
    length overall ``length`` (m) and the lateral area's centroid ``s_l`` (m forward of midship); Fossen (2021)
    sec. 10.1.2, with ``CD_l = CD_l_AF A_F / A_L`` and ``CD_l_AF`` the head-wind value for ``|gamma| <= pi/2``::

        C_X = -CD_l_AF cos(gamma) / den,   C_Y = CD_t sin(gamma) / den,   C_N = (s_L/L - 0.18 (|gamma| - pi/2)) C_Y
        den = 1 - delta/2 (1 - CD_l/CD_t) sin^2(2 gamma)

    The source writes C_N for 0 <= gamma <= pi; ``|gamma|`` mirrors it to the starboard side, so that a wind from
    either beam turns her the same way to leeward (MSS evaluates ``gamma - pi/2`` for negative ``gamma`` too,
    which is not symmetric).
    """

    def __init__(self, vessel_type: str, frontal_area: float, lateral_area: float, length: float,
                 s_l: float = 0.0) -> None:
        self.row = blendermann_type(vessel_type)
        self.frontal_area = require_positive("frontal_area", frontal_area)
        self.lateral_area = require_positive("lateral_area", lateral_area)
        self.length = require_positive("length", length)
        self.s_l = require_finite("s_l", s_l)
        if abs(self.s_l) > self.length / 2.0:
            raise ParameterError(f"s_l (the lateral area's centroid forward of midship) must lie within half the "
                                 f"length, {self.length / 2.0:g} m, got {s_l!r}")
        self.name = f"Blendermann (1994): {vessel_type}"
        row = self.row
        self.packed = read_only(np.array([row.cd_t, row.cd_l_af_bow, row.cd_l_af_stern, row.delta,
                                           self.frontal_area, self.lateral_area, self.s_l, self.length], dtype=float),
                                 np.empty(0), np.empty((3, 0)))

    def _evaluate(self, gamma: np.ndarray) -> np.ndarray:
        if gamma.ndim == 0:
            return np.array(_blendermann(float(gamma), self.packed[0]))
        row, off = self.row, np.abs(gamma)
        cd_l_af = np.where(off <= math.pi / 2.0, row.cd_l_af_bow, row.cd_l_af_stern)
        cd_l = cd_l_af * self.frontal_area / self.lateral_area
        den = 1.0 - 0.5 * row.delta * (1.0 - cd_l / row.cd_t) * np.sin(2.0 * gamma) ** 2
        cx = -cd_l_af * np.cos(gamma) / den
        cy = row.cd_t * np.sin(gamma) / den
        cn = (self.s_l / self.length - 0.18 * (off - math.pi / 2.0)) * cy
        return np.stack([cx, cy, cn])


class TabulatedCoefficients(WindCoefficients):
    """Coefficients tabulated at ``angles_deg`` (deg of ``gamma``, increasing, 0 first, no gap over
    :data:`MAX_GAP_DEG`), linear between them. A half table (0..180) is a vessel symmetric port/starboard: the
    other side mirrors it, ``C_X(-gamma) = C_X(gamma)``, ``C_Y`` and ``C_N`` change sign (so they must be 0 at 0
    and 180 deg). A full table runs from 0 to 330 deg or more (180..360 being the starboard side, ``gamma`` + 360)
    and wraps round to 0; a row at 360 must repeat the row at 0."""

    def __init__(self, angles_deg: np.ndarray, cx: np.ndarray, cy: np.ndarray, cn: np.ndarray,
                 name: str = "tabulated wind coefficients") -> None:
        angles, cx, cy, cn = (np.asarray(a, dtype=float) for a in (angles_deg, cx, cy, cn))
        if not angles.ndim == 1 or not angles.shape == cx.shape == cy.shape == cn.shape or angles.size < 2:
            raise ParameterError("angles_deg, cx, cy and cn must be 1-D of one length, at least 2")
        if not all(np.all(np.isfinite(a)) for a in (angles, cx, cy, cn)):
            raise ParameterError("wind coefficients and their angles must be finite numbers")
        if angles[0] != 0.0 or np.any(np.diff(angles) <= 0.0):
            raise ParameterError("the angles must start at 0 deg and increase")
        if np.any(np.diff(angles) > MAX_GAP_DEG):
            raise ParameterError(f"the angles must be no more than {MAX_GAP_DEG:g} deg apart")
        if angles[-1] == 180.0:
            if max(abs(cy[0]), abs(cn[0]), abs(cy[-1]), abs(cn[-1])) > 0.0:
                raise ParameterError("a half table (0..180 deg) mirrors to the other side: cy and cn must be 0 at "
                                     "0 and 180 deg")
            angles = np.concatenate([angles, 360.0 - angles[-2::-1]])
            cx = np.concatenate([cx, cx[-2::-1]])
            cy, cn = (np.concatenate([c, -c[-2::-1]]) for c in (cy, cn))
        elif 360.0 - MAX_GAP_DEG <= angles[-1] <= 360.0:
            if angles[-1] == 360.0:
                if not np.allclose([cx[-1], cy[-1], cn[-1]], [cx[0], cy[0], cn[0]], rtol=0.0, atol=1e-9):
                    raise ParameterError("the row at 360 deg must repeat the row at 0 deg")
            else:
                angles, cx, cy, cn = (np.append(a, b) for a, b in zip((angles, cx, cy, cn),
                                                                      (360.0, cx[0], cy[0], cn[0])))
        else:
            raise ParameterError(f"the angles must end at 180 deg (a half table) or run to {360 - MAX_GAP_DEG:g} "
                                 f"deg or more (a full one), not {angles[-1]:g} deg")
        self.angles = np.radians(angles)
        """The table's angles over the full circle 0..2 pi (rad)."""
        self.table = np.stack([cx, cy, cn])
        """C_X, C_Y, C_N at :attr:`angles`, (3, n)."""
        self.name = name
        self.packed = read_only(np.empty(0), self.angles.copy(), self.table.copy())

    def _evaluate(self, gamma: np.ndarray) -> np.ndarray:
        if gamma.ndim == 0:
            return np.array(_tabulated(float(gamma), *self.packed[1:]))
        turn = np.mod(gamma, 2.0 * math.pi)
        return np.stack([np.interp(turn, self.angles, row) for row in self.table])


# One angle at a time, compiled: the simulation asks at each stage of each step (:func:`wind_load_at`).

@compiled
def coefficients_at(gamma: float, params: np.ndarray, angles: np.ndarray, table: np.ndarray
                    ) -> tuple[float, float, float]:
    """``(C_X, C_Y, C_N)`` at one angle ``gamma`` (rad, any real value; wrapped as :func:`_wrap`) of the coefficients
    packed as :attr:`WindCoefficients.packed`: a table where ``angles`` has any, else Blendermann's."""
    wrapped = math.pi - (math.pi - gamma) % (2.0 * math.pi)
    if angles.size:
        return _tabulated(wrapped, angles, table)
    return _blendermann(wrapped, params)


@compiled
def _blendermann(gamma: float, params: np.ndarray) -> tuple[float, float, float]:
    """:class:`BlendermannCoefficients`' formulas at one wrapped ``gamma`` (rad); ``params`` its (CD_t, CD_l_AF
    bow, CD_l_AF stern, delta, A_F m^2, A_L m^2, s_L m, L m)."""
    cd_t, bow, stern, delta, frontal, lateral, s_l, length = params[0], params[1], params[2], params[3], \
        params[4], params[5], params[6], params[7]
    off = abs(gamma)
    cd_l_af = bow if off <= math.pi / 2.0 else stern
    cd_l = cd_l_af * frontal / lateral
    den = 1.0 - 0.5 * delta * (1.0 - cd_l / cd_t) * math.sin(2.0 * gamma) ** 2
    cy = cd_t * math.sin(gamma) / den
    return -cd_l_af * math.cos(gamma) / den, cy, (s_l / length - 0.18 * (off - math.pi / 2.0)) * cy


@compiled
def _tabulated(gamma: float, angles: np.ndarray, table: np.ndarray) -> tuple[float, float, float]:
    """:class:`TabulatedCoefficients` at one wrapped ``gamma`` (rad, or NaN): np.interp's arithmetic over
    ``angles`` (n,) and ``table`` (3, n)."""
    if math.isnan(gamma):
        return math.nan, math.nan, math.nan
    turn = gamma % (2.0 * math.pi)
    j = np.searchsorted(angles, turn, side="right") - 1
    if j >= angles.size - 1 or angles[j] == turn:
        return table[0, j], table[1, j], table[2, j]
    x0, step = angles[j], angles[j + 1] - angles[j]
    return ((table[0, j + 1] - table[0, j]) / step * (turn - x0) + table[0, j],
            (table[1, j + 1] - table[1, j]) / step * (turn - x0) + table[1, j],
            (table[2, j + 1] - table[2, j]) / step * (turn - x0) + table[2, j])


def read_wind_coefficients(path: str | Path) -> TabulatedCoefficients:
    """Read a wind coefficient table: CSV with the header ``angle_deg,cx,cy,cn``, then one row per angle of
    attack ``gamma`` (deg; increasing from 0 to 180, or to 330..360; no gap over :data:`MAX_GAP_DEG`), every cell a
    number; lines starting with ``#`` (before the header: where the numbers come from) and blank lines are skipped.
    Normalisation: the module's load formula (X by A_F, Y by A_L, N by A_L L) with the wind speed at 10 m; signs
    and angle as the module's (:class:`TabulatedCoefficients`). Raises :class:`FileFormatError` naming the line
    and what was expected there."""
    path = Path(path)
    check_file(path, "wind coefficient file")
    text = _text(path)
    header_line, rows, lines = None, [], []
    for number, raw in enumerate(text.splitlines(), start=1):
        line = raw.strip()
        if not line or line.startswith("#"):
            continue
        cells = [cell.strip() for cell in line.split(",")]
        if header_line is None:
            if tuple(cell.lower() for cell in cells) != HEADER:
                raise FileFormatError(path, number, f"expected the header {','.join(HEADER)!r}, got {line!r}")
            header_line = number
            continue
        if len(cells) != len(HEADER):
            raise FileFormatError(path, number, f"expected {len(HEADER)} cells ({','.join(HEADER)}), got "
                                                f"{len(cells)}: {line!r}")
        values = [_number(path, number, cell, name) for cell, name in zip(cells, HEADER)]
        _check_angle(path, number, values[0], rows[-1][0] if rows else None)
        rows.append(values)
        lines.append(number)
    if header_line is None:
        raise FileFormatError(path, None, f"no header: expected a line {','.join(HEADER)!r}, then one row per angle")
    if len(rows) < 2:
        raise FileFormatError(path, header_line, "expected rows for angles 0 to 180 deg (or 0 to 360) under the "
                                                 f"header, got {len(rows)}")
    angles, cx, cy, cn = (np.array(column) for column in zip(*rows))
    last = angles[-1]
    if last == 180.0:
        for i in (0, -1):
            if cy[i] != 0.0 or cn[i] != 0.0:
                raise FileFormatError(path, lines[i], f"a half table (0..180 deg) is mirrored to the other side: "
                                                      f"expected cy = cn = 0 at {angles[i]:g} deg, got cy = "
                                                      f"{cy[i]:g}, cn = {cn[i]:g}")
    elif 360.0 - MAX_GAP_DEG <= last <= 360.0:
        if last == 360.0 and not np.allclose([cx[-1], cy[-1], cn[-1]], [cx[0], cy[0], cn[0]], rtol=0.0, atol=1e-9):
            raise FileFormatError(path, lines[-1], "expected the row at 360 deg to repeat the row at 0 deg")
    else:
        raise FileFormatError(path, lines[-1], f"expected the angles to cover 0..180 deg (a half table, ending at "
                                               f"180) or 0..360 deg (ending at {360 - MAX_GAP_DEG:g}..360), but "
                                               f"they end at {last:g} deg")
    return TabulatedCoefficients(angles, cx, cy, cn, name=f"wind coefficients from {path.name}")


def _text(path: Path) -> str:
    try:
        return path.read_text(encoding="utf-8-sig")
    except UnicodeDecodeError as error:
        raise FileFormatError(path, None, f"not a text file ({error.reason} at byte {error.start})") from None
    except OSError as error:
        raise FileFormatError(path, None, f"cannot read: {error.strerror}") from None


def _number(path: Path, line: int, cell: str, name: str) -> float:
    if not cell:
        raise FileFormatError(path, line, f"expected {name} (a number), got an empty cell")
    try:
        value = float(cell)
    except ValueError:
        raise FileFormatError(path, line, f"expected {name} (a number), got {cell!r}") from None
    if not math.isfinite(value):
        raise FileFormatError(path, line, f"expected {name} (a finite number), got {cell!r}")
    return value


def _check_angle(path: Path, line: int, angle: float, previous: float | None) -> None:
    if previous is None:
        if angle != 0.0:
            raise FileFormatError(path, line, f"expected the first angle to be 0 deg, got {angle:g}")
        return
    if angle <= previous:
        raise FileFormatError(path, line, f"expected angles increasing, got {angle:g} deg after {previous:g}")
    if angle > 360.0:
        raise FileFormatError(path, line, f"expected an angle of 360 deg at most, got {angle:g}")
    if angle - previous > MAX_GAP_DEG:
        raise FileFormatError(path, line, f"expected angles no more than {MAX_GAP_DEG:g} deg apart, got a gap from "
                                          f"{previous:g} to {angle:g} deg")


# --- loads ------------------------------------------------------------------------------------------------------


@compiled
def relative_wind(u: float, v: float, psi: float, wind_speed: float, wind_from: float) -> tuple[float, float]:
    """The apparent wind: its speed ``V_r`` (m/s) and angle of attack ``gamma`` (rad, the module's convention) on a
    vessel heading ``psi`` (rad) at surge ``u`` and sway ``v`` (m/s) in a wind of ``wind_speed`` (m/s) from the
    compass bearing ``wind_from`` (rad)."""
    relative = wind_from - psi
    u_w, v_w = -wind_speed * math.cos(relative), -wind_speed * math.sin(relative)  # the air's velocity, body axes
    u_r, v_r = u - u_w, v - v_w
    return math.hypot(u_r, v_r), -math.atan2(v_r, u_r)


def wind_force(coefficients: WindCoefficients, frontal_area: float, lateral_area: float, length: float,
               u: float, v: float, psi: float, wind_speed: float, wind_from: float,
               rho_air: float = RHO_AIR) -> np.ndarray:
    """The wind's load (X N, Y N, N N m), (3,), on a vessel of projected areas ``frontal_area``, ``lateral_area``
    (m^2) and length ``length`` (m) heading ``psi`` (rad) at ``u``, ``v`` (m/s), in a wind of ``wind_speed`` (m/s,
    at 10 m) from the compass bearing ``wind_from`` (rad): the module's load formula at the apparent wind
    (:func:`relative_wind`). The areas must be the ones ``coefficients`` were made for."""
    return np.array(wind_load_at(float(u), float(v), float(psi), float(wind_speed), float(wind_from),
                                 *coefficients.packed, float(frontal_area), float(lateral_area), float(length),
                                 float(rho_air)))


@compiled
def wind_load_at(u: float, v: float, psi: float, wind_speed: float, wind_from: float, params: np.ndarray,
                 angles: np.ndarray, table: np.ndarray, frontal_area: float, lateral_area: float, length: float,
                 rho_air: float) -> tuple[float, float, float]:
    """:func:`wind_force` (X N, Y N, N N m) with the coefficients packed (:attr:`WindCoefficients.packed`):
    compiled, for the stages of a step."""
    speed, gamma = relative_wind(u, v, psi, wind_speed, wind_from)
    q = 0.5 * rho_air * speed**2
    cx, cy, cn = coefficients_at(gamma, params, angles, table)
    return q * cx * frontal_area, q * cy * lateral_area, q * cn * lateral_area * length


@dataclass(frozen=True)
class WindLoads:
    """A vessel's wind loads: her ``coefficients``, frontal and lateral projected areas ``frontal_area``,
    ``lateral_area`` (m^2) above the waterline, length overall ``length`` (m) and the air's density ``rho_air``
    (kg/m^3)."""

    coefficients: WindCoefficients
    frontal_area: float
    lateral_area: float
    length: float
    rho_air: float = RHO_AIR

    def __post_init__(self) -> None:
        for name in ("frontal_area", "lateral_area", "length", "rho_air"):
            require_positive(name, getattr(self, name))

    @classmethod
    def blendermann(cls, vessel_type: str, frontal_area: float, lateral_area: float, length: float,
                    s_l: float = 0.0, rho_air: float = RHO_AIR) -> WindLoads:
        """A vessel of one of Blendermann's types (:data:`BLENDERMANN`); ``s_l`` the lateral area's centroid (m
        forward of midship)."""
        coefficients = BlendermannCoefficients(vessel_type, frontal_area, lateral_area, length, s_l)
        return cls(coefficients, frontal_area, lateral_area, length, rho_air)

    @classmethod
    def from_file(cls, path: str | Path, frontal_area: float, lateral_area: float, length: float,
                  rho_air: float = RHO_AIR) -> WindLoads:
        """A vessel with her coefficients read from ``path`` (:func:`read_wind_coefficients`)."""
        return cls(read_wind_coefficients(path), frontal_area, lateral_area, length, rho_air)

    @property
    def packed(self) -> tuple[np.ndarray, np.ndarray, np.ndarray, float, float, float, float]:
        """What :func:`wind_load_at` reads after the wind: the coefficients packed, the areas (m^2), the length (m)
        and the air's density (kg/m^3)."""
        return (*self.coefficients.packed, float(self.frontal_area), float(self.lateral_area), float(self.length),
                float(self.rho_air))

    def force(self, u: float, v: float, psi: float, wind_speed: float, wind_from: float) -> np.ndarray:
        """The load (X N, Y N, N N m), (3,), in a wind of ``wind_speed`` (m/s at 10 m) from the compass bearing
        ``wind_from`` (rad), she heading ``psi`` (rad) at ``u``, ``v`` (m/s): :func:`wind_force`."""
        return wind_force(self.coefficients, self.frontal_area, self.lateral_area, self.length, u, v, psi,
                          wind_speed, wind_from, self.rho_air)


def _require_non_negative(name: str, value: float) -> float:
    number = require_finite(name, value)
    if number < 0.0:
        raise ParameterError(f"{name} must be >= 0, got {value!r}")
    return number
