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


# -- a hawser: the shuttle tanker astern of an FPSO (configs/moorings/tanker_hawser.toml) --------------------------

HAWSER = ROOT / "configs" / "moorings" / "tanker_hawser.toml"
HAWSER_DEPTH = 100.0
"""The offshore-loading exercise's water depth (m): the hawser, in the air, is clear of the seabed at any depth."""


@pytest.fixture(scope="module")
def hawser() -> Moorings:
    return load_moorings(HAWSER, HAWSER_DEPTH)


def chock_at(hawser: Moorings, span: float, psi: float) -> tuple[float, float]:
    """The vessel's (north m, east m) at heading ``psi`` (rad) that puts her bow chock ``span`` (m, horizontal) from
    the fixed point, on the line from the fixed point through the chock's place at the set point."""
    line = hawser.lines[0]
    x, y, _ = line.fairlead
    c0, s0 = math.cos(hawser.heading), math.sin(hawser.heading)
    fixed = np.array(line.anchor)
    away = np.array([x * c0 - y * s0, x * s0 + y * c0]) - fixed
    chock = fixed + span * away / np.linalg.norm(away)
    c, s = math.cos(psi), math.sin(psi)
    return float(chock[0] - (x * c - y * s)), float(chock[1] - (x * s + y * c))


def moorpy_hawser(hawser: Moorings, north: float, east: float, psi: float) -> float:
    """MoorPy's own solve of the same two-point line (x east, y north, z up): the fixed point and the bow chock
    where the vessel at (``north``, ``east``, ``psi``) has it, both fixed; its tension at the chock (N). Built in
    air (``rho`` 0), as ours: MoorPy 1.3's Line weighs a line with both ends above the water wet."""
    line = hawser.lines[0]
    system = moorpy.System(depth=hawser.depth, rho=0.0, g=G)
    system.setLineType(dnommm=line.diameter_m * 1000.0, material=line.material, name="hawser")
    x, y, z = line.fairlead
    c, s = math.cos(psi), math.sin(psi)
    fixed = system.addPoint(1, np.array([line.anchor[1], line.anchor[0], line.anchor_height_m]))
    chock = system.addPoint(1, np.array([east + x * s + y * c, north + x * c - y * s, z]))
    system.addLine(line.length_m, "hawser", pointA=fixed.number, pointB=chock.number)
    system.initialize()
    system.solveEquilibrium()
    return float(system.lineList[0].TB)


def test_hawser_file_is_just_taut_at_the_set_point(hawser):
    """The shipped hawser: 92.4 m of 0.14 m nylon over 93.1 m chock to chock, some 190 kN of pretension (the
    header's figure), the FPSO's stern 90 m ahead of her bow on her heading 260 deg, 25 m up."""
    (line,) = hawser.lines
    assert line.hawser and line.anchor_height_m == 25.0
    assert math.degrees(hawser.heading) == pytest.approx(260.0)
    assert math.hypot(*line.anchor) == pytest.approx(213.0, abs=0.01)
    assert math.degrees(math.atan2(line.anchor[1], line.anchor[0])) % 360.0 == pytest.approx(260.0, abs=0.01)
    assert 100e3 < hawser.pretensions[0] < 300e3
    assert hawser.pretensions[0] == pytest.approx(188e3, rel=0.02)


@pytest.mark.parametrize("yaw_deg", [0.0, 25.0, -40.0])
def test_taut_hawser_tension_equals_moorpys_solve(hawser, yaw_deg):
    """Where the hawser is taut (its chock 0.2 % to 15 % beyond its length from the fixed point) and with the tanker
    weathervaned off her set heading, our tabulated tension equals MoorPy's System solve of the same line between
    two fixed points within 1 %. Failing: the fixed point's height, the weight in air or the table's knee wrong."""
    psi = hawser.heading + math.radians(yaw_deg)
    length = hawser.lines[0].length_m
    for stretch in (1.002, 1.005, 1.01, 1.03, 1.06, 1.1, 1.15):
        span = math.sqrt((stretch * length) ** 2 - 5.0 ** 2)
        north, east = chock_at(hawser, span, psi)
        ours = hawser.tensions(north, east, psi)[0]
        assert ours == pytest.approx(moorpy_hawser(hawser, north, east, psi), rel=0.01), stretch


def test_slack_hawser_hangs_under_its_weight(hawser):
    """Closer than its length the hawser goes slack: its tension falls below its own weight in air (some 10 kN)
    and stays there however close the tanker comes (held below the table); MoorPy's solve of the slack line
    agrees within 1 % over the table."""
    line = hawser.lines[0]
    weight = line.weight_n_m * line.length_m
    assert 9e3 < weight < 12e3
    psi = hawser.heading
    for fraction in (0.95, 0.9, 0.85):
        north, east = chock_at(hawser, fraction * line.length_m, psi)
        slack = hawser.tensions(north, east, psi)[0]
        assert 0.0 < slack < weight
        assert slack == pytest.approx(moorpy_hawser(hawser, north, east, psi), rel=0.01)
    for span in (60.0, 30.0, 5.0):
        north, east = chock_at(hawser, span, psi)
        assert 0.0 < hawser.tensions(north, east, psi)[0] < weight
        assert np.linalg.norm(hawser.force(north, east, psi)[:2]) < 0.5 * weight


@pytest.mark.parametrize("yaw_deg", [20.0, -20.0])
def test_hawser_pulls_her_bow_towards_the_fixed_point(hawser, yaw_deg):
    """Her bow chock where it is at the set point but her heading 20 deg off the hawser's line: the pull, at the
    pretension, points from the chock to the fixed point, and its yaw moment (about her origin, 120 m aft of the
    chock) turns her bow back towards it: -x H sin(20 deg) with the bow swung to starboard, + to port. Failing: a
    sign of the body frame or the heading wrong, and a weathervaning tanker would turn away from the FPSO."""
    psi = hawser.heading + math.radians(yaw_deg)
    line = hawser.lines[0]
    x, y, _ = line.fairlead
    c0, s0 = math.cos(hawser.heading), math.sin(hawser.heading)
    north, east = chock_at(hawser, math.hypot(line.anchor[0] - x * c0, line.anchor[1] - x * s0), psi)
    along, sideways, moment = hawser.force(north, east, psi)
    c, s = math.cos(psi), math.sin(psi)
    pull = np.array([along * c - sideways * s, along * s + sideways * c])  # earth frame, north and east
    chock = np.array([north + x * c - y * s, east + x * s + y * c])
    to_fixed = np.array(line.anchor) - chock
    cross = pull[0] * to_fixed[1] - pull[1] * to_fixed[0]
    assert cross == pytest.approx(0.0, abs=1e-9 * np.linalg.norm(pull) * np.linalg.norm(to_fixed))  # parallel
    assert pull @ to_fixed > 0.0
    assert hawser.tensions(north, east, psi)[0] == pytest.approx(hawser.pretensions[0], rel=1e-6)
    off = (psi - math.atan2(to_fixed[1], to_fixed[0]) + math.pi) % (2.0 * math.pi) - math.pi  # bow off the line
    assert math.degrees(off) == pytest.approx(yaw_deg, abs=0.05)
    assert math.copysign(1.0, moment) == -math.copysign(1.0, yaw_deg)
    assert moment == pytest.approx(-x * np.linalg.norm(pull) * math.sin(off), rel=1e-6)
    assert along > 0.0 and abs(along) > abs(sideways)  # still mostly a pull ahead


def test_parted_hawser_pulls_nothing(hawser):
    """The hawser parted (the instructor's fault): no force, no moment, no tension, wherever she is."""
    parted = hawser.with_failed("hawser")
    psi = hawser.heading + 0.3
    north, east = chock_at(hawser, 100.0, psi)
    assert np.all(hawser.force(north, east, psi) != 0.0)
    assert np.all(parted.force(north, east, psi) == 0.0)
    assert parted.tensions(north, east, psi)[0] == 0.0 and parted.pretensions[0] == 0.0


def hawser_line(**keys) -> Line:
    """The shipped hawser's line, with ``keys`` changed."""
    psi = math.radians(260.0)
    given = dict(name="hawser", anchor=(213.0 * math.cos(psi), 213.0 * math.sin(psi)), fairlead=(120.0, 0.0, 20.0),
                 length_m=92.4, material="nylon", diameter_m=0.14, anchor_height_m=25.0) | keys
    return Line(**given)


@pytest.mark.parametrize("keys, expected", [
    (dict(anchor_height_m=-3.0), "line hawser: fixed point 3.0 m below the waterline: a hawser's far end is a point "
                                 "above the water"),
    (dict(fairlead=(120.0, 0.0, -2.0)), "line hawser: fairlead 2.0 m below the waterline: a hawser runs in air"),
    (dict(anchor_depth_m=100.0), "line hawser: give anchor_depth_m (an anchor on the seabed) or anchor_height_m (a "
                                 "hawser's fixed point above the water), not both"),
    (dict(length_m=70.0), "line hawser: 70.0 m long, too short to reach its fairlead 93.1 m from the fixed point "
                          "(stretched to its breaking load: 84.0 m)"),
])
def test_bad_hawser_is_refused(keys, expected):
    """A fixed point under the water, a hawser's fairlead under it, an anchor depth as well, a hawser too short to
    reach its fairlead without breaking: one line naming the line and the numbers."""
    with pytest.raises(ParameterError) as error:
        Moorings([hawser_line(**keys)], HAWSER_DEPTH, math.radians(260.0))
    assert one_line(error.value) == expected


@pytest.mark.parametrize("change, expected", [
    (("fixed_point_m = [", "anchor_bearing_deg = 260.0\nfixed_point_m = ["),
     r"lines\[0\]\.anchor_bearing_deg: give the far end one way: anchor_bearing_deg and anchor_radius_m \(an "
     r"anchor\) or fixed_point_m \(a hawser's fixed point\), not both"),
    (("fixed_point_m = [-36.99, -209.76, 25.0]", "anchor_radius_m = 213.0"),
     r"lines\[0\]\.anchor_bearing_deg: required with anchor_radius_m \(an anchor\), or fixed_point_m instead \(a "
     r"hawser's fixed point\)$"),
    (("-209.76, 25.0]", "-209.76, -4.0]"),
     r"line hawser: fixed point 4\.0 m below the waterline: a hawser's far end is a point above the water"),
    (("-209.76, 25.0]", "-209.76]"), r"lines\[0\]\.fixed_point_m: expected \[north, east, z\] in metres"),
])
def test_bad_hawser_file_is_refused(tmp_path: Path, change, expected):
    """Both ways of giving a line's far end, half an anchor, a fixed point under the water, a fixed point of two
    coordinates: one line naming the file and the key (or the line)."""
    path = tmp_path / "bad.toml"
    text = HAWSER.read_text()
    assert change[0] in text
    path.write_text(text.replace(*change, 1))
    with pytest.raises(ScenarioError) as error:
        load_moorings(path, HAWSER_DEPTH)
    assert re.search(rf"bad\.toml: {expected}", one_line(error.value))


def test_hawser_table_starts_where_moorpy_solves_a_slack_hawser(monkeypatch):
    """Should MoorPy's catenary fail for a hawser hanging well slack, its table starts at the first span MoorPy
    solves and the tension closer in is held there (small: its weight). Forced here: MoorPy 1.3 solves these."""
    import moorpy.Catenary
    from moorpy.helpers import CatenaryError

    from marinesim.station import moorings as module

    solve = moorpy.Catenary.catenary

    def failing(span, height, length, *args, **keys):
        if span < 0.9 * length and keys.get("CB", 0.0) < 0.0:
            raise CatenaryError("forced")
        return solve(span, height, length, *args, **keys)

    module._table.cache_clear()
    monkeypatch.setattr(moorpy.Catenary, "catenary", failing)
    try:
        moorings = Moorings([hawser_line()], HAWSER_DEPTH, math.radians(260.0))
    finally:
        module._table.cache_clear()
    low = moorings.span_range[0, 0]
    assert 0.9 * 92.4 <= low < 0.9 * 92.4 + 0.5
    at_low = moorings.tensions(*chock_at(moorings, low, moorings.heading), moorings.heading)[0]
    closer = moorings.tensions(*chock_at(moorings, 40.0, moorings.heading), moorings.heading)[0]
    assert closer == pytest.approx(at_low, rel=1e-9) and closer < 12e3


def test_hawser_moors_in_deep_water(hawser):
    """A scenario without a water depth (deep water): the hawser, clear of the seabed, pulls as in 100 m; an
    anchored line cannot be laid there and is refused in one line."""
    deep = load_moorings(HAWSER, math.inf)
    psi = hawser.heading + 0.2
    for span in (80.0, 93.0, 100.0):
        north, east = chock_at(hawser, span, psi)
        np.testing.assert_array_equal(deep.force(north, east, psi), hawser.force(north, east, psi))
    with pytest.raises(ParameterError) as error:
        Moorings([chain()], math.inf)
    assert one_line(error.value) == ("line 3: an anchor on the seabed needs a water depth, got deep water (only a "
                                     "hawser to a fixed point moors a vessel there)")


def test_the_shuttle_tanker_on_her_hawser_weathervanes_and_falls_back_when_it_parts():
    """configs/tanker_hawser.toml (the tanker astern of an FPSO's stern on a 92 m nylon hawser, 30 t astern pull,
    wind from 265 deg, 5 deg off her heading): for five minutes the hawser holds her (its tension in the record,
    hundreds of kN on average as she surges on it, never at its breaking load), within its reach of the fixed
    point; her heading has turned towards the wind. Parted at five minutes (the instructor's fault), its tension is zero and she falls back from the FPSO.
    What would be wrong if not: a hawser that does not hold, a record without its tension, or a parted line that
    still pulls."""
    from marinesim.scenario import load_scenario
    from marinesim.session.timeline import Simulation

    scenario = load_scenario(ROOT / "configs" / "tanker_hawser.toml")
    sim = Simulation(scenario, wake=False)
    sim.order(fault="line:hawser", at=300.0)
    times = np.arange(0.0, 600.0, 5.0)
    record = sim.frame(times)
    tension = record["line_hawser_tension_kn"]
    holding, parted = times < 300.0, times > 305.0
    assert tension[holding].mean() > 200.0 and tension[holding].max() < 4690.0, tension[holding]
    assert np.all(tension[parted] == 0.0)
    fixed = np.array([-36.99, -209.76])
    reach = np.hypot(record["north_m"] - fixed[0], record["east_m"] - fixed[1])
    assert reach[holding].max() < 213.0 + 0.2 * 92.4, "the hawser (92 m, 20 % stretch at its breaking load) holds her"
    assert reach[-1] > reach[holding].max() + 20.0, "parted, she falls back from the FPSO"
    heading = record["heading_deg"][(times > 200.0) & (times < 300.0)].mean()
    assert 260.5 < heading < 270.0, f"she weathervanes towards the wind from 265 deg, heading {heading:.1f}"
