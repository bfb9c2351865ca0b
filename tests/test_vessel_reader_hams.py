"""HAMS and HydroStar ``.rao`` readers on HAMS's own certification case (tests/data/hams, Apache-2.0).

The cylinder (radius 1 m, draught 0.5 m, 10 m water depth, 30 frequencies 0.99-5.42 rad/s, 36 headings) is
checked against physics (the free-floating long-wave limits of CONVENTIONS.md in the file's depth, port/starboard
symmetry) and against HAMS's second output of the same run, its WAMIT-format ``Buoy.4``, read by the other reader.
"""

from __future__ import annotations

import lzma
import math
import shutil
from pathlib import Path

import numpy as np
import pytest

from conftest import ROOT
from marinesim.errors import FileFormatError
from marinesim.sea.dispersion import k_from_omega
from marinesim.vessel import native
from marinesim.vessel.hydrostar import is_hams_output, read_hams_wamit, read_hydrostar, sniff
from marinesim.vessel.rao import MIRROR_SIGN

DATA = ROOT / "tests" / "data" / "hams"
CYLINDER = DATA / "cylinder"
MOTION = CYLINDER / "Output" / "Hydrostar_format" / "Motion_3.rao"


@pytest.fixture(scope="module")
def table():
    return read_hydrostar(MOTION)


@pytest.fixture
def hams_run(tmp_path: Path) -> Path:
    """HAMS's output tree of the cylinder run with Buoy.4 unpacked: tmp/Input/ControlFile.in, tmp/Output/..."""
    shutil.copytree(CYLINDER / "Input", tmp_path / "Input")
    wamit = tmp_path / "Output" / "Wamit_format"
    wamit.mkdir(parents=True)
    (wamit / "Buoy.4").write_bytes(lzma.decompress((CYLINDER / "Output" / "Wamit_format" / "Buoy.4.xz").read_bytes()))
    return wamit / "Buoy.4"


def _file_headings(t) -> np.ndarray:
    return np.round(np.degrees(t.beta)).astype(int)


def test_long_wave_limits_in_the_files_depth(table):
    """At the lowest frequency (kR = 0.12) the small cylinder rides the wave: heave 1 at phase 0, pitch i k cos b,
    roll -i k sin b, surge -i cos b / tanh(kh) (k in 10 m depth). A phase sign error (lag read as lead, or waves
    'coming from' read as 'going to') turns the +-90 deg phases round; rotations left in the file's 'deg/m' label
    would give pitch / k = 0.018 instead of 1."""
    assert table.depth == 10.0 and not table.mirrored
    w = table.omega[0]
    k = float(k_from_omega(w, table.depth, table.g))
    h = table.values[0, :, 0]  # headings x 6
    b = table.beta
    np.testing.assert_allclose(np.abs(h[:, 2]), 1.0, atol=0.01)
    np.testing.assert_allclose(np.angle(h[:, 2], deg=True), 0.0, atol=1.0)
    for j, expected, weight in ((4, 1j * k * np.cos(b), np.abs(np.cos(b))), (3, -1j * k * np.sin(b), np.abs(np.sin(b))),
                                (0, -1j * np.cos(b) / math.tanh(k * table.depth), np.abs(np.cos(b)))):
        strong = weight > 0.5
        ratio = h[strong, j] / expected[strong]
        np.testing.assert_allclose(np.abs(ratio), 1.0, atol=0.1, err_msg=f"DOF {j} amplitude")
        np.testing.assert_allclose(np.angle(ratio, deg=True), 0.0, atol=5.0, err_msg=f"DOF {j} phase")
    assert any("deg/m" in note and "rad/m" in note for note in table.notes), "the unit override must be reported"


def test_port_and_starboard_headings_mirror(table):
    """Waves towards port (b) and towards starboard (360 - b) give the same surge, heave and pitch and opposite
    sway and roll, within the mesh's own asymmetry (3 % of each DOF's peak below the heave resonance)."""
    headings = _file_headings(table)
    assert set(headings) == set(range(0, 360, 10))
    mirror = [int(np.flatnonzero(headings == (360 - h) % 360)[0]) for h in headings]
    low = table.omega < 2.5
    values = table.values[0][:, low]
    mirrored = values[mirror] * MIRROR_SIGN
    for j in range(5):  # yaw of an axisymmetric body is numerical noise (1e-6 rad/m)
        peak = np.abs(table.values[0, :, :, j]).max()
        assert np.abs(values[..., j] - mirrored[..., j]).max() < 0.03 * peak, f"DOF {j}"


def test_hams_wamit_format_equals_the_hydrostar_files(table, hams_run):
    """HAMS's Buoy.4 holds the same run normalised by rho g and multiplied by i (SolveMotion.f90): undone, it equals
    the HydroStar files to their printed precision (7 digits; phases to 1e-4 deg). Left as WAMIT's convention it
    would be 1e-4 of them and 90 deg out of phase."""
    other = read_hams_wamit(hams_run)
    np.testing.assert_allclose(other.omega, table.omega, rtol=1e-4)  # HydroStar prints w to 4 decimals
    np.testing.assert_array_equal(_file_headings(other), _file_headings(table))
    assert other.depth == table.depth == 10.0
    for j in range(6):
        peak = np.abs(table.values[..., j]).max()
        np.testing.assert_allclose(other.values[..., j], table.values[..., j], rtol=0, atol=1e-5 * peak,
                                   err_msg=f"DOF {j}")
    assert any("rho g" in note for note in other.notes)
    assert is_hams_output(hams_run), "WAMIT's own reader needs this check to refuse the file"
    assert not is_hams_output(ROOT / "rao" / "tanker" / "tanker.4"), "a real WAMIT .4 is not HAMS's"


def test_hams_wamit_format_needs_the_control_file(hams_run, table):
    """The PER column's meaning is in Input/ControlFile.in; without it the reader refuses (no silent guess) unless
    told, and told the same it gives the same table."""
    alone = hams_run.parent.parent.parent / "alone.4"
    shutil.copy(hams_run, alone)
    with pytest.raises(FileFormatError, match="ControlFile.in"):
        read_hams_wamit(alone)
    told = read_hams_wamit(alone, frequency_type=4, depth=10.0)
    np.testing.assert_allclose(told.values, read_hams_wamit(hams_run).values)


def test_a_truncated_real_file_is_refused_with_its_line():
    """HAMS's DeepCwind run left its HydroStar files cut after the column line (22 lines, no rows, no #ENDFILE)."""
    with pytest.raises(FileFormatError, match=r"Motion_3.rao, line 22: .*ENDFILE"):
        read_hydrostar(DATA / "deepcwind_truncated" / "Motion_3.rao")


@pytest.mark.parametrize("edit, message", [
    (lambda lines: lines[:24] + [lines[24].rsplit(None, 1)[0]] + lines[25:], r"line 25: expected 73 numbers"),
    (lambda lines: [line.replace("#NBHEADING    36", "#NBHEADING    35") for line in lines], r"line 21: #HEADING lists 36"),
    (lambda lines: lines[:26] + [lines[26].replace("1.031930E+00", "NaN", 1)] + lines[27:], r"non-finite"),
    (lambda lines: lines[:26] + [lines[26].replace("1.7152", "1.3000", 1)] + lines[27:], r"line 27: w 1.3"),
    (lambda lines: [line.replace("#UNIT       :  m/m", "#UNIT       :  ft/ft") for line in lines], r"ft/ft"),
])
def test_malformed_copies_name_the_line(tmp_path, edit, message):
    """Corrupted copies of the real set fail with a FileFormatError naming the file and what is wrong."""
    for source in MOTION.parent.glob("Motion_*.rao"):
        shutil.copy(source, tmp_path / source.name)
    target = tmp_path / "Motion_3.rao"
    target.write_text("\n".join(edit(target.read_text().splitlines())) + "\n")
    with pytest.raises(FileFormatError, match=message):
        read_hydrostar(target)


def test_missing_dof_files_are_named(tmp_path):
    """One DOF per file: a folder without the pitch file is refused, naming pitch."""
    for source in MOTION.parent.glob("Motion_*.rao"):
        if source.name != "Motion_5.rao":
            shutil.copy(source, tmp_path / source.name)
    with pytest.raises(FileFormatError, match="pitch"):
        read_hydrostar(tmp_path / "Motion_1.rao")


def test_sniffers_tell_hydrostar_from_native_rao():
    """Both HydroStar and marinesim's own tables use .rao: HydroStar's '#RAOTYPE'/'#HEADING' header tells them apart."""
    head = MOTION.read_bytes()[:4096]
    assert sniff(head) and not native.sniff(head)
    own = b"phase = lead\nspeed_kn,heading_deg,period_s,surge_amp_m_m,surge_phase_deg\n0,180,10,1,90\n"
    assert native.sniff(own) and not sniff(own)


def test_the_registry_reads_each_file_as_the_program_that_wrote_it(table, hams_run, tmp_path):
    """Through ``read_rao`` (what a scenario's ``rao =`` uses): a HydroStar .rao is HydroStar's, a marinesim .rao
    is still marinesim's (the two share the extension, their content decides), and HAMS's .4 is read as HAMS
    wrote it, not as WAMIT's (where it would come out 1e-4 of the true motions)."""
    from marinesim.vessel import read_rao
    from marinesim.vessel.native import write_native

    by_registry = read_rao(MOTION)
    assert by_registry.source_format == table.source_format
    np.testing.assert_array_equal(by_registry.values, table.values)
    write_native(table, tmp_path / "own.rao")
    own = read_rao(tmp_path / "own.rao")
    assert own.source_format == "native"
    np.testing.assert_allclose(own.values, table.values, rtol=1e-8, atol=1e-12)
    hams = read_rao(hams_run)
    assert hams.source_format == "hams-wamit" and any("rho g" in note for note in hams.notes)
    np.testing.assert_allclose(hams.values, read_hams_wamit(hams_run).values)
