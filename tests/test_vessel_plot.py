"""The RAO plot: its speed in knots like everything else, and phase panels that show the phase where it
means something, unwrapped along frequency, instead of a thicket of +-180 deg wraps and the noise of responses
near zero."""

import math

import numpy as np

from conftest import DEFAULT
from marinesim.scenario import load_scenario
from marinesim.vessel.plot import PHASE_SHOWN_FROM, plot_rao, rao_figure
from marinesim.vessel.rao import DOFS

HEADINGS = [180.0, 135.0, 90.0, 45.0, 0.0]


def test_the_default_vessels_rao_plot_gives_knots_and_unwrapped_phase_where_the_response_is(tmp_path):
    """The default scenario's tanker at her 4 kn, as the headless run draws her: the title says 4 kn (it said
    2.06 m/s); on every phase curve no two neighbouring drawn points differ by more than 180 deg (a wrap drawn
    as a spike), and a point is drawn exactly where the amplitude reaches the share of the DOF's peak (its
    phase elsewhere is noise); every DOF keeps some phase drawn. The figure saves as a PNG."""
    vessel = load_scenario(DEFAULT).vessel
    figure = rao_figure(vessel.rao, HEADINGS, vessel.speed_m_s)
    title = figure.get_suptitle()
    assert title.endswith(", 4 kn") and "m/s" not in title, title
    for j, dof in enumerate(DOFS):
        amplitude_axes, phase_axes = figure.axes[2 * j], figure.axes[2 * j + 1]
        amplitudes = [line.get_ydata() for line in amplitude_axes.get_lines()]
        phases = [line.get_ydata() for line in phase_axes.get_lines()]
        assert len(amplitudes) == len(phases) == len(HEADINGS)
        peak = max(a.max() for a in amplitudes)
        for heading, amplitude, phase in zip(HEADINGS, amplitudes, phases):
            drawn = phase[np.isfinite(phase)]
            assert np.all(np.abs(np.diff(drawn)) <= 180.0), f"{dof} at {heading:g} deg jumps by a wrap"
            np.testing.assert_array_equal(np.isfinite(phase), amplitude >= PHASE_SHOWN_FROM * peak,
                                          err_msg=f"{dof} at {heading:g} deg")
        assert any(np.isfinite(phase).any() for phase in phases), f"no {dof} phase drawn"
    assert not np.isfinite(figure.axes[3].get_lines()[0].get_ydata()).any(), "head seas' sway is noise, not drawn"
    plot_rao(vessel.rao, tmp_path / "rao.png", HEADINGS, vessel.speed_m_s)
    assert (tmp_path / "rao.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


def test_a_wrapped_phase_would_have_jumped(tmp_path):
    """The check above can fail: the default tanker's heave phase in head seas, wrapped to +-180 deg as the plot
    drew it, has a jump of more than 180 deg between neighbouring drawn points."""
    vessel = load_scenario(DEFAULT).vessel
    omega = np.geomspace(vessel.rao.omega[0], vessel.rao.omega[-1], 400)
    h = vessel.rao(omega, np.full(omega.size, math.pi), vessel.speed_m_s)[:, 2]
    shown = np.abs(h) >= PHASE_SHOWN_FROM * np.abs(h).max()
    assert np.abs(np.diff(np.degrees(np.angle(h[shown])))).max() > 180.0
