"""`marinesim export` says how much of the motion came from outside the RAO table.

The vessel is a small wave follower: its RAO is the free-floating long-wave limit at every frequency
(heave 1, surge -i cos(beta), sway -i sin(beta): it rides the wave), tabulated over 0.99..5.4 rad/s
only, as user tables from short-period BEM runs are. Driven by a Tp 10 s sea (peak 0.63 rad/s), most
of its motion comes from below the table; for heave (|H| = 1 at every frequency and heading) that
share is the share of the sea's spectrum below 0.99 rad/s, the reference here. The components
sample the spectrum on three 256^2 tiles (10^4 components): the two agree to 0.5 % of the variance
(2 % on the conftest's 64^2 tiles).
"""

import json
import math

import numpy as np
import pytest

from conftest import VESSEL_SCENARIO, cli, write
from marinesim.scenario import load_scenario
from marinesim.session.assembly import Assembly
from marinesim.session.export import export_motions, outside_table_note
from marinesim.vessel import DOFS
from marinesim.vessel.native import write_native
from marinesim.vessel.rao import long_wave_limit, make_table

HEADINGS = np.radians(np.arange(0.0, 181.0, 30.0))
SAMPLING = 0.005
"""Share of variance within which the ocean's components reproduce the spectrum's integrals."""


def follower(tmp_path, low: float, high: float):
    """A wave follower's native RAO file over ``low..high`` rad/s (deep water); its path."""
    omega = np.linspace(low, high, 30)
    w, b = np.meshgrid(omega, HEADINGS)
    values = long_wave_limit(w.ravel(), b.ravel()).reshape(HEADINGS.size, omega.size, 6)[None]
    path = tmp_path / f"follower_{low:g}_{high:g}.csv"
    write_native(make_table(omega, HEADINGS, [0.0], values, source="follower"), path)
    return path


def scenario_text(rao_path) -> str:
    """The conftest vessel scenario (Hs 4 m, Tp 10 s, cos-2s 10) with the follower at rest, no hull, 60 s,
    on 256^2 tiles."""
    lines = [line for line in VESSEL_SCENARIO.splitlines() if not line.startswith(("rao =", "hull =", "speed_kn"))]
    text = "\n".join(lines).replace("[vessel]", f'[vessel]\nrao = "{rao_path}"\nspeed_kn = 0.0')
    return text.replace("duration_s = 120.0", "duration_s = 60.0").replace("resolution = 64", "resolution = 256")


def spectral_share(scenario, low: float, high: float, transfer=lambda w: np.ones_like(w)) -> tuple[float, float]:
    """Shares of ``integral S(w) |transfer(w)|^2 dw`` below ``low`` and above ``high`` (rad/s)."""
    omega = np.linspace(1e-3, 12.0, 240_001)
    density = sum(system.spectrum.density(omega) for system in scenario.sea.spectral_systems)
    power = density * np.abs(transfer(omega)) ** 2
    total = np.trapezoid(power, omega)
    return (np.trapezoid(np.where(omega < low, power, 0.0), omega) / total,
            np.trapezoid(np.where(omega > high, power, 0.0), omega) / total)


def test_sidecar_and_console_give_the_share_from_below_the_table(tmp_path):
    # the sea's spectrum has ~82 % of its variance below 0.99 rad/s: so has the follower's heave, which
    # the sidecar and the console must say; if this fails, the export extrapolates below the table in
    # silence or counts the wrong components as outside it
    path = write(tmp_path, scenario_text(follower(tmp_path, 0.99, 5.4)))
    result = cli("export", str(path), "--out", "m.csv", "--quiet", cwd=tmp_path)
    assert result.returncode == 0, result.stderr
    coverage = json.loads((tmp_path / "m.csv.json").read_text())["outside_rao_table"]
    assert coverage["omega_rad_s"] == pytest.approx([0.99, 5.4])
    (leg,) = coverage["legs"]
    scenario = load_scenario(path)
    below, _ = spectral_share(scenario, 0.99, 5.4)
    assert leg["below"]["heave"] == pytest.approx(below, abs=SAMPLING)
    components = Assembly(scenario).components()
    assert components.omega.max() < 5.4  # nothing above the table in this ocean
    assert all(leg["above"][dof] == 0.0 for dof in DOFS if leg["above"][dof] is not None)
    note = next(line for line in result.stdout.splitlines() if line.startswith("note:"))
    assert "0.99..5.4 rad/s" in note and f"heave {100 * leg['below']['heave']:.1f}/0.0" in note


def test_share_above_the_table_and_none_inside_it(tmp_path):
    # a table over 0.2..0.9 rad/s leaves the sea's short waves above it, where the RAO tapers to zero at
    # 1.35 rad/s: the share above is the spectrum's weighted by the tapered heave |H|^2 (1 inside the table);
    # if this fails, the share is not weighted by the response or the two sides are mixed up
    path = write(tmp_path, scenario_text(follower(tmp_path, 0.2, 0.9)))
    scenario = load_scenario(path)
    assembly = Assembly(scenario)
    shares = assembly.response.variance_outside_table()
    rao = scenario.vessel.rao
    _, above = spectral_share(scenario, 0.2, 0.9, lambda w: rao(w, np.full(w.size, math.pi))[:, 2])
    assert above > 5 * SAMPLING
    assert shares["above"]["heave"] == pytest.approx(above, abs=SAMPLING)
    assert shares["below"]["heave"] == 0.0  # the ocean's longest waves are shorter than 2 pi / 0.2 rad/s
    # a table over the whole sea: no share outside, and the console says nothing
    inside = write(tmp_path, scenario_text(follower(tmp_path, 0.05, 6.0)), "inside.toml")
    export = export_motions(Assembly(load_scenario(inside)), tmp_path / "inside.csv")
    (leg,) = export.outside_table["legs"]
    assert all(share in (0.0, None) for side in ("below", "above") for share in leg[side].values())
    assert outside_table_note(export.outside_table) is None

