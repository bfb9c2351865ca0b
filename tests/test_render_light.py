"""The light a scene is drawn in (marinesim/render/daylight.py) and the navigation lights (nav_lights.py).

The sun and the moon are checked against a second ephemeris (PyEphem, the XEphem library's VSOP87 and ELP
series) rather than against astral itself; the lights' intensities against COLREG Annex I's own table; the
pictures on a real OpenGL context: night is dark but its lights are lit, each light only in its sector, an
overcast sky has no sun glitter and its cloud covers the sky's share the oktas say."""

from __future__ import annotations

import dataclasses
import math
from datetime import datetime, timezone

import ephem
import numpy as np
import pytest

from conftest import luminance, offscreen, run_lengths
from marinesim.constants import NAUTICAL_MILE
from marinesim.render.daylight import bodies_at, illuminated_fraction, light_at, visible_drops_m3
from marinesim.render.nav_lights import (CUT_OFF_DEG, RED, THRESHOLD_LUX, TRANSMISSIVITY, WHITE,
                                         illuminance_lux, lit, luminous_intensity_cd, place_lights, sector_weight)
from marinesim.scenario.model import EnvironmentOptions


PLACES = [("2026-11-25T22:00:00", 60.0, 2.0), ("2026-06-21T12:00:00", 60.0, 2.0),
          ("2026-03-20T18:00:00", -33.9, 18.4), ("2027-01-10T05:30:00", 29.4, -94.8),
          ("2026-09-01T03:00:00", 1.3, 103.8)]
"""North Sea at night and at the solstice's noon, Cape Town at dusk, Galveston before dawn, Singapore Strait."""


def compass_and_elevation(v) -> tuple[float, float]:
    return (90.0 - math.degrees(math.atan2(v[1], v[0]))) % 360.0, math.degrees(math.asin(v[2]))


@pytest.mark.parametrize("when, latitude, longitude", PLACES)
def test_sun_and_moon_stand_where_a_second_ephemeris_puts_them(when, latitude, longitude):
    """Within 0.05 deg for the sun (astral's refraction is the difference) and 0.1 deg for the moon, whose
    parallax (up to a degree: two of its diameters) must be taken off astral's geocentric position; the moon's
    lit fraction within 1 % (the elongation seen from the surface differs from the Earth centre's by the parallax). A swapped azimuth convention would be off by 90 or 180 deg."""
    t = datetime.fromisoformat(when).replace(tzinfo=timezone.utc)
    sun, moon = bodies_at(EnvironmentOptions(time_utc=t, latitude_deg=latitude, longitude_deg=longitude), 0.0)
    observer = ephem.Observer()
    observer.lat, observer.lon, observer.pressure = str(latitude), str(longitude), 0.0
    observer.date = t.strftime("%Y/%m/%d %H:%M:%S")
    for ours, body, within in ((sun, ephem.Sun(observer), 0.05), (moon, ephem.Moon(observer), 0.1)):
        azimuth, elevation = compass_and_elevation(ours)
        assert elevation == pytest.approx(math.degrees(body.alt), abs=within)
        assert (azimuth - math.degrees(body.az) + 180.0) % 360.0 - 180.0 == pytest.approx(0.0, abs=within)
    assert illuminated_fraction(sun, moon) == pytest.approx(ephem.Moon(observer).phase / 100.0, abs=0.01)


def test_a_time_with_another_offset_is_the_same_instant():
    """16:00+02:00 is 14:00 UTC for the sun and the moon alike (astral's moon reads the clock, not the offset)."""
    from datetime import timedelta

    utc = EnvironmentOptions(time_utc=datetime(2026, 11, 25, 22, 0, tzinfo=timezone.utc), latitude_deg=60.0,
                             longitude_deg=2.0)
    local = EnvironmentOptions(time_utc=datetime(2026, 11, 26, 0, 0, tzinfo=timezone(timedelta(hours=2))),
                               latitude_deg=60.0, longitude_deg=2.0)
    assert np.allclose(bodies_at(utc, 0.0), bodies_at(local, 0.0), atol=1e-9)


def test_the_sun_moves_with_the_run():
    """An hour into a run the sun has moved by about 15 deg of hour angle: it stands higher in the morning."""
    morning = EnvironmentOptions(time_utc=datetime(2026, 6, 21, 6, 0, tzinfo=timezone.utc), latitude_deg=60.0,
                                 longitude_deg=2.0)
    low, high = (compass_and_elevation(bodies_at(morning, t)[0])[1] for t in (0.0, 3600.0))
    assert 6.0 < high - low < 12.0


def test_the_sky_darkens_through_twilight_and_clouds_dim_it():
    """Brighter with every step of sun elevation from night to day; 8 oktas of cloud let through a quarter of the
    light (Kasten and Czeplak), none of the direct sun's glitter (tested in the picture below)."""
    night = light_at(EnvironmentOptions(sun_elevation_deg=-30.0)).sky
    levels = [light_at(EnvironmentOptions(sun_elevation_deg=h)).sky for h in (-18, -12, -6, 0, 6, 30)]
    assert night == levels[0], "below astronomical twilight the sun no longer lights the sky"
    assert all(a < b for a, b in zip(levels, levels[1:]))
    assert levels[0] < 0.01 * levels[-1]
    assert light_at(EnvironmentOptions(cloud_cover_oktas=8)).sky == pytest.approx(0.25 * levels[-1])
    red, _, blue = light_at(EnvironmentOptions(sun_elevation_deg=2.0)).sun_colour
    assert red > 3.0 * blue, "a sun on the horizon shines through some 20 air masses: red"


# -- navigation lights ---------------------------------------------------------------------------------------

@pytest.mark.parametrize("range_nm, candela", [(1, 0.9), (2, 4.3), (3, 12.0), (4, 27.0), (5, 52.0), (6, 94.0)])
def test_intensities_follow_annex_one_and_reach_their_range_in_its_atmosphere(range_nm, candela):
    """Annex I section 8(b)'s table of minimum intensities; and seen through the atmosphere it assumes (K = 0.8 per
    nm, a meteorological visibility of ln 20 / -ln 0.8 nm), the light gives the threshold illuminance at its range."""
    assert luminous_intensity_cd(range_nm) == pytest.approx(candela, rel=0.05)
    visibility_m = math.log(20.0) / -math.log(TRANSMISSIVITY) * NAUTICAL_MILE
    at_range = illuminance_lux(luminous_intensity_cd(range_nm), range_nm * NAUTICAL_MILE, visibility_m)
    assert at_range == pytest.approx(THRESHOLD_LUX, rel=1e-4)  # Annex I's 3.43e6 is 1852^2 rounded


def test_sectors_cover_the_horizon_as_rule_21_draws_them(default):
    """Masthead and sternlight share the horizon between them, each bearing once; the sidelights split the
    masthead's arc at the bow; every light falls to nothing within the cut-off outside its arc."""
    mesh = offscreen_mesh(default)
    lights = {light.name: light for light in place_lights(mesh, "underway", default.vessel.points["bridge"])}
    bearings = np.arange(-180.0, 180.0, 0.25)
    fully = {name: sector_weight(light, bearings) == 1.0 for name, light in lights.items()}
    inside = (np.abs(bearings) < 112.5 - CUT_OFF_DEG) | (np.abs(bearings) > 112.5 + CUT_OFF_DEG)
    assert np.all(fully["masthead forward"] ^ fully["sternlight"] | ~inside)
    assert np.array_equal(fully["masthead forward"], fully["port sidelight"] | fully["starboard sidelight"])
    assert np.all(fully["port sidelight"][(bearings >= 0) & (bearings <= 112.5)])
    assert not np.any(sector_weight(lights["port sidelight"], np.array([-CUT_OFF_DEG, 112.5 + CUT_OFF_DEG])))
    assert lights["masthead aft"].position[2] >= lights["masthead forward"].position[2] + 4.5
    assert lights["port sidelight"].position[1] > 0 > lights["starboard sidelight"].position[1]
    anchored = place_lights(mesh, "anchored")
    assert [light.sector_deg for light in anchored] == [(0.0, 360.0)] * 2
    restricted = place_lights(mesh, "restricted", default.vessel.points["bridge"])
    signal = [light for light in restricted if light.name.startswith("restricted")]
    assert [light.colour for light in signal] == [RED, WHITE, RED], "Rule 27 (b): red, white, red from below"
    heights = [light.position[2] for light in signal]
    assert np.allclose(np.diff(heights), 2.0) and all(light.sector_deg == (0.0, 360.0) for light in signal)
    assert len({light.position[:2] for light in signal}) == 1, "not in a vertical line"
    assert {light.name for light in restricted} >= set(lights), "restricted drops the lights of a vessel underway"
    on_dp = place_lights(mesh, "restricted", default.vessel.points["bridge"], making_way=False)
    assert on_dp == signal, "Rule 27 (b)(iii): not making way, only red-white-red"


def test_lights_are_lit_from_sunset_and_in_restricted_visibility():
    assert not lit(0.5, 40_000.0) and lit(-0.01, 40_000.0) and lit(0.5, 1_000.0)


def offscreen_mesh(scenario) -> np.ndarray:
    from marinesim.render.layers.vessel import drawn_mesh
    from marinesim.session.timeline import Simulation

    sim = Simulation(scenario, wake=False)
    try:
        return drawn_mesh(sim).positions
    finally:
        sim.close()


def night_of(scenario, **air):
    """``scenario`` under the ``[environment]`` keys ``air``."""
    return dataclasses.replace(scenario, environment=EnvironmentOptions(**air))


LIGHT_COLOURS = {"port sidelight": "red", "starboard sidelight": "green", "sternlight": "white",
                 "masthead forward": "white", "masthead aft": "white"}


def colour_at(image: np.ndarray, pixel) -> str:
    """What a light looks like at ``pixel``: the brightest of its 5 x 5 neighbourhood, named."""
    x, y = int(round(pixel[0])), int(round(pixel[1]))
    patch = image[max(y - 2, 0):y + 3, max(x - 2, 0):x + 3].reshape(-1, 3).astype(int)
    r, g, b = patch[np.argmax(patch.sum(axis=1))]
    if min(r, g, b) > 170:
        return "white"
    if r > 140 and r > g + 80:
        return "red"
    if g > 140 and g > r + 80:
        return "green"
    return "dark"


@pytest.mark.parametrize("azimuth, seen", [
    (0.0, {"sternlight"}),                                                     # from astern
    (172.0, {"masthead forward", "masthead aft", "starboard sidelight"}),      # fine on the starboard bow
    (188.0, {"masthead forward", "masthead aft", "port sidelight"}),           # fine on the port bow
    (90.0, {"masthead forward", "masthead aft", "starboard sidelight"}),       # starboard beam
    (270.0, {"masthead forward", "masthead aft", "port sidelight"}),           # port beam
])
def test_night_is_dark_and_each_light_shows_only_in_its_sector(default, azimuth, seen):
    """The tanker at night from the orbit camera round her: every light whose sector holds the eye is a point of
    its colour where it projects; every other light leaves its place dark. A sidelight seen from the wrong side,
    or a sternlight from ahead, would give another ship's aspect: a collision."""
    night = night_of(default, sun_elevation_deg=-30.0)
    with offscreen(night, size=(960, 540)) as view:
        view.scene.cameras["orbit"].azimuth_deg = azimuth
        view.scene.cameras["orbit"].elevation_deg = 8.0
        view.go_to(10.0)
        image = view.frame(hud=False)
        eye = view.scene.camera.eye(view.scene.sim.pose())
        pose = view.scene.sim.pose().matrix()
        lights = view.scene.renderer.nav_lights.lights
        assert luminance(image).mean() < 25.0, "a moonless night should be dark"
        for light in lights:
            world = pose[:3, :3] @ np.asarray(light.position) + pose[:3, 3]
            x, y, _ = eye.project(world[None, :], (960, 540))[0]
            expected = LIGHT_COLOURS[light.name] if light.name in seen else "dark"
            assert colour_at(image, (x, y)) == expected, (light.name, azimuth)


def test_an_overcast_sky_takes_the_suns_glitter_off_the_water(default):
    """Looking towards the sun over the water: a clear day's glitter is the brightest thing on the sea; under 8
    oktas there is no direct sun and the sea's brightest pixels are far dimmer."""
    brightest = {}
    for oktas in (0, 8):
        with offscreen(night_of(default, cloud_cover_oktas=oktas), size=(480, 270)) as view:
            view.scene.camera_name = "free"
            free = view.scene.cameras["free"]
            free.position, free.yaw_deg, free.pitch_deg = (0.0, -600.0, 30.0), 90.0 - 200.0, -12.0
            view.go_to(10.0)
            image = view.frame(hud=False)
        brightest[oktas] = float(np.percentile(luminance(image[image.shape[0] // 2:]), 99.5))
    assert brightest[8] < 0.6 * brightest[0], brightest


def rain_streaks(scenario, rain_mm_h: float) -> np.ndarray:
    """Pixels that rain of ``rain_mm_h`` changes in the tanker's bridge view, HUD off: a (rows, cols) bool mask."""
    frames = []
    for rate in (rain_mm_h, 0.0):
        with offscreen(night_of(scenario, rain_mm_h=rate, cloud_cover_oktas=8.0, wind_speed_m_s=0.0),
                       size=(480, 270)) as view:
            view.scene.camera_name = "bridge"
            view.go_to(10.0)
            frames.append(view.frame(hud=False).astype(int))
    return np.abs(frames[0] - frames[1]).max(axis=-1) > 8


def test_rain_falls_in_upright_streaks_more_of_them_the_harder_it_rains(default):
    """Light rain (2.5 mm/h) has a ninth of the visible drops (over 1 mm) of violent showers (50 mm/h) by Marshall
    and Palmer's sizes: far fewer streaks; in calm air they fall upright: each streak runs down the picture several
    times further than across it."""
    assert visible_drops_m3(2.5) / visible_drops_m3(50.0) == pytest.approx(0.107, abs=0.005)
    light, violent = rain_streaks(default, 2.5), rain_streaks(default, 50.0)
    assert 0.0005 < light.mean() < 0.3 * violent.mean()
    assert run_lengths(violent.T) > 3.0 * run_lengths(violent)
