"""A table of one speed used far from it is noted, not refused.

The S175's VERES file holds five speeds (0, 5, 10, 15, 20 kn). Cut to its zero-speed block it is a table of one
speed, which serves every speed with the encounter frequency shifted but its values unchanged: at 15 kn its
head-sea pitch near the peak is tens of percent off the full table's 15 kn values. Where the Froude number
U / sqrt(g L) of the speed asked is more than 0.1 from the table's, the scenario's notes, ``marinesim export``,
``run`` and ``rao --speed-kn`` say so, naming the table's speed, the speed asked and Fn; L is the hull's, else
the RAO file's (VERES: Lpp 175 m), else the manoeuvring model's; with none, speeds more than 5 kn apart are noted.
"""

import math
import re

import numpy as np
import pytest

from conftest import ROOT, VESSEL_SCENARIO, cli, write
from marinesim.constants import G, KNOT
from marinesim.hull import hydrostatics, load_hull
from marinesim.scenario import load_scenario
from marinesim.vessel import read_rao
from marinesim.vessel.native import write_native
from marinesim.vessel.veres import TITLE_LINES

S175 = ROOT / "rao" / "s175" / "input.re1"
S175_HULL = ROOT / "hulls" / "s175_hull.stl"
S175_LPP_M = 175.0
NOTE = "the RAO table has one speed (0 kn)"


def zero_speed_copy(folder):
    """The S175 file cut to its first (0 kn) speed block: the header with NVEL 1, then that block (its speed line,
    and per heading the HEAD line and per frequency the FREQ line and six DOF lines); its path."""
    lines = S175.read_text().splitlines(keepends=True)
    counts = TITLE_LINES + 3                                # RHO G; LPP B T; LCG VCG; then the counts' line
    nvel, nhead, nfreq, ndof = (int(word) for word in lines[counts].split())
    block = 1 + nhead * (1 + nfreq * (1 + ndof))
    assert len(lines) == counts + 1 + nvel * block
    path = folder / "s175_0kn.re1"
    path.write_text("".join(lines[:counts]) + f"     1 {nhead:5d} {nfreq:5d} {ndof:5d}\n"
                    + "".join(lines[counts + 1:counts + 1 + block]))
    return path


@pytest.fixture(scope="module")
def cut(tmp_path_factory):
    return zero_speed_copy(tmp_path_factory.mktemp("one_speed"))


def scenario_text(rao, speed_kn: float, extra: str = "") -> str:
    """The conftest vessel scenario with the S175 table ``rao`` at ``speed_kn`` in head seas (waves from the north,
    bow north), no hull, 20 s; ``extra`` lines go into ``[vessel]``."""
    lines = [line for line in VESSEL_SCENARIO.splitlines()
             if not line.startswith(("rao =", "hull =", "speed_kn", "heading_deg", "from_deg"))]
    text = "\n".join(lines).replace("[vessel]", f'[vessel]\nrao = "{rao}"\nspeed_kn = {speed_kn}\n'
                                                f'heading_deg = 0.0\n{extra}')
    return text.replace('type = "jonswap"', 'type = "jonswap"\nfrom_deg = 0.0').replace("duration_s = 120.0",
                                                                                         "duration_s = 20.0")


def froude(speed_kn: float, length_m: float) -> float:
    return speed_kn * KNOT / math.sqrt(G * length_m)


def test_the_cut_file_is_the_zero_speed_table(cut):
    full, one = read_rao(S175), read_rao(cut)
    assert one.speed.tolist() == [0.0] and one.length == S175_LPP_M == full.length
    np.testing.assert_array_equal(one.values[0], full.values[0])


def test_one_speed_misses_the_head_sea_pitch_at_15_kn(cut):
    """The physics behind the note: a table of one speed gives its own values at any speed, and at 15 kn the full
    table's head-sea pitch differs from them by tens of percent over the half-power band of its peak."""
    full, one = read_rao(S175), read_rao(cut)
    omega = full.omega
    head = np.full(omega.size, math.pi)
    speed = 15.0 * KNOT
    assert full.speed[3] == pytest.approx(speed, rel=1e-6)
    used = np.abs(one(omega, head, speed)[:, 4])
    np.testing.assert_allclose(used, np.abs(full(omega, head, 0.0)[:, 4]), rtol=1e-12)  # the 0 kn values
    at_speed = np.abs(full(omega, head, speed)[:, 4])
    band = at_speed >= at_speed.max() / math.sqrt(2.0)
    error = np.abs(used / at_speed - 1.0)
    peak = np.argmax(at_speed)
    print(f"head-sea pitch, the 0 kn table at 15 kn over the 15 kn peak's half-power band {omega[band][0]:.3f}.."
          f"{omega[band][-1]:.3f} rad/s: {100 * error[band].min():.0f}..{100 * error[band].max():.0f} % off, "
          f"{100 * error[peak]:.0f} % at the peak ({omega[peak]:.3f} rad/s); peaks {used.max():.4f} and "
          f"{at_speed.max():.4f} rad/m")
    assert error[peak] > 0.2 and error[band].max() > 0.4 and error[band].min() > 0.05
    assert used.max() / at_speed.max() - 1.0 > 0.2


@pytest.mark.parametrize("table, speed_kn, noted", [("cut", 15.0, True), ("cut", 3.0, False), ("full", 15.0, False)])
def test_export_notes_a_one_speed_table_far_from_its_speed(cut, tmp_path, table, speed_kn, noted):
    rao = cut if table == "cut" else S175
    scenario = write(tmp_path, scenario_text(rao, speed_kn))
    result = cli("export", str(scenario), "--out", str(tmp_path / "motions.csv"), "--quiet")
    assert result.returncode == 0, result.stderr
    lines = [line for line in result.stdout.splitlines() if NOTE in line]
    assert len(lines) == int(noted), result.stdout
    if noted:
        line, = lines
        assert line.startswith("note: vessel.speed_kn: the RAO table has one speed (0 kn) and is used at 15 kn")
        assert "L 175 m, the RAO file's" in line and "encounter frequency shift is applied" in line
        fn = float(re.search(r"Fn (\d\.\d+)", line).group(1))
        assert fn == pytest.approx(froude(15.0, S175_LPP_M), abs=5e-4) and fn == pytest.approx(0.186, abs=1e-3)
    elif table == "cut":
        assert froude(speed_kn, S175_LPP_M) == pytest.approx(0.037, abs=1e-3)  # under 0.1: nothing to note


def test_rao_speed_kn_notes_a_one_speed_table(cut):
    noted = cli("rao", str(cut), "--speed-kn", "15")
    assert noted.returncode == 0, noted.stderr
    assert (f"note: --speed-kn: {NOTE} and is used at 15 kn (Fn {froude(15.0, S175_LPP_M):.3f}; L 175 m, "
            "the RAO file's)") in noted.stdout
    for args in ((str(cut), "--speed-kn", "3"), (str(S175), "--speed-kn", "15")):
        quiet = cli("rao", *args)
        assert quiet.returncode == 0 and NOTE not in quiet.stdout, quiet.stdout


def test_the_length_comes_from_the_hull_then_the_file_then_the_manoeuvring_model(cut, tmp_path):
    hull = hydrostatics(load_hull(S175_HULL)).froude_length_m
    from_hull = load_scenario(write(tmp_path, scenario_text(cut, 15.0, f'hull = "{S175_HULL}"'), "hull.toml"))
    note, = from_hull.notes
    assert f"Fn {froude(15.0, hull):.3f}; L {hull:.4g} m, the hull's" in note
    native = tmp_path / "s175_0kn.csv"
    write_native(read_rao(cut), native)
    assert read_rao(native).length is None                  # the native table states no length
    model = load_scenario(write(tmp_path, scenario_text(native, 15.0, 'manoeuvring = "s175"'), "model.toml"))
    length = model.vessel.ship.length_m
    note, = model.notes
    assert f"Fn {froude(15.0, length):.3f}; L {length:.4g} m, the manoeuvring model's" in note


def test_no_length_known_notes_above_5_kn(cut, tmp_path):
    native = tmp_path / "s175_0kn.csv"
    write_native(read_rao(cut), native)
    fast = load_scenario(write(tmp_path, scenario_text(native, 6.0), "fast.toml"))
    note, = fast.notes
    assert note.startswith(f"vessel.speed_kn: {NOTE} and is used at 6 kn (length unknown, so no Froude number")
    assert load_scenario(write(tmp_path, scenario_text(native, 4.0), "slow.toml")).notes == ()


def test_an_event_speed_order_is_noted(cut, tmp_path):
    text = scenario_text(cut, 3.0, 'manoeuvring = "s175"') + "\n[[events]]\nat_s = 5.0\nspeed_kn = 15.0\n"
    scenario = load_scenario(write(tmp_path, text))
    note, = scenario.notes
    assert note.startswith(f"events[0].speed_kn: {NOTE} and is used at 15 kn (Fn {froude(15.0, 175.0):.3f}")
