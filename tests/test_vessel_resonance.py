"""A lightly damped resonance beyond the plausibility limits (marinesim/vessel/rao.py, read.py): the tanker's WAMIT
set moored in surge by the external stiffness of its .frc (K11 = 3.9e5 N/m, a natural period near 100 s). What
was found is said (the peak, its period, its damping from the half-power bandwidth), and the user accepts it with
``marinesim rao --accept-resonance`` or ``[vessel] accept_resonance = true``."""

from __future__ import annotations

import math
import shutil
from pathlib import Path

import numpy as np
import pytest

from conftest import ROOT, VESSEL_SCENARIO, cli, write
from marinesim.errors import FileFormatError
from marinesim.vessel.read import read_rao
from marinesim.vessel.wamit_forces import read_force_set

TANKER = ROOT / "rao" / "tanker"
MOORING = 3.9e5
"""Surge stiffness of the mooring (N/m)."""


def moored(folder: Path, surge_damping: str) -> Path:
    """The tanker's set with the .frc's first external stiffness row ``MOORING`` and its external surge damping
    replaced by ``surge_damping`` (N s/m, as the file writes it); the path of the .3."""
    for suffix in (".1", ".3", ".hst", ".frc", ".cfg", ".gdf"):
        shutil.copyfile(TANKER / f"tanker{suffix}", folder / f"tanker{suffix}")
    frc = folder / "tanker.frc"
    lines = frc.read_text().splitlines()
    assert lines[12].startswith("410000.00") and lines[18] == "1"
    lines[12] = lines[12].replace("410000.00", surge_damping, 1)
    lines[19] = f"{MOORING:.2f} 0.00 0.00 0.00 0.00 0.00"
    frc.write_text("\n".join(lines) + "\n")
    return folder / "tanker.3"


def natural_period_and_damping(path: Path) -> tuple[float, float]:
    """The moored surge's natural period (s) and damping ratio, from the set's own mass, added mass and damping
    (single DOF: T = 2 pi sqrt((m + A11) / K), zeta = B11 / (2 sqrt(K (m + A11)))), at the period nearest T."""
    fs = read_force_set(path)
    m = fs.mass[0, 0]
    k = int(np.argmin(np.abs(2 * math.pi / fs.omega - 2 * math.pi * math.sqrt((m + fs.added[0, 0, 0]) / MOORING))))
    inertia = m + fs.added[k, 0, 0]
    damping = fs.damping[k, 0, 0] + fs.frc.damping[0, 0]
    return 2 * math.pi * math.sqrt(inertia / MOORING), damping / (2 * math.sqrt(MOORING * inertia))


def test_a_moored_surge_resonance_is_described_and_noted(tmp_path):
    """With the .frc's surge damping (4.1e5 N s/m, about 3 % of critical) the surge peak is 15 times the wave
    orbit: the note gives the peak, its period within a step of the table of the single-DOF natural period, and a
    damping estimate no smaller than the damping the set holds (the table's coarse steps widen the peak), not
    "check the units" alone."""
    path = moored(tmp_path, "410000.00")
    period, zeta = natural_period_and_damping(path)
    table = read_rao(path)
    note = next(n for n in table.notes if n.startswith("implausible unless real: surge RAO"))
    found_period = float(note.split("at T ")[1].split()[0])
    found_zeta = float(note.split("with about ")[1].split()[0]) / 100
    assert found_period == pytest.approx(period, rel=0.1)
    assert zeta <= found_zeta < 3 * zeta
    assert "--accept-resonance" in note
    accepted = read_rao(path, accept_resonance=True)
    assert any(n.startswith("resonance accepted: surge RAO") for n in accepted.notes)
    assert not any(n.startswith("implausible") for n in accepted.notes)


def test_an_undamped_resonance_is_refused_unless_accepted(tmp_path):
    """Without the surge damping the peak passes 50 m/m, beyond any floating body's but for a resonance: refused
    in one line naming the file and the resonance (exit 2, the files untouched), read with --accept-resonance."""
    path = moored(tmp_path, "0.00")
    with pytest.raises(FileFormatError, match="a resonance peak of .* at T .* of critical damping") as error:
        read_rao(path)
    assert error.value.path == path
    before = {p.name: p.read_bytes() for p in tmp_path.iterdir()}
    result = cli("rao", str(path), cwd=tmp_path)
    lines = result.stderr.strip().splitlines()
    assert result.returncode == 2 and len(lines) == 1 and "Traceback" not in result.stderr, result.stderr
    assert str(path) in lines[0] and "surge" in lines[0] and "--accept-resonance" in lines[0]
    assert {p.name: p.read_bytes() for p in tmp_path.iterdir()} == before
    accepted = cli("rao", str(path), "--accept-resonance", cwd=tmp_path)
    assert accepted.returncode == 0 and "resonance accepted: RAO surge amplitude" in accepted.stdout, accepted.stderr


def test_the_scenario_accepts_it_with_accept_resonance(tmp_path):
    """The same set as a scenario's RAO: refused (exit 2, one line naming vessel.rao), and run with
    [vessel] accept_resonance = true."""
    path = moored(tmp_path, "0.00")
    base = VESSEL_SCENARIO.replace(f'hull = "{ROOT / "hulls" / "tanker.gdf"}"\n', "").replace(
        "speed_kn = 6.0", "speed_kn = 0.0").replace("duration_s = 120.0", "duration_s = 10.0").replace(
        str(TANKER / "tanker.4"), str(path))
    refused = cli("export", str(write(tmp_path, base, "plain.toml")), "--out", "a.csv", "--quiet", cwd=tmp_path)
    lines = refused.stderr.strip().splitlines()
    assert refused.returncode == 2 and len(lines) == 1 and "resonance" in lines[0], refused.stderr
    accepted = write(tmp_path, base.replace("[vessel]\n", "[vessel]\naccept_resonance = true\n"), "accepted.toml")
    result = cli("export", str(accepted), "--out", "b.csv", "--quiet", cwd=tmp_path)
    assert result.returncode == 0, result.stderr
