"""What a DP operator sees in the viewer: the footprint plot, the offset chart and the thrusters' use, on the
shipped supply vessel on DP (configs/supply_dp.toml) after her first bow tunnel was lost at 10 minutes."""

from __future__ import annotations

import numpy as np

from conftest import ROOT
from marinesim.scenario import load_scenario


def test_the_panels_show_the_footprint_plot_and_each_thrusters_use_with_the_lost_one_crossed_out():
    """At 11 minutes with the panels on (1280 x 720): the DP line names her offset against the 5 m footprint and
    each thruster's use, the lost bow tunnel as X; the footprint plot sits at the right (its circle green: she is
    inside) and leaves the middle of the picture, the vessel's, free; a fifth strip chart gives the offset.
    What would be wrong if not: a DP operator without the position plot, or a lost thruster shown as idle."""
    from marinesim.render.offscreen import Offscreen
    from marinesim.render.renderer import RenderOptions

    scenario = load_scenario(ROOT / "configs" / "supply_dp.toml")
    with Offscreen(scenario, (1280, 720), solver="off", options=RenderOptions(reproducible=True, hud="panels",
                                                                              wake=False)) as view:
        view.go_to(660.0)
        lines = view.scene.hud_lines()
        footprint = view.scene.footprint()
        charts = [chart.title for chart in view.scene.charts()]
        with_hud = view.frame(hud=True).astype(int)
        bare = view.frame(hud=False).astype(int)
    dp = next(line for line in lines if line.startswith("DP  offset"))
    assert "/ 5 m" in dp and "thrust % X " in dp, dp
    assert charts[-1] == "offset"
    assert footprint is not None and footprint.radius == 5.0 and footprint.east.size > 100
    assert np.hypot(footprint.east, footprint.north).max() < 5.0
    hud = np.abs(with_hud - bare).sum(axis=2) > 30
    green = (with_hud[..., 1] > 180) & (with_hud[..., 0] < 150) & (with_hud[..., 2] < 160) & hud
    right = green[:, 1280 - 300:]
    assert right[:360].sum() > 150, "the footprint's green circle at the top right"
    assert hud[260:460, 440:840].mean() < 0.02, "the middle, where the vessel is, stays free"
