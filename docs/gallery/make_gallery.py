"""The picture gallery: every shipped scenario from the orbit camera and from its bridge, as headless marinesim
draws them (960x540 JPEG of quality 85, the HUD on: a tenth of a PNG of the sea's detail), and
docs/gallery/README.md listing them, so that the next change to the
picture can be compared by eye.

Run from the repository root: python docs/gallery/make_gallery.py
The frames are reproducible (headless renders use numpy.fft for the sea: the same scenario gives the same bytes).
"""

from __future__ import annotations

from pathlib import Path

from PIL import Image

from marinesim.render.offscreen import Offscreen
from marinesim.render.renderer import RenderOptions
from marinesim.scenario import load_scenario

HERE = Path(__file__).resolve().parent
ROOT = HERE.parents[1]
AT_S = {"heavy_weather_transit": 300.0, "helideck_landing": 920.0}
"""When to take the picture (s): an exercise's moment to show, else a minute in."""


def main() -> None:
    rows = []
    for path in sorted((ROOT / "configs").glob("*.toml")) + sorted((ROOT / "configs" / "training").glob("*.toml")):
        scenario = load_scenario(path)
        at = min(AT_S.get(path.stem, 60.0), scenario.run.duration_s)
        shots = []
        for camera in ("orbit", "bridge"):
            out = HERE / f"{path.stem}_{camera}.jpg"
            with Offscreen(scenario, (960, 540), camera, "auto", RenderOptions(reproducible=True)) as view:
                view.go_to(at)
                Image.fromarray(view.frame()).save(out, format="JPEG", quality=85)
            shots.append(f"![{path.stem}, {camera}]({out.name})")
            print(f"wrote {out.relative_to(ROOT)}")
        air = scenario.environment
        rows.append(f"## {path.relative_to(ROOT)} at {at:g} s\n\nSun {air.sun_azimuth_deg:g} deg, "
                    f"{air.sun_elevation_deg:g} deg high; visibility {air.visibility_m / 1000:g} km.\n\n"
                    + "\n".join(shots) + "\n")
    (HERE / "README.md").write_text("# Picture gallery\n\nEvery shipped scenario from the orbit camera and from its "
                                    "bridge, as `marinesim render --screenshot` draws them headless (960x540, "
                                    "here on Mesa's llvmpipe). Made by "
                                    "`python docs/gallery/make_gallery.py`.\n\n" + "\n".join(rows))


if __name__ == "__main__":
    main()
