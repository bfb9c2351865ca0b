"""RAO writers (marinesim/vessel/write.py, ``marinesim rao --write``): a table read from one program, written as
WAMIT's ``.4`` or as marinesim's native table and read back, is the same table to the precision written; the
``.4`` is WAMIT's own layout and convention, so WAMIT's tanker comes back line for line."""

import json

import numpy as np
import pytest

from conftest import ROOT
from marinesim.cli import main
from marinesim.constants import KNOT
from marinesim.errors import ParameterError
from marinesim.vessel import read_rao
from marinesim.vessel.write import write_rao

TANKER = ROOT / "rao" / "tanker" / "tanker.4"
S175 = ROOT / "rao" / "s175" / "input.re1"
NATIVE = """\
# a hand-written table in other units and the lag convention: the reader converts, the writer must not undo it wrongly
vessel = test barge
reference_point_m = 1.5, 0, -2
rho_kg_m3 = 1000
phase = lag
heading_deg,period_s,surge_amp_m_m,surge_phase_deg,sway_amp_m_m,sway_phase_deg,heave_amp_m_m,heave_phase_deg,\
roll_amp_deg_m,roll_phase_deg,pitch_amp_deg_m,pitch_phase_deg,yaw_amp_deg_m,yaw_phase_deg
0,20,0.9,90,0,0,1.0,0,0,0,0.5,-90,0,0
0,8,0.5,60,0,0,0.5,-30,0,0,3.0,-120,0,0
90,20,0,0,0.9,90,1.0,0,0.6,90,0,0,0.1,0
90,8,0,0,0.4,45,0.8,-10,5.729577951,120,0,0,0.3,10
180,20,0.9,-90,0,0,1.0,0,0,0,0.5,90,0,0
180,8,0.5,-120,0,0,0.5,-30,0,0,3.0,60,0,0
"""


def _relative(a: np.ndarray, b: np.ndarray) -> float:
    """Largest error of ``b`` against ``a`` per real and imaginary part, relative to that part (what a decimal
    with a fixed number of significant digits keeps)."""
    parts = [(a.real, b.real), (a.imag, b.imag)]
    return max(float(np.max(np.abs(x - y) / np.maximum(np.abs(x), 1e-300))) for x, y in parts)


def test_tanker_round_trip_is_bit_exact_and_line_for_line(tmp_path):
    """WAMIT's tanker, read and written as .4, reads back bit for bit, and the file is WAMIT's own: PER, BETA, I, RE
    and IM identical as text on every line (same layout, order and convention; a sign flip would be a lag
    convention, a changed order another loop nesting), MOD within one unit of its last printed digit and PHA
    within 2e-4 deg (recomputed from the printed RE and IM, where WAMIT used its unprinted digits)."""
    table = read_rao(TANKER)
    out = tmp_path / "tanker.4"
    assert write_rao(table, out) == ()
    again = read_rao(out)
    assert np.array_equal(again.omega, table.omega) and np.array_equal(again.beta, table.beta)
    assert np.array_equal(again.values, table.values) and again.mirrored
    original = [line.split() for line in TANKER.read_text().splitlines()]
    written = [line.split() for line in out.read_text().splitlines()]
    assert len(written) == len(original) == 6612
    assert all([o[k] for k in (0, 1, 2, 5, 6)] == [w[k] for k in (0, 1, 2, 5, 6)] for o, w in zip(original, written))
    modulus = np.array([[float(o[3]), float(w[3])] for o, w in zip(original, written)])
    phase = np.array([[float(o[4]), float(w[4])] for o, w in zip(original, written)])
    unit = 1e-6 * 10 ** np.floor(np.log10(np.maximum(modulus[:, 0], 1e-300)))  # of the 7th significant digit
    assert np.all(np.abs(modulus[:, 0] - modulus[:, 1]) <= 1.01 * unit)
    real = modulus[:, 0] > 1e-9  # below: numerical zeros (roll in head seas), printed by WAMIT with a nominal +-90
    assert real.sum() > 6000 and np.abs(phase[real, 0] - phase[real, 1]).max() < 2e-4  # deg: printed to 1e-4
    assert out.read_text().splitlines()[0] == TANKER.read_text().splitlines()[0].replace("1.368770E+00", "1.368771E+00")


def test_s175_several_speeds_choose_one_for_the_4_and_keep_all_in_the_csv(tmp_path):
    """VERES's S175 (5 speeds): a .4 has no speed column, so it is refused without a chosen speed and with one the
    table does not have; each chosen speed reads back within the 7 significant digits written (periods within 6),
    and re-writing what was read is bit-exact (nothing drifts). The native .csv keeps all five speeds to 10 digits."""
    table = read_rao(S175)
    assert table.speed.size == 5 and table.mirrored
    with pytest.raises(ParameterError, match="has no speed column and this table has speeds 0, 5, 10, 15, 20 kn"):
        write_rao(table, tmp_path / "s175.4")
    with pytest.raises(ParameterError, match="speed 3 kn is not one of the table's speeds"):
        write_rao(table, tmp_path / "s175.4", speed=3 * KNOT)
    assert not (tmp_path / "s175.4").exists()
    for i, knots in enumerate((0, 5, 10, 15, 20)):
        notes = write_rao(table, tmp_path / "s175.4", speed=knots * KNOT)
        assert f"wrote speed {knots:g} kn only" in notes[0] and "reference point (2.54748, 0, 9.55)" in notes[1]
        back = read_rao(tmp_path / "s175.4")
        assert np.array_equal(back.beta, table.beta) and back.speed.tolist() == [0.0]
        assert np.abs(back.omega / table.omega - 1).max() < 5e-6  # PER to 6 significant digits
        assert _relative(table.values[i], back.values[0]) <= 5.0001e-7  # RE, IM to 7 significant digits
    write_rao(back, tmp_path / "again.4")
    assert np.array_equal(read_rao(tmp_path / "again.4").values, back.values)
    assert write_rao(table, tmp_path / "s175.csv") == ()
    native = read_rao(tmp_path / "s175.csv")
    assert np.array_equal(native.speed, table.speed) and np.array_equal(native.omega, table.omega)
    assert np.all(np.abs(native.values - table.values) <= 2e-9 * np.abs(table.values))  # amplitude, phase: 10 digits


def test_native_table_round_trips_and_its_4_is_the_lead_convention(tmp_path):
    """A hand-written native table (lag phases, rotations in deg/m, periods, an off-origin reference point, fresh
    water) -> .csv -> read: the same RAOs to 10 digits, the reference point and rho kept. -> .4: the lines hold the
    internal RAO itself (a heave given as 0.5 lagging 30 deg is RE 0.4330127, IM 0.25, PHA +30: lead; a roll of
    5.73 deg/m is 0.1 rad/m: ULEN 1), and the .4's notes say the reference point and rho are not in it."""
    source = tmp_path / "barge.csv"
    source.write_text(NATIVE)
    table = read_rao(source)
    assert write_rao(table, tmp_path / "out.csv") == ()
    back = read_rao(tmp_path / "out.csv")
    assert back.reference_point == (1.5, 0.0, -2.0) and back.rho == 1000.0
    assert np.abs(back.omega / table.omega - 1).max() < 5e-10 and np.abs(back.beta - table.beta).max() < 1e-12
    assert np.all(np.abs(back.values - table.values) <= 2e-9 * np.abs(table.values))  # amplitude, phase: 10 digits
    notes = write_rao(table, tmp_path / "out.4")
    assert any("reference point (1.5, 0, -2)" in n for n in notes) and any("rho 1000" in n for n in notes)
    rows = {(float(r[0]), float(r[1]), int(r[2])): [float(v) for v in r[3:]]
            for r in (line.split() for line in (tmp_path / "out.4").read_text().splitlines())}
    assert rows[(8.0, 180.0, 3)] == pytest.approx([0.5, 30.0, 0.4330127, 0.25], abs=1e-7)
    assert rows[(8.0, 90.0, 4)] == pytest.approx([0.1, -120.0, -0.05, -0.08660254], abs=1e-7)
    assert list(rows)[:2] == [(8.0, 0.0, 1), (8.0, 0.0, 2)]  # period outer (increasing), heading, mode inner
    assert rows[(8.0, 0.0, 2)] == [0.0, 90.0, 0.0, 0.0]  # WAMIT's dummy phase of a zero value
    four = read_rao(tmp_path / "out.4")
    assert _relative(table.values[0], four.values[0]) <= 5.0001e-7
    assert np.abs(four.omega - table.omega).max() < 1e-12
    write_rao(back, tmp_path / "circle.4")  # the native table wrote the whole circle: so does the .4 (0..270 deg)
    circle = read_rao(tmp_path / "circle.4")
    assert not circle.mirrored and np.degrees(circle.beta).tolist() == [0.0, 90.0, 180.0, 270.0]
    assert _relative(back.values[0], circle.values[0]) <= 5.0001e-7


def test_unknown_extension_is_refused_naming_the_supported_ones(tmp_path):
    """A writer chosen by extension must say which extensions exist, and write nothing."""
    with pytest.raises(ParameterError, match=r"unknown extension '.3'; supported: .4 \(WAMIT .4 numeric output\), "
                                             r"\.csv \(marinesim native table\)"):
        write_rao(read_rao(TANKER), tmp_path / "tanker.3")
    assert not list(tmp_path.iterdir())


def test_cli_write(tmp_path, capsys):
    """``marinesim rao FILE --write``: the S175 .4 at a chosen speed and the tanker .csv are written and read back;
    a several-speed table without --speed-kn and an unknown extension are refused in one line, before any output."""
    assert main(["rao", str(S175), "--write", str(tmp_path / "s175.4"), "--speed-kn", "10"]) == 0
    out = capsys.readouterr().out
    assert f"wrote {tmp_path / 's175.4'}" in out and "note: wrote speed 10 kn only" in out
    assert read_rao(tmp_path / "s175.4").omega.size == 36
    assert main(["rao", str(TANKER), "--json", "--write", str(tmp_path / "tanker.csv")]) == 0
    assert json.loads(capsys.readouterr().out)["written"] == {"path": str(tmp_path / "tanker.csv"), "notes": []}
    assert np.abs(read_rao(tmp_path / "tanker.csv").values - read_rao(TANKER).values).max() < 1e-9
    for args, message in (((str(S175), "--write", str(tmp_path / "x.4")), "choose one (marinesim rao --speed-kn)"),
                          ((str(TANKER), "--write", str(tmp_path / "x.xlsx")), "unknown extension '.xlsx'; supported: .4")):
        assert main(["rao", *args]) == 2
        captured = capsys.readouterr()
        assert message in captured.err and "Traceback" not in captured.err and captured.out == ""
        assert len(captured.err.strip().splitlines()) == 1
    assert sorted(p.name for p in tmp_path.iterdir()) == ["s175.4", "tanker.csv"]
