"""The picture gallery: every shipped scenario from the orbit camera and from its bridge, then the same ships at
night, at dusk, in fog, in a gale and throwing spray, as headless marinesim draws them (960x540 JPEG of quality
85, the HUD on: a tenth of a PNG of the sea's detail), and docs/gallery/README.md listing them, so that the next
change to the picture can be compared by eye.

Run from the repository root: python docs/gallery/make_gallery.py [NAME ...]; with names (``heavy_weather_transit``,
``gale_transit``, ...) only the pictures whose file name starts with one are drawn again, the README all the same.
The frames are reproducible (headless renders use numpy.fft for the sea: the same scenario gives the same bytes).
"""

from __future__ import annotations

import dataclasses
import math
import sys
from datetime import datetime, timezone
from pathlib import Path

from PIL import Image

from marinesim.render.daylight import light_at
from marinesim.render.offscreen import Offscreen
from marinesim.render.renderer import RenderOptions
from marinesim.scenario import Scenario, load_scenario
from marinesim.sea.seastate import scaled_sea

HERE = Path(__file__).resolve().parent
ROOT = HERE.parents[1]
AT_S = {"heavy_weather_transit": 1200.0, "helideck_landing": 1200.0}
"""When to take the picture (s): an exercise's moment to show, else a minute in."""
NORTH_SEA = {"latitude_deg": 60.5, "longitude_deg": 2.0}


@dataclasses.dataclass(frozen=True)
class Shot:
    """A picture beyond the shipped ones: ``scenario`` (under configs/) at ``at_s`` under other ``[environment]``
    keys and its sea's heights times ``hs_factor``, from ``camera`` (orbit: at ``azimuth_deg`` from astern and
    ``elevation_deg``, ``distance_m`` out), with the HUD as ``hud`` (one of ``marinesim.render.HUDS``)."""

    name: str
    scenario: str
    what: str
    camera: str = "orbit"
    at_s: float = 60.0
    air: dict = dataclasses.field(default_factory=dict)
    azimuth_deg: float | None = None
    elevation_deg: float | None = None
    hs_factor: float = 1.0
    distance_m: float | None = None
    hud: str = "strip"
    orders: tuple = ()
    """(time s, the order's keywords) given on the way to ``at_s``."""


SHOTS = (
    Shot("helideck_panels", "training/helideck_landing.toml", "The helideck landing at the pitch alarm with the "
         "HUD's full panels (TAB): every criterion with its expected value and percentile, the motions' strip charts.",
         at_s=900.0, hud="panels"),
    Shot("night_tanker_port_bow", "default.toml", "The tanker at night from her port bow: masthead lights, red "
         "sidelight, a waxing moon.", air={"time_utc": datetime(2026, 11, 22, 21, 0, tzinfo=timezone.utc),
                                           **NORTH_SEA}, azimuth_deg=200.0, elevation_deg=6.0),
    Shot("night_tanker_astern", "default.toml", "The same night from astern: her sternlight only.",
         air={"time_utc": datetime(2026, 11, 22, 21, 0, tzinfo=timezone.utc), **NORTH_SEA}, azimuth_deg=10.0,
         elevation_deg=6.0),
    Shot("night_crane_lift", "training/crane_lift.toml", "The supply vessel lifting on DP at night from her port "
         "bow: red-white-red all round over her mast (restricted in her ability to manoeuvre, not making way: no "
         "masthead or sidelights).", air={"sun_elevation_deg": -25.0}, azimuth_deg=250.0, elevation_deg=6.0),
    Shot("dusk_loading", "training/offshore_loading.toml", "Offshore loading at dusk, broken cloud.",
         air={"time_utc": datetime(2026, 11, 25, 15, 10, tzinfo=timezone.utc), "cloud_cover_oktas": 5.0,
              **NORTH_SEA}, azimuth_deg=140.0, elevation_deg=10.0),
    Shot("fog_bridge", "default.toml", "Fog from the tanker's bridge: visibility 800 m, overcast; her lights are "
         "lit (restricted visibility).", camera="bridge", air={"visibility_m": 800.0, "cloud_cover_oktas": 8.0}),
    Shot("gale_transit", "training/heavy_weather_transit.toml", "The transit's gale at 1200 s: Hs 9 m, "
         "Beaufort 9 streaks, 7 oktas, 4 km visibility.", at_s=1200.0),
    Shot("storm_s175", "s175_heavy_weather.toml", "The S175 in a storm: the sea doubled, 24 m/s of wind (Beaufort "
         "9), overcast.", air={"wind_speed_m_s": 24.0, "cloud_cover_oktas": 8.0, "visibility_m": 5000.0},
         elevation_deg=12.0, hs_factor=2.0),
    Shot("turn_s175_bridge", "training/heavy_weather_transit.toml", "The S175 turning: 20 deg of starboard rudder "
         "ordered at 30 s, 65 s later; the conning line reads her heading, hand steering, the rudder, her rate of "
         "turn, "
         "the rpm set for 10 kn, her speed and course over ground (her bow 7 deg inside her track); she heels 3 deg "
         "outward, to port.", camera="bridge", at_s=95.0, orders=((30.0, {"rudder_deg": 20.0}),)),
    Shot("turn_s175_orbit", "training/heavy_weather_transit.toml", "The same moment from astern: she swings to "
         "starboard (her wash and wake are drawn straight astern of her, as on a straight course).", at_s=95.0,
         orders=((30.0, {"rudder_deg": 20.0}),)),
    Shot("bow_impact_s175", "s175_heavy_weather.toml", "The S175 half a second after the hardest bow impact of her "
         "first ten minutes (the sea rising against her stem at 1.7 times Ochi's slamming velocity; her forefoot stays "
         "in the water, so the slamming criterion stays at 0): spray off both sides of the bow.",
         at_s=401.2, azimuth_deg=125.0, elevation_deg=12.0, distance_m=200.0),
)


def save(scenario: Scenario, out: Path, camera: str, at_s: float, azimuth_deg: float | None = None,
         elevation_deg: float | None = None, distance_m: float | None = None, hud: str = "strip",
         orders: tuple = ()) -> None:
    with Offscreen(scenario, (960, 540), camera, "auto", RenderOptions(reproducible=True, hud=hud)) as view:
        orbit = view.scene.cameras["orbit"]
        if azimuth_deg is not None:
            orbit.azimuth_deg = azimuth_deg
        if elevation_deg is not None:
            orbit.elevation_deg = elevation_deg
        if distance_m is not None:
            orbit.distance_m = distance_m
        for t, order in orders:
            view.go_to(t)
            view.scene.exercise.act("order", **order)
        view.go_to(at_s)
        Image.fromarray(view.frame()).save(out, format="JPEG", quality=85)
    print(f"wrote {out.relative_to(ROOT)}")


def light_words(scenario: Scenario, at_s: float) -> str:
    air, light = scenario.environment, light_at(scenario.environment, at_s, scenario.sea)
    when = f"{air.time_utc:%Y-%m-%d %H:%M} UTC at {air.latitude_deg:g} N {air.longitude_deg:g} E; " if air.time_utc \
        else ""
    return (f"{when}sun {math.degrees(math.asin(light.sun[2])):+.0f} deg high; cloud {air.cloud_cover_oktas:g} oktas; "
            f"visibility {air.visibility_m / 1000:g} km; wind {light.wind[2]:.0f} m/s.")


def main(only: tuple[str, ...] = ()) -> None:
    """Draw the gallery (only the pictures whose name starts with one of ``only``, if given) and write its README."""
    rows = []
    for path in sorted((ROOT / "configs").glob("*.toml")) + sorted((ROOT / "configs" / "training").glob("*.toml")):
        scenario = load_scenario(path)
        at = min(AT_S.get(path.stem, 60.0), scenario.run.duration_s)
        shots = []
        for camera in ("orbit", "bridge"):
            out = HERE / f"{path.stem}_{camera}.jpg"
            if not only or out.stem.startswith(only):
                save(scenario, out, camera, at)
            shots.append(f"![{path.stem}, {camera}]({out.name})")
        rows.append(f"## {path.relative_to(ROOT)} at {at:g} s\n\n{light_words(scenario, at)}\n\n"
                    + "\n".join(shots) + "\n")
    rows.append("# The full panels; a turn; night, dusk, fog and storm\n")
    for shot in SHOTS:
        scenario = load_scenario(ROOT / "configs" / shot.scenario)
        sea = scaled_sea(scenario.sea, shot.hs_factor, 1.0, 0.0)
        air = scenario.environment.model_dump(exclude_unset=True)
        if "time_utc" in shot.air:  # the sun from the shot's date, not the scenario's sun keys
            air = {k: v for k, v in air.items() if not k.startswith("sun_")}
        elif any(k.startswith("sun_") for k in shot.air):  # the shot's sun, not the scenario's date
            air = {k: v for k, v in air.items() if k not in ("time_utc", "latitude_deg", "longitude_deg")}
        environment = type(scenario.environment).model_validate(air | shot.air)
        scenario = dataclasses.replace(scenario, sea=sea, environment=environment)
        out = HERE / f"{shot.name}.jpg"
        if not only or out.stem.startswith(only):
            save(scenario, out, shot.camera, shot.at_s, shot.azimuth_deg, shot.elevation_deg, shot.distance_m,
                 shot.hud, shot.orders)
        rows.append(f"## {shot.name}: configs/{shot.scenario} at {shot.at_s:g} s\n\n{shot.what} "
                    f"{light_words(scenario, shot.at_s)}\n\n![{shot.name}]({out.name})\n")
    (HERE / "README.md").write_text("# Picture gallery\n\nEvery shipped scenario from the orbit camera and from its "
                                    "bridge, then night, dusk, fog and storm, as `marinesim render --screenshot` "
                                    "draws them headless (960x540, here on Mesa's llvmpipe), with the HUD's "
                                    "compact strip (one shot shows its full panels). Made by "
                                    "`python docs/gallery/make_gallery.py`.\n\n" + "\n".join(rows))


if __name__ == "__main__":
    main(tuple(sys.argv[1:]))
