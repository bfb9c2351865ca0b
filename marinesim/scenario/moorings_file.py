"""A mooring file (``configs/moorings/*.toml``): a vessel's spread of catenary lines or her hawser, validated as a
scenario is (one pydantic model; errors name the file and the key), and the
:class:`~marinesim.station.moorings.Moorings` built from it in the scenario's water depth.

Anchors are given as mariners lay them, a compass bearing (deg) and a horizontal distance (m) from the set point,
for the heading the vessel holds on station (``heading_deg``); a hawser's fixed point above the water (an FPSO's
stern chock) instead as ``fixed_point_m`` = [north, east, z up from the waterline] (m from the set point); fairleads
in the body frame (x forward, y to starboard, z up from the waterline, m); line types by MoorPy's material name and
nominal diameter.
"""

from __future__ import annotations

import functools
import hashlib
import math
import tomllib
from pathlib import Path
from typing import Annotated

from pydantic import AfterValidator, Field, model_validator
from pydantic_core import PydanticCustomError

from marinesim.errors import MarinesimError, ScenarioError
from marinesim.scenario.model import Quantity, Section, _expecting, _refuse, read_small_file, validate
from marinesim.station.moorings import DIAMETER_RANGE_M, Line, Moorings, materials

MAX_LINES = 32
MAX_RADIUS_M = 20_000.0
"""The farthest anchor and the longest line (m)."""
MAX_FAIRLEAD_M = 500.0
"""The farthest a fairlead lies from the vessel's origin along any axis (m)."""
ANCHOR_KEYS = ("anchor_bearing_deg", "anchor_radius_m")
"""A line's far end as an anchor on the seabed; ``fixed_point_m`` instead: a hawser's fixed point."""


def _material(name: str) -> str:
    if name not in materials():
        raise PydanticCustomError("material", f"expected one of MoorPy's line types ({', '.join(materials())}), "
                                              f"got {name!r}")
    return name


class MooringLineOptions(Section):
    """``[[lines]]``: one mooring line."""

    name: Annotated[str, Field(min_length=1, max_length=40)] = Field(description="the line's name (faults name it)")
    anchor_bearing_deg: Annotated[float | None, Quantity("deg", ge=0.0, le=360.0, what="a compass bearing")] = Field(
        None, description="compass bearing of the anchor from the set point (with anchor_radius_m)")
    anchor_radius_m: Annotated[float | None, Quantity("m", gt=0.0, le=MAX_RADIUS_M)] = Field(
        None, description="horizontal distance of the anchor from the set point (with anchor_bearing_deg)")
    fixed_point_m: Annotated[list[float] | None, Quantity("m", ge=-MAX_RADIUS_M, le=MAX_RADIUS_M),
                             Field(min_length=3, max_length=3),
                             _expecting(f"[north, east, z] in metres, each in -{MAX_RADIUS_M:g}..{MAX_RADIUS_M:g}")
                             ] = Field(None, description="a hawser's far end instead of an anchor: [north, east, z up "
                                                         "from the waterline] of a fixed point from the set point")
    fairlead_m: Annotated[list[float], Quantity("m", ge=-MAX_FAIRLEAD_M, le=MAX_FAIRLEAD_M),
                          Field(min_length=3, max_length=3),
                          _expecting(f"[x, y, z] in metres, each in -{MAX_FAIRLEAD_M:g}..{MAX_FAIRLEAD_M:g}")] = Field(
        description="[x forward, y to starboard, z up from the waterline] from the vessel's origin")
    length_m: Annotated[float, Quantity("m", gt=0.0, le=MAX_RADIUS_M)] = Field(description="unstretched length")
    material: Annotated[str, AfterValidator(_material)] = Field(
        description="MoorPy's line type: chain (R4 studless), chain_studlink, wire, polyester, nylon, ...")
    diameter_m: Annotated[float, Quantity("m", ge=DIAMETER_RANGE_M[0], le=DIAMETER_RANGE_M[1])] = Field(
        description="nominal diameter")

    @model_validator(mode="after")
    def _one_far_end(self) -> MooringLineOptions:
        given = [key for key in ANCHOR_KEYS if getattr(self, key) is not None]
        if self.fixed_point_m is not None and given:
            raise _refuse(given[0], "give the far end one way: anchor_bearing_deg and anchor_radius_m (an anchor) or "
                                    "fixed_point_m (a hawser's fixed point), not both")
        if self.fixed_point_m is None and len(given) < len(ANCHOR_KEYS):
            missing, other = sorted(ANCHOR_KEYS, key=lambda key: key in given)
            raise _refuse(missing, f"required with {other} (an anchor), or fixed_point_m instead (a hawser's fixed "
                                   f"point)")
        return self


class MooringFile(Section):
    """A mooring file."""

    name: Annotated[str, Field(min_length=1, max_length=80)]
    source: Annotated[str, Field(min_length=1, max_length=2000)] = Field(description="where the figures come from")
    heading_deg: Annotated[float, Quantity("deg", ge=0.0, le=360.0, what="a compass heading")] = Field(
        description="the heading the vessel holds on station, the pattern laid for it")
    depth_m: Annotated[float | None, Quantity("m", gt=0.0, le=12_000.0)] = Field(
        None, description="the water depth the pattern is laid for: the anchors' depth (absent: the scenario's)")
    lines: Annotated[list[MooringLineOptions], Field(min_length=1, max_length=MAX_LINES)]

    @model_validator(mode="after")
    def _names_unique(self) -> MooringFile:
        names = [line.name for line in self.lines]
        for i, name in enumerate(names):
            if name in names[:i]:
                raise _refuse("lines", f"two lines named {name!r}")
        return self


def build_moorings(file: MooringFile, depth: float) -> Moorings:
    """The :class:`Moorings` a validated file describes in water ``depth`` (m)."""
    lines = []
    for options in file.lines:
        if options.fixed_point_m is not None:
            north, east, height = options.fixed_point_m
            lines.append(Line(options.name, (north, east), tuple(options.fairlead_m), options.length_m,
                              options.material, options.diameter_m, anchor_height_m=height))
            continue
        bearing = math.radians(options.anchor_bearing_deg)
        anchor = (options.anchor_radius_m * math.cos(bearing), options.anchor_radius_m * math.sin(bearing))
        lines.append(Line(options.name, anchor, tuple(options.fairlead_m), options.length_m, options.material,
                          options.diameter_m, file.depth_m))
    return Moorings(lines, depth, math.radians(file.heading_deg))


def load_moorings(path: Path, depth: float) -> Moorings:
    """Read, validate and build the mooring file ``path`` in water ``depth`` (m). Errors (:class:`ScenarioError`)
    name the file and the key, or the line."""
    path = Path(path)
    data = read_small_file(path, "mooring file")
    return _load(str(path), hashlib.sha256(data).hexdigest(), data, float(depth))


@functools.lru_cache(maxsize=16)
def _load(path: str, digest: str, data: bytes, depth: float) -> Moorings:
    try:
        file = validate(MooringFile, tomllib.loads(data.decode("utf-8-sig")))
    except (UnicodeDecodeError, tomllib.TOMLDecodeError) as error:
        raise ScenarioError(f"{path}: not valid TOML: {error}") from None
    except ScenarioError as error:
        raise ScenarioError(f"{path}: {error}") from None
    try:
        return build_moorings(file, depth)
    except MarinesimError as error:
        raise ScenarioError(f"{path}: {error}") from None
