"""Rotations no floating body has are noted where a table is read (``marinesim rao``, ``export``, ``run``).

Two rules (``marinesim/vessel/rao.py``, :func:`non_physical_rotations`): a roll, pitch or yaw at a speed between
two others over 3x both neighbouring speeds' (same frequency and heading, over a quarter of the wave slope k), and
one over the wave slope k at an encounter frequency over 3x the DOF's resonance, where an inertia-controlled
rotation is about 1/8 of it. One line per DOF and speed names the worst point and what it was compared with.
The S175's VERES table is checked against the file's own numbers, parsed here from its lines.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from conftest import ROOT, cli, write
from marinesim.constants import KNOT
from marinesim.errors import ScenarioError
from marinesim.scenario import load_scenario
from marinesim.vessel import read_rao
from marinesim.vessel.rao import make_table
from marinesim.vessel.veres import TITLE_LINES

S175 = ROOT / "rao" / "s175" / "input.re1"
SUPPLY = ROOT / "rao" / "supply" / "input.re1"
DATA = ROOT / "tests" / "data"


def found(table) -> list[str]:
    return [note for note in table.notes if note.startswith("non-physical")]


def veres_roll_deg_m(path) -> tuple[dict[tuple[int, float, float], float], float]:
    """The file's roll amplitude (deg/m) by (speed block, heading deg, frequency rad/s), read from its lines as
    VERES writes them (per speed its speed line, per heading the HEAD line, per frequency the FREQ line and six
    lines ``DOF Re Im`` in rad/m), and the file's g (m/s^2)."""
    lines = path.read_text().splitlines()
    g = float(lines[TITLE_LINES].split()[1])
    counts = TITLE_LINES + 3                                # RHO G; LPP B T; LCG VCG; then the counts' line
    nvel, nhead, nfreq, ndof = (int(word) for word in lines[counts].split())
    roll, i = {}, counts + 1
    for speed in range(nvel):
        i += 1                                              # the speed line
        for _ in range(nhead):
            head = float(lines[i])
            i += 1
            for _ in range(nfreq):
                freq = float(lines[i])
                dof, re, im = lines[i + 4].split()
                assert dof == "4"
                roll[speed, round(head, 3), round(freq, 3)] = math.degrees(math.hypot(float(re), float(im)))
                i += 1 + ndof
    assert i == len(lines)
    return roll, g


@pytest.fixture(scope="module")
def s175():
    return read_rao(S175)


def test_the_s175s_roll_at_15_kn_is_noted_with_the_files_numbers(s175):
    """At heading 150 deg and 1.047 rad/s the file's roll is 0.16, 0.33, 0.89, 7.38, 1.25 deg/m at 0, 5, 10, 15,
    20 kn against a wave slope k = w^2 / g of 6.4 deg/m: 15 kn jumps 5.9x both neighbours (rule a) and exceeds
    the slope at an encounter frequency 5.7x the zero-speed beam-sea roll peak (0.314 rad/s), where an
    inertia-controlled roll is about 1/30 of it (rule b). All of its flagged points make one line: a failure means
    the rule misses a spike no hull has, misreports it, or prints one line per point."""
    raw, g = veres_roll_deg_m(S175)
    roll = [raw[s, 150.0, 1.047] for s in range(5)]
    np.testing.assert_allclose(roll, [0.16, 0.33, 0.89, 7.38, 1.25], atol=0.005)
    slope = math.degrees(1.047198**2 / g)
    assert slope == pytest.approx(6.4, abs=0.01)
    beam = {w: value for (s, head, w), value in raw.items() if s == 0 and head == 90.0}
    resonance = max(beam, key=beam.get)
    encounter = 1.047198 + 1.047198**2 / g * 15.0 * KNOT * math.cos(math.radians(30.0))  # bow-quartering: up
    assert resonance == pytest.approx(0.314, abs=1e-3) and encounter / resonance > 5.0
    line, = [note for note in found(s175) if note.startswith("non-physical roll RAO at 15 kn")]
    assert line.startswith(f"non-physical roll RAO at 15 kn, 150 deg, 1.047 rad/s: {roll[3]:.3g} deg/m against "
                           f"{roll[2]:.3g} and {roll[4]:.3g} at 10 and 20 kn (wave slope {slope:.3g} deg/m; "
                           f"{roll[3] / slope:.3g}x it at an encounter frequency {encounter / resonance:.2g}x the "
                           "resonance)"), line
    assert "over 3x both neighbouring speeds" in line and "over 1x the wave slope beyond 3x the resonance" in line
    assert f"roll resonance: {resonance:.3g} rad/s" in line and "its first peak at 0 kn" in line


def test_only_the_s175s_roll_at_15_and_20_kn_is_noted(s175):
    """Nothing at 0, 5 or 10 kn, nor in pitch or yaw. 20 kn, the table's last speed, has no second neighbour to
    jump against, but its bow-quartering roll is as wrong: at 130 deg it runs 0.48, 5.12, 10.5, 9.04, 1.37 deg/m
    from 0.898 to 1.257 rad/s, 10.5 deg/m being 1.6x the wave slope at an encounter frequency 5.7x the roll
    resonance (rule b). A failure means a rule cries wolf on the sound speeds or misses the other bad one."""
    assert [note[:note.index(" kn")] for note in found(s175)] == ["non-physical roll RAO at 15",
                                                                  "non-physical roll RAO at 20"]
    raw, g = veres_roll_deg_m(S175)
    spike = [raw[4, 130.0, w] for w in (0.898, 0.967, 1.047, 1.142, 1.257)]
    np.testing.assert_allclose(spike, [0.48, 5.12, 10.5, 9.04, 1.37], atol=0.01)
    slope = math.degrees(1.047198**2 / g)
    line = found(s175)[1]
    assert line.startswith(f"non-physical roll RAO at 20 kn, 130 deg, 1.047 rad/s: {spike[2]:.3g} deg/m (wave slope "
                           f"{slope:.3g} deg/m; {spike[2] / slope:.3g}x it"), line
    assert spike[2] / slope > 1.5 and "neighbouring" not in line


@pytest.mark.parametrize("path", [ROOT / "rao" / "tanker" / "tanker.4", SUPPLY, ROOT / "rao" / "semisub" / "semisub.4",
                                  DATA / "aqwa" / "cylinder_excerpt.LIS",
                                  DATA / "hams" / "cylinder" / "Output" / "Hydrostar_format" / "Motion_3.rao",
                                  DATA / "orcaflex" / "cylinder_vessel_type.yml"])
def test_real_tables_of_sound_sources_carry_no_such_note(path):
    """WAMIT, VERES at zero speed, AQWA, HAMS and OrcaFlex tables of real hulls stay far under both rules (beyond
    3x their resonance under 0.45x the wave slope): a failure means a rule cries wolf."""
    assert found(read_rao(path)) == []


@pytest.fixture(scope="module")
def supply():
    return read_rao(SUPPLY)


def three_speeds(table, scale: dict[tuple[float, float], float]) -> list[str]:
    """The notes on ``table`` (one speed) repeated at 0, 5 and 10 kn, its roll at 5 kn times ``scale[heading deg,
    w rad/s]`` at the points named."""
    values = np.repeat(table.values, 3, axis=0)
    for (heading, omega), factor in scale.items():
        b = int(np.argmin(np.abs(np.degrees(table.beta) - heading)))
        w = int(np.argmin(np.abs(table.omega - omega)))
        values[1, b, w, 3] *= factor
    return found(make_table(table.omega, table.beta, np.array([0.0, 5.0, 10.0]) * KNOT, values, g=table.g))


def test_an_injected_jump_is_noted_at_its_speed(supply):
    """The supply ship's table at 0, 5 and 10 kn (the same values: nothing to note) with its roll at 5 kn, 150 deg,
    1.047 rad/s (0.14x the wave slope, encounter frequency 2x the roll resonance) made 5x its neighbours':
    one line names that speed and point and both neighbours; a failure means the jump goes unseen or misplaced."""
    assert three_speeds(supply, {}) == []
    w = int(np.argmin(np.abs(supply.omega - 1.047)))
    b = int(np.argmin(np.abs(np.degrees(supply.beta) - 150.0)))
    roll = math.degrees(abs(supply.values[0, b, w, 3]))
    line, = three_speeds(supply, {(150.0, 1.047): 5.0})
    assert line.startswith(f"non-physical roll RAO at 5 kn, 150 deg, 1.047 rad/s: {5 * roll:.3g} deg/m against "
                           f"{roll:.3g} and {roll:.3g} at 0 and 10 kn"), line
    assert "at 5 kn 1 point over 3x both neighbouring speeds, at headings 150..150 deg" in line


def test_a_peak_where_speed_meets_the_resonance_is_not_a_jump(supply):
    """In following quartering seas (30 deg) the encounter frequency of 1.047 rad/s at 5 kn is 0.80 rad/s,
    1.2x the supply ship's roll resonance (0.661 rad/s): a speed there may truly peak against its neighbours, so the
    same 5x is left alone there while at 150 deg (encounter 1.30 rad/s) it is noted."""
    k = 1.047198**2 / supply.g
    for heading, encounter in ((30.0, 0.80), (150.0, 1.30)):
        assert 1.047198 - k * 5.0 * KNOT * math.cos(math.radians(heading)) == pytest.approx(encounter, abs=0.005)
    line, = three_speeds(supply, {(30.0, 1.047): 5.0, (150.0, 1.047): 5.0})
    assert "5 kn, 150 deg" in line and "1 point over" in line


def test_a_rotation_over_the_wave_slope_far_above_resonance_is_noted_in_a_table_of_one_speed(supply):
    """Rule b needs no other speed: the supply ship's roll at 150 deg, 2.513 rad/s (3.8x its roll resonance
    0.661 rad/s) set to 2x the wave slope is noted, where an inertia-controlled roll is under 1/13 of it; the same
    at 0.898 rad/s (1.4x the resonance, where a lightly damped roll may well exceed the slope) is not."""
    def with_roll(omega: float) -> list[str]:
        values = supply.values.copy()
        w = int(np.argmin(np.abs(supply.omega - omega)))
        b = int(np.argmin(np.abs(np.degrees(supply.beta) - 150.0)))
        values[0, b, w, 3] = 2.0 * supply.omega[w] ** 2 / supply.g
        return found(make_table(supply.omega, supply.beta, supply.speed, values, g=supply.g))

    line, = with_roll(2.513)
    slope = math.degrees(2.513274**2 / supply.g)
    assert line.startswith(f"non-physical roll RAO at 0 kn, 150 deg, 2.513 rad/s: {2 * slope:.3g} deg/m (wave slope "
                           f"{slope:.3g} deg/m; 2x it at an encounter frequency 3.8x the resonance)"), line
    assert "roll resonance: 0.661 rad/s" in line
    assert with_roll(0.898) == []


def test_marinesim_rao_prints_the_note():
    """The user reading the S175 with ``marinesim rao`` is told, in one line per DOF and speed."""
    report = cli("rao", str(S175))
    assert report.returncode == 0, report.stderr
    lines = [line for line in report.stdout.splitlines() if line.startswith("note: non-physical")]
    assert len(lines) == 2 and lines[0].startswith("note: non-physical roll RAO at 15 kn, 150 deg, 1.047 rad/s: 7.38")


def test_a_speed_the_rao_table_does_not_have_is_refused(tmp_path):
    """rao_speeds_kn names speeds of the table: 7 kn, which the S175's VERES table does not have, is one line naming
    the key and the speeds it has."""
    text = (ROOT / "configs" / "training" / "heavy_weather_transit.toml").read_text().replace('"../../', f'"{ROOT}/')
    path = write(tmp_path, text.replace("rao_speeds_kn = [0.0, 5.0, 10.0]", "rao_speeds_kn = [0.0, 7.0]"))
    with pytest.raises(ScenarioError, match=r"vessel.rao_speeds_kn: .*7 kn is not one of the table's speeds "
                                            r"\(0, 5, 10, 15, 20 kn\)"):
        load_scenario(path)
