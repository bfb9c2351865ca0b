"""A WAMIT body placed off the global origin by its run's .pot (XBODY, YBODY, ZBODY, PHIBODY;
marinesim/hull/wamit_pot.py): WAMIT refers phases to the wave at its global origin and headings to its global X
axis, and its .gdf is in body coordinates. The tanker's RAOs, written as WAMIT would write them for the tanker
placed 50 m ahead, 20 m to port and turned 30 deg, read back with that .pot as the tanker's own RAOs; its hull,
written with the waterline 2 m above the body origin and placed 2 m down, has the tanker's hydrostatics."""

from __future__ import annotations

import math
import re

import numpy as np
import pytest

from conftest import ROOT
from marinesim.hull import hydrostatics, load_hull
from marinesim.sea.dispersion import k_from_omega
from marinesim.vessel.rao import make_table
from marinesim.vessel.read import read_rao
from marinesim.vessel.write import write_wamit

TANKER = ROOT / "rao" / "tanker"


def test_raos_of_a_placed_body_are_referred_to_the_body(tmp_path):
    """A failure means the phase shift has the wrong sign or size (the wave reaches a body 50 m ahead in head
    seas k 50 m earlier, not later) or the headings are turned the wrong way."""
    body = read_rao(TANKER / "tanker.4")
    x, y, phi = 50.0, 20.0, 30.0
    beta_global = np.mod(body.beta + math.radians(phi), 2 * math.pi)
    k = k_from_omega(body.omega, math.inf, body.g)
    lag = np.exp(-1j * k[None, :] * (x * np.cos(beta_global) + y * np.sin(beta_global))[:, None])
    order = np.argsort(beta_global)
    as_wamit = make_table(body.omega, beta_global[order], [0.0], (body.values[0] * lag[..., None])[order][None],
                          reference_point=(0.0, 0.0, 0.0), rho=body.rho, g=body.g, source="placed",
                          source_format="wamit")
    write_wamit(as_wamit, tmp_path / "placed.4")
    (tmp_path / "placed.cfg").write_text("IALTPOT=1\n")
    (tmp_path / "placed.pot").write_text(f"placed tanker\n1\n3\n-1 {x} {y} 0 {phi}\n0 1 0\n")
    read = read_rao(tmp_path / "placed.4")
    assert any("body origin at (50, 20, 0) m" in note for note in read.notes)
    at = np.isclose(np.mod(read.beta[:, None] - body.beta[None, :] + 1e-9, 2 * math.pi), 1e-9).argmax(axis=1)
    peak = np.abs(body.values).max()
    np.testing.assert_allclose(read.values[0], body.values[0][at], rtol=2e-6, atol=1e-6 * peak)


def test_a_gdf_placed_below_the_free_surface_by_zbody_floats_as_its_hull(tmp_path):
    """The tanker's panels written 2 m higher in body coordinates (its waterline at body z = +2) with a .pot
    putting the body origin 2 m below the free surface: the hull read has the tanker's volume and centre of
    buoyancy. Read without the .pot, the free surface would cut it 2 m below its waterline (a fifth of it lost)."""
    lines = (TANKER / "tanker.gdf").read_text().splitlines()
    raised = lines[:4] + [" ".join([*line.split()[:2], f"{float(line.split()[2]) + 2.0:.5f}"]) for line in lines[4:]]
    (tmp_path / "raised.gdf").write_text("\n".join(raised) + "\n")
    (tmp_path / "raised.pot").write_text("raised tanker\n1\n3\n-1 0 0 -2.0 0\n0 1 0\n")
    (tmp_path / "raised.cfg").write_text("IALTPOT=1\n")
    original, placed = hydrostatics(load_hull(TANKER / "tanker.gdf")), hydrostatics(load_hull(tmp_path / "raised.gdf"))
    assert placed.volume_m3 == pytest.approx(original.volume_m3, rel=1e-6)
    np.testing.assert_allclose(placed.centre_of_buoyancy_m, original.centre_of_buoyancy_m, atol=1e-4)
    assert any("ZBODY -2 m" in note for note in load_hull(tmp_path / "raised.gdf").notes)
    (tmp_path / "raised.pot").unlink()
    assert hydrostatics(load_hull(tmp_path / "raised.gdf")).volume_m3 < 0.85 * original.volume_m3


@pytest.mark.parametrize("old_form,text,words", [
    (True, "placed\n1\n3\n-1 50 x 0 30\n0 1 0\n", "HBOT XBODY(1..4) not found"),
    (False, "placed\n200.0\n1 1\n-3\n1.0 2.0\n", "expected NBETA"),
    (False, "placed\n200.0\n1 1\n999999 (NPER)\n", "NPER 999999: at most 100000"),
])
def test_a_flawed_pot_is_refused_naming_the_file(tmp_path, old_form, text, words):
    """A .pot whose XBODY line has text in it (old form), whose heading count is missing, or which lists more
    periods than any run: refused in one line naming the file, not read as an origin at (0, 0, 0)."""
    from marinesim.errors import FileFormatError

    (tmp_path / "t.4").write_bytes((TANKER / "tanker.4").read_bytes())
    (tmp_path / "t.pot").write_text(text)
    if old_form:
        (tmp_path / "t.cfg").write_text("IALTPOT=1\n")
    with pytest.raises(FileFormatError, match=re.escape(words)) as error:
        read_rao(tmp_path / "t.4")
    assert "t.pot" in str(error.value)
