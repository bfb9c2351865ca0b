"""Catenary mooring lines (:mod:`marinesim.station.moorings`) against MoorPy's own system solve.

The shipped eight-line chain spread of the semisubmersible (``configs/moorings/semisub_8_chain.toml``, 150 m water,
heading 250 deg) is built once. MoorPy's reference is an independent build of the same lines as a MoorPy ``System``
(x east, y north, z up; the body's yaw a math angle): what agrees between the two checks our frames, the fairlead
geometry, the use of MoorPy's line library and the interpolated tables at once.
"""

from __future__ import annotations

import math
import re
from pathlib import Path

import moorpy
import numpy as np
import pytest
from scipy.integrate import solve_ivp
from scipy.optimize import root

from conftest import ROOT
from marinesim.constants import RHO_SEAWATER, G
from marinesim.errors import ParameterError, ScenarioError
from marinesim.scenario.moorings_file import load_moorings
from marinesim.station.moorings import Line, Moorings

CONFIG = ROOT / "configs" / "moorings" / "semisub_8_chain.toml"
DEPTH = 150.0
MASS = 27.1625e6
"""The semisubmersible's mass (kg) and her low-frequency surge added mass (MSS semisub: MA[0, 0], kg)."""
ADDED_MASS = 1.7e7
FORCE = 1.0e6
"""A steady horizontal load (N), e.g. the mean wind, current and wave drift together."""


@pytest.fixture(scope="module")
def moorings() -> Moorings:
    return load_moorings(CONFIG, DEPTH)


def moorpy_system(moorings: Moorings, force_north: float = 0.0, force_east: float = 0.0,
                  coupled: bool = False) -> tuple[moorpy.System, moorpy.Body]:
    """The same lines as a MoorPy System: a body free in surge, sway and yaw (or coupled: held) under the
    horizontal force (N) applied at its origin, anchors fixed on the seabed."""
    system = moorpy.System(depth=moorings.depth, rho=RHO_SEAWATER, g=G)
    yaw = math.pi / 2.0 - moorings.heading  # compass heading -> math angle about z up
    body = system.addBody(-1 if coupled else 0, np.array([0.0, 0.0, 0.0, 0.0, 0.0, yaw]), DOFs=[0, 1, 5],
                          f6Ext=np.array([force_east, force_north, 0.0, 0.0, 0.0, 0.0]))
    for line in moorings.lines:
        if line.name in moorings.failed:
            continue
        kind = f"{line.material}{line.diameter_m * 1000:.0f}"
        system.setLineType(dnommm=line.diameter_m * 1000.0, material=line.material, name=kind)
        anchor = system.addPoint(1, np.array([line.anchor[1], line.anchor[0], -moorings.depth]))
        x, y, z = line.fairlead
        on_body = np.array([x, -y, z])  # MoorPy's body y to port
        fairlead = system.addPoint(1, on_body)
        body.attachPoint(fairlead.number, on_body)
        system.addLine(line.length_m, kind, pointA=anchor.number, pointB=fairlead.number)
    system.initialize()
    return system, body


def equilibrium(moorings: Moorings, force_north: float, force_east: float) -> np.ndarray:
    """(north m, east m, psi rad) where the lines balance the earth-frame force (N) applied at the origin."""
    def residual(q: np.ndarray) -> np.ndarray:
        c, s = math.cos(q[2]), math.sin(q[2])
        applied = np.array([force_north * c + force_east * s, -force_north * s + force_east * c, 0.0])
        return (moorings.force(*q) + applied) / np.array([1e5, 1e5, 1e7])

    solution = root(residual, np.array([0.0, 0.0, moorings.heading]), tol=1e-12)
    assert solution.success, solution.message
    return solution.x


LOADS = {"1 MN from the north": (-FORCE, 0.0), "1 MN from the east": (0.0, -FORCE),
         "1 MN from 300 deg": (-FORCE * math.cos(math.radians(300.0)), -FORCE * math.sin(math.radians(300.0)))}


@pytest.mark.parametrize("load", LOADS)
def test_static_offset_equals_moorpys_equilibrium(moorings, load):
    """The offset under a steady load from our tables equals MoorPy's System.solveEquilibrium within 1 % (or 5 cm),
    the yaw within 1e-4 rad, every line's fairlead tension within 0.1 %. Failing: a frame mix-up (north/east,
    starboard/port, the heading's sense) shows as an offset in the wrong direction; a wrong line property or a
    coarse table as a wrong size."""
    force_north, force_east = LOADS[load]
    north, east, psi = equilibrium(moorings, force_north, force_east)
    system, body = moorpy_system(moorings, force_north, force_east)
    system.solveEquilibrium()
    ref_east, ref_north, ref_yaw = body.r6[0], body.r6[1], body.r6[5]
    offset = math.hypot(north, east)
    assert 2.0 < offset < 10.0  # a stiff chain spread in 150 m: a few metres per MN
    assert math.hypot(north - ref_north, east - ref_east) <= max(0.01 * offset, 0.05), (north, east, ref_north,
                                                                                           ref_east)
    assert abs((psi - moorings.heading) + (ref_yaw - (math.pi / 2.0 - moorings.heading))) < 1e-4
    assert north * force_north + east * force_east > 0.0  # pushed the way the load pushes
    ours = moorings.tensions(north, east, psi)
    theirs = np.array([line.TB for line in system.lineList])
    np.testing.assert_allclose(ours, theirs, rtol=1e-3)


def test_surge_period_from_moorpys_stiffness_and_free_decay(moorings):
    """Surge stiffness (along her heading) from MoorPy's coupled-body stiffness equals ours within 1 %; a free decay
    of mass + added mass on our force law swings with 2 pi sqrt((M + A11) / K11) within 2 %. Failing: the
    stiffness's axes or the tables' slopes are wrong (the period is what a moored vessel's surge resonance, and
    so her slow-drift motion, hangs on)."""
    system, _ = moorpy_system(moorings, coupled=True)
    k_moorpy = system.getCoupledStiffnessA()  # x east, y north, yaw (the body's DOFs)
    along = np.array([math.sin(moorings.heading), math.cos(moorings.heading)])
    k11_moorpy = along @ k_moorpy[:2, :2] @ along
    ours = moorings.stiffness()
    assert ours[0, 0] == pytest.approx(k11_moorpy, rel=0.01)
    assert ours[2, 2] == pytest.approx(k_moorpy[2, 2], rel=0.01)  # yaw: the fairleads' lever arms
    assert system.getCoupledStiffness()[0, 0] == pytest.approx(k_moorpy[0, 0], rel=0.01)
    period = 2.0 * math.pi * math.sqrt((MASS + ADDED_MASS) / k11_moorpy)
    assert 60.0 < period < 120.0  # a semisubmersible's moored surge period

    c, s = math.cos(moorings.heading), math.sin(moorings.heading)

    def rates(t: float, y: np.ndarray) -> list[float]:
        return [y[1], moorings.force(y[0] * c, y[0] * s, moorings.heading)[0] / (MASS + ADDED_MASS)]

    decay = solve_ivp(rates, (0.0, 6.0 * period), [0.05, 0.0], rtol=1e-9, atol=1e-12, max_step=period / 50.0,
                      dense_output=True)
    t = np.linspace(0.0, 6.0 * period, 20001)
    x = decay.sol(t)[0]
    up = np.nonzero((x[:-1] < 0.0) & (x[1:] >= 0.0))[0]
    crossings = t[up] - x[up] * (t[up + 1] - t[up]) / (x[up + 1] - x[up])
    assert len(crossings) >= 4
    assert np.mean(np.diff(crossings)) == pytest.approx(period, rel=0.02)


def test_failed_line_loads_its_neighbour_and_the_offset_grows(moorings):
    """The most loaded line under 1 MN from the north parts: her offset under the same load grows, the other line
    of that corner takes more tension, the parted line carries none, and MoorPy without that line agrees on the new
    offset. Failing: a parted line still pulling (the instructor's fault does nothing) or the wrong line parted."""
    intact = equilibrium(moorings, -FORCE, 0.0)
    tensions = moorings.tensions(*intact)
    worst = int(np.argmax(tensions))
    fairleads = np.array([line.fairlead for line in moorings.lines])
    gaps = np.linalg.norm(fairleads - fairleads[worst], axis=1)
    gaps[worst] = np.inf
    neighbour = int(np.argmin(gaps))
    broken = moorings.with_failed(moorings.names[worst])
    assert broken.failed == {moorings.names[worst]} and moorings.failed == frozenset()
    after = equilibrium(broken, -FORCE, 0.0)
    assert math.hypot(*after[:2]) > 1.2 * math.hypot(*intact[:2])
    now = broken.tensions(*after)
    assert now[worst] == 0.0
    assert now[neighbour] > 1.2 * tensions[neighbour]
    system, body = moorpy_system(broken, -FORCE, 0.0)
    system.solveEquilibrium()
    assert math.hypot(after[0] - body.r6[1], after[1] - body.r6[0]) <= max(0.01 * math.hypot(*after[:2]), 0.05)


def test_tension_carries_on_past_the_table(moorings):
    """Driven past the tabulated spans (beyond 3 x MBL on the taut side), the taut lines' tension keeps growing
    smoothly, no jump at the table's end. Failing: the extrapolation drops the line's pull or jumps."""
    direction = np.array([math.cos(math.radians(110.0)), math.sin(math.radians(110.0))])  # away from lines 1-2
    steps = np.linspace(0.0, 70.0, 701)
    pulls = np.array([moorings.tensions(*(d * direction), moorings.heading)[:2] for d in steps])
    assert np.all(np.diff(pulls, axis=0) > 0.0)
    jumps = np.abs(np.diff(pulls, n=2, axis=0))
    assert jumps.max() < 0.05 * np.abs(np.diff(pulls, axis=0)).max()
    c, s = math.cos(moorings.heading), math.sin(moorings.heading)
    for line, (low, high) in zip(moorings.lines[:2], moorings.span_range[:2]):
        x, y, _ = line.fairlead
        fairlead = 70.0 * direction + np.array([x * c - y * s, x * s + y * c])
        assert np.hypot(*(np.array(line.anchor) - fairlead)) > high  # the walk did leave the table


def chain(name: str = "3", anchor=(-850.0, 0.0), length: float = 880.0, **keys) -> Line:
    """100 mm chain from an anchor 850 m north of a fairlead 10 m deep on the vessel's origin, 150 m water."""
    return Line(name, anchor, (0.0, 0.0, -10.0), length, "chain", 0.1, **keys)


def one_line(error: Exception) -> str:
    text = str(error)
    assert "\n" not in text
    return text


def test_anchor_above_the_seabed_is_refused():
    """An anchor stated 12 m above a 150 m seabed: MoorPy would hang the line from it; we refuse, naming the line
    and the numbers."""
    with pytest.raises(ParameterError) as error:
        Moorings([chain(anchor_depth_m=138.0)], DEPTH)
    assert one_line(error.value) == "line 3: anchor 12.0 m above the seabed (depth 150 m)"


def test_file_laid_for_another_depth_is_refused():
    """The shipped file is laid for 150 m: loaded for a 300 m scenario its anchors would float 150 m up."""
    with pytest.raises(ScenarioError) as error:
        load_moorings(CONFIG, 300.0)
    assert re.search(r"semisub_8_chain\.toml: line 1: anchor 150\.0 m above the seabed \(depth 300 m\)$",
                     one_line(error.value))


def test_line_too_short_is_refused():
    """700 m of chain cannot reach a fairlead 861 m away (it breaks first); 852 m reaches it only above its
    breaking load (a 10.3 MN pull against 9.91 MN: 0.7 % stretch)."""
    with pytest.raises(ParameterError) as error:
        Moorings([chain(length=700.0)], DEPTH)
    assert one_line(error.value).startswith("line 3: 700.0 m long, too short to reach its fairlead")
    with pytest.raises(ParameterError) as error:
        Moorings([chain(length=852.0)], DEPTH)
    assert re.match(r"line 3: tension [\d.]+ MN at the set point is above its breaking load 9\.91 MN",
                    one_line(error.value))


def test_unknown_line_type_is_refused():
    """A material MoorPy's library does not have is refused, the known ones listed."""
    with pytest.raises(ParameterError) as error:
        Line("3", (-850.0, 0.0), (0.0, 0.0, -10.0), 880.0, "steel", 0.1)
    assert one_line(error.value).startswith("line 3: line type 'steel' is not in MoorPy's library (known: chain")


def test_unknown_failed_line_is_refused(moorings):
    with pytest.raises(ParameterError) as error:
        moorings.with_failed("9")
    assert one_line(error.value) == "line 9: no such mooring line (lines: 1, 2, 3, 4, 5, 6, 7, 8)"


@pytest.mark.parametrize("change, expected", [
    (("length_m = 880.0\n", ""), r"lines\[0\]\.length_m: required"),
    (('material = "chain"\n', 'material = "steel"\n'), r"lines\[0\]\.material: expected one of MoorPy's line types"),
])
def test_bad_file_is_refused(tmp_path: Path, change, expected):
    """A mooring file missing a line's length, or naming an unknown material: one line naming the file and key."""
    path = tmp_path / "bad.toml"
    path.write_text(CONFIG.read_text().replace(*change, 1))
    with pytest.raises(ScenarioError) as error:
        load_moorings(path, DEPTH)
    assert re.search(rf"bad\.toml: {expected}", one_line(error.value))
