"""The ``marinesim`` command. User mistakes print one line and exit with status 2."""

from __future__ import annotations

import argparse
import json
import math
import sys
from pathlib import Path

import numpy as np

from marinesim import __version__
from marinesim.atomic import atomic_path
from marinesim.errors import MarinesimError, ParameterError, require_finite
from marinesim.formats import extensions, formats
from marinesim.progress import reporting
from marinesim.sea import Ocean, SeaState
from marinesim.sea.build import SPECTRUM_TYPES, SPREADING_TYPES, wave_system
from marinesim.sea.summary import summary

def main(argv: list[str] | None = None) -> int:
    parser = _parser()
    args = parser.parse_args(argv)
    if args.command is None:
        parser.print_help()
        return 0
    try:
        return args.handler(args)
    except MarinesimError as error:
        print(f"marinesim {args.command}: error: {error}", file=sys.stderr)
        return 2
    except KeyboardInterrupt:
        print(f"marinesim {args.command}: interrupted (files being written were discarded)", file=sys.stderr)
        return 130
    except OSError as error:
        print(f"marinesim {args.command}: error: {error.strerror or error}: {error.filename}", file=sys.stderr)
        return 2


def _parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(
        prog="marinesim",
        description="Ship motion and wake simulator: waves on FFT cascades, RAO response, Kelvin wake.",
    )
    parser.add_argument("--version", action="version", version=f"marinesim {__version__}")
    commands = parser.add_subparsers(dest="command", metavar="COMMAND")
    _add_run(commands)
    _add_render(commands)
    _add_export(commands)
    _add_rao(commands)
    _add_hull(commands)
    _add_wake(commands)
    _add_sea(commands)
    return parser


def _bars(quiet: bool):
    """A progress reporter drawing tqdm bars on stderr (None when ``quiet``)."""
    if quiet:
        return None
    from tqdm import tqdm

    def bar(name: str, total: int, unit: str):
        return tqdm(total=total, desc=name, unit=unit, file=sys.stderr, mininterval=0.5)
    return bar


def _number_list(option: str, text: str, unit: str) -> list[float]:
    """Comma-separated finite numbers, or a ParameterError naming the option."""
    try:
        return [require_finite(option, float(v)) for v in text.split(",")]
    except ValueError:
        raise ParameterError(f"{option} must be comma-separated {unit}, got {text!r}") from None


def _add_hull_options(p: argparse.ArgumentParser) -> None:
    g = p.add_argument_group("hull placement (meshes carry no units and often other axes)")
    g.add_argument("--units", default="m", help="mesh length units: m, cm, mm, ft, in (default m)")
    g.add_argument("--scale", type=float, default=1.0, help="geometric scale of a model mesh, e.g. 50 for 1:50")
    g.add_argument("--axes", default="x,y,z", help="mesh axes that become body x (forward), y (port), z (up), "
                                                   "e.g. 'x,-z,y' for a y-up mesh (default x,y,z)")
    g.add_argument("--draft", type=float, help="draft, m: the lowest point goes to z = -draft (default: the "
                                               "mesh's z = 0 is the waterline)")
    g.add_argument("--trim-deg", type=float, default=0.0, help="trim, deg, bow down positive (default 0)")


def _hull_from_args(args: argparse.Namespace):
    from marinesim.hull import load_hull

    return load_hull(args.hull, units=args.units, scale=args.scale, axes=args.axes, draft=args.draft,
                     trim_deg=args.trim_deg)


def _add_hull(commands: argparse._SubParsersAction) -> None:
    p = commands.add_parser(
        "hull", help="check a hull mesh and print its hydrostatics",
        description=f"Read a hull ({', '.join(extensions('mesh'))}), place it in the body frame "
                    "(x forward, y to port, z up, waterline z = 0), check it and print its hydrostatics.")
    p.add_argument("hull", type=Path, help="hull mesh file")
    _add_hull_options(p)
    p.add_argument("--json", action="store_true", help="print the summary as one JSON object")
    p.set_defaults(handler=_run_hull)


def _run_hull(args: argparse.Namespace) -> int:
    from marinesim.hull import format_hydrostatics, hydrostatics

    hull = _hull_from_args(args)
    statics = hydrostatics(hull)
    if args.json:
        print(json.dumps(statics.as_dict() | {"triangles": len(hull.faces), "notes": list(hull.notes)}))
    else:
        print(f"{hull.source}: {len(hull.faces):,} triangles")
        print(format_hydrostatics(statics))
        for note in hull.notes:
            print(f"note: {note}")
    return 0


def _add_wake(commands: argparse._SubParsersAction) -> None:
    p = commands.add_parser(
        "wake", help="compute the Kelvin wake and wave resistance of a hull",
        description="Integrate Tuck's amplitude function A(theta) exactly over the wetted triangles of the hull "
                    f"({', '.join(extensions('mesh'))}), "
                    "give Michell's wave resistance, and compute the far-field wake on a grid in the vessel "
                    "frame. Results are cached; --out writes the field, its grid and the parameters (.npz).")
    p.add_argument("hull", type=Path, help="hull mesh file")
    p.add_argument("--speed-kn", required=True,
                   help="speed, kn; several comma-separated speeds are precomputed in one call")
    _add_hull_options(p)
    g = p.add_argument_group("grid (default: lambda0 / 16 spacing, lambda0 = 2 pi U^2 / g)")
    g.add_argument("--nx", type=int, default=2048, help="cells along the track (default 2048)")
    g.add_argument("--ny", type=int, default=1024, help="cells across (default 1024)")
    g.add_argument("--spacing", type=float, help="cell size, m")
    out = p.add_argument_group("output")
    out.add_argument("--out", type=Path, help="write the wake (.npz); with several speeds, NAME_<speed>kn.npz")
    out.add_argument("--plot", type=Path, metavar="PATH", help="draw the field and |A(theta)| (PNG)")
    out.add_argument("--json", action="store_true", help="print one JSON object (a list with several speeds)")
    out.add_argument("--no-cache", action="store_true", help="compute even if the cache has the result")
    out.add_argument("--quiet", action="store_true", help="no progress bar")
    p.set_defaults(handler=_run_wake)


def _run_wake(args: argparse.Namespace) -> int:
    import time

    from marinesim.constants import KNOT
    from marinesim.wake.cache import cached_wake
    from marinesim.wake.compute import WakeGrid, compute_wake
    from marinesim.wake.plot import plot_wake

    speeds = _number_list("--speed-kn", args.speed_kn, "knots")
    if any(v <= 0 for v in speeds):
        raise ParameterError(f"--speed-kn must be > 0 (a hull at rest makes no wake), got {args.speed_kn}")
    for path in (args.out, args.plot):
        if path is not None and not path.resolve().parent.is_dir():
            raise ParameterError(f"cannot write {path}: folder {path.resolve().parent} does not exist")
    grid = WakeGrid(args.nx, args.ny, args.spacing)
    hull = _hull_from_args(args)
    reports = []
    for speed_kn in speeds:
        started = time.perf_counter()
        with reporting(_bars(args.quiet)):
            if args.no_cache:
                wake, cached = compute_wake(hull, speed_kn * KNOT, grid), False
            else:
                wake, cached = cached_wake(hull, speed_kn * KNOT, grid)
        report = {key: wake.info[key] for key in ("speed_m_s", "speed_kn", "froude", "wave_resistance_N",
                                                  "wave_resistance_coefficient", "kelvin_half_angle_deg",
                                                  "transverse_wavelength_m", "measured_transverse_wavelength_m")}
        report |= {key: wake.info[key] for key in ("validity_note", "grid_note", "measurement_note") if key in wake.info}
        report |= {"seconds": time.perf_counter() - started, "cached": cached,
                   "seconds_computing": wake.info["seconds_amplitude"] + wake.info["seconds_field"]}
        for flag, suffix in ((args.out, ".npz"), (args.plot, ".png")):
            if flag:
                path = flag if len(speeds) == 1 else flag.with_name(f"{flag.stem}_{speed_kn:g}kn{flag.suffix or suffix}")
                if suffix == ".npz":
                    wake.save(path)
                else:
                    with atomic_path(path) as temp:
                        plot_wake(wake, temp)
                report["out" if suffix == ".npz" else "plot"] = str(path)
        reports.append(report)
        if not args.json:
            print(_format_wake(report, hull.notes if speed_kn == speeds[0] else ()))
    if args.json:
        print(json.dumps(reports[0] if len(reports) == 1 else reports))
    return 0


def _format_wake(r: dict, notes: tuple[str, ...]) -> str:
    angle = r["kelvin_half_angle_deg"]
    lines = [f"{r['speed_kn']:.3g} kn ({r['speed_m_s']:.3f} m/s), Fn {r['froude']:.3f}: wave resistance "
             f"{r['wave_resistance_N'] / 1e3:,.1f} kN (Cw {r['wave_resistance_coefficient']:.3e})",
             "  Kelvin half-angle measured on the field: "
             + (f"{angle:.2f} deg (theory 19.47)" if angle is not None else "not measured (see the note)"),
             f"  transverse wavelength {r['transverse_wavelength_m']:.2f} m (2 pi U^2 / g)",
             f"  {r['seconds']:.2f} s" + (" (from the cache)" if r["cached"] else "")]
    lines += [f"  wrote {r[key]}" for key in ("out", "plot") if key in r]
    lines += [f"note: {r[key]}" for key in ("validity_note", "grid_note", "measurement_note") if r.get(key)]
    lines += [f"note: {note}" for note in notes]
    return "\n".join(lines)


def _add_view_options(p: argparse.ArgumentParser) -> None:
    from marinesim.render.scene import CAMERAS

    g = p.add_argument_group("view")
    g.add_argument("--camera", choices=CAMERAS, default="orbit", help="orbit (default), bridge or free")
    g.add_argument("--solver", choices=("auto", "on", "off"), default="auto",
                   help="the local wave solver around the hull: auto = on with a GPU, off on a software renderer")
    g.add_argument("--no-wake", action="store_true", help="do not draw the Kelvin wake")


def _render_options(args: argparse.Namespace):
    from marinesim.render.renderer import RenderOptions

    return RenderOptions(wake=not args.no_wake)


def _add_run(commands: argparse._SubParsersAction) -> None:
    p = commands.add_parser(
        "run", help="open the viewer on a scenario (default configs/default.toml)",
        description="Open the viewer on a scenario: the vessel moving in the rendered sea with its wake "
        "(H in the window lists the keys). Without a display it runs headless instead: plots of the sea, "
        "the motions and the RAOs, the motion CSV over the scenario's run, and a 10 s video, and says where "
        "they are.",
    )
    p.add_argument("scenario", nargs="?", type=Path, help="scenario TOML file (default: the shipped default.toml)")
    p.add_argument("--out", type=Path, help="output folder of a headless run (default out/<scenario name>)")
    p.add_argument("--headless", action="store_true", help="do not open a window even if there is a display")
    p.add_argument("--quiet", action="store_true", help="no progress bar")
    _add_view_options(p)
    p.set_defaults(handler=_run_scenario)


HEADLESS_VIDEO = {"seconds": 10.0, "size": (640, 360), "fps": 25.0}
"""The video a headless ``run`` renders: short and small, so that a software renderer makes it in a minute."""


def _run_scenario(args: argparse.Namespace) -> int:
    from marinesim.scenario import load_scenario
    from marinesim.session.assembly import Assembly
    from marinesim.session.headless import run_headless

    from marinesim.resources import default_scenario

    scenario = load_scenario(args.scenario or default_scenario())
    print(f"scenario {scenario.path}: {len(scenario.sea.systems)} wave system(s), Hs {scenario.sea.hs:.2f} m, "
          f"Tp {scenario.sea.tp:.2f} s, {scenario.run.duration_s:g} s at dt {scenario.run.dt_s:g} s, "
          f"seed {scenario.run.seed}")
    vessel = scenario.vessel
    if vessel is not None:
        print(f"vessel: {vessel.rao_path.name} ({vessel.rao.source_format}), {vessel.speed_kn:.3g} kn, "
              f"heading {vessel.heading_deg:g} deg, points: {', '.join(vessel.points) or 'none'}")
    if not args.headless:
        from marinesim.render.viewer import NoDisplay, Viewer

        try:
            with reporting(_bars(False)):
                viewer = Viewer(scenario, args.camera, args.solver, options=_render_options(args))
        except NoDisplay as reason:
            print(f"{reason}: running headless instead")
        else:
            print("viewer open: H lists the keys, ESC quits")
            viewer.run()
            return 0
    out_dir = args.out or Path("out") / scenario.name
    with reporting(_bars(args.quiet)):
        headless = run_headless(Assembly(scenario), out_dir)
        for note in headless.notes:
            print(note)
        files = headless.files | _headless_video(scenario, out_dir, args)
    described = {"sea_plot": "the sea state picture", "motions": "the vessel's 6-DOF motions",
                 "sidecar": "their metadata", "motions_plot": "a plot of the motions", "rao_plot": "the RAOs",
                 "elevation": "the wave elevation at (0, 0)", "elevation_plot": "a plot of it",
                 "wake_plot": "the Kelvin wake", "video": "a video of the first seconds"}
    width = max(len(described[key]) for key in files)
    for key, path in files.items():
        print(f"wrote {described[key] + ':':{width + 1}s} {path}")
    return 0


def _headless_video(scenario, out_dir: Path, args: argparse.Namespace) -> dict[str, Path]:
    from marinesim.render.offscreen import render_video

    video = HEADLESS_VIDEO
    seconds = min(video["seconds"], scenario.run.duration_s)
    size = video["size"]
    print(f"rendering {seconds:g} s of video at {size[0]}x{size[1]}, {video['fps']:g} frames/s through EGL "
          f"(camera {args.camera})")
    result = render_video(scenario, out_dir / "video.mp4", seconds, size, video["fps"], args.camera, args.solver,
                          _render_options(args), motions=False)
    print(f"the local wave solver was {'on' if result.solver else 'off (software renderer; --solver on forces it)'}")
    return {"video": result.video}


def _add_render(commands: argparse._SubParsersAction) -> None:
    p = commands.add_parser(
        "render", help="render a scenario headless: an MP4 video with its motion CSV, or a screenshot",
        description="Render a scenario without a window (EGL). A video gets the motions over its length "
        "beside it (the same file `marinesim export --duration SECONDS` writes).",
    )
    p.add_argument("scenario", type=Path, help="scenario TOML file")
    p.add_argument("--out", type=Path, help="video file (.mp4); its motions go beside it as .csv")
    p.add_argument("--seconds", type=float, default=20.0, help="video length, s of simulated time (default 20)")
    p.add_argument("--fps", type=float, default=30.0, help="frames per second (default 30)")
    p.add_argument("--size", default="1280x720", help="WIDTHxHEIGHT in pixels, even (default 1280x720)")
    p.add_argument("--screenshot", type=Path, metavar="PNG", help="write one frame as a PNG instead of a video")
    p.add_argument("--time", type=float, default=0.0, help="time of the screenshot, s (default 0)")
    p.add_argument("--quiet", action="store_true", help="no progress bar")
    _add_view_options(p)
    p.set_defaults(handler=_run_render)


def _run_render(args: argparse.Namespace) -> int:
    from marinesim.render.offscreen import parse_size, render_video, screenshot
    from marinesim.scenario import load_scenario

    size = parse_size(args.size)
    if (args.out is None) == (args.screenshot is None):
        raise ParameterError("give either --out VIDEO.mp4 or --screenshot SHOT.png")
    scenario = load_scenario(args.scenario)
    if args.screenshot is not None:
        path = screenshot(scenario, args.screenshot, args.time, size, args.camera, args.solver, _render_options(args))
        print(f"wrote the frame at {args.time:g} s ({size[0]}x{size[1]}, camera {args.camera}): {path}")
        return 0
    if args.out.suffix.lower() != ".mp4":
        raise ParameterError(f"--out must be an .mp4 file, got {args.out}")
    with reporting(_bars(args.quiet)):
        result = render_video(scenario, args.out, args.seconds, size, args.fps, args.camera, args.solver,
                              _render_options(args))
    print(f"wrote {result.frames} frames ({args.seconds:g} s at {result.fps:g} frames/s, {size[0]}x{size[1]}, "
          f"solver {'on' if result.solver else 'off'}): {result.video}")
    if result.motions is not None:
        print(f"wrote the motions over the video (as marinesim export): {result.motions}")
    return 0


def _add_rao(commands: argparse._SubParsersAction) -> None:
    p = commands.add_parser(
        "rao", help="summarise an RAO file (ranges, long-wave limits, resonances)",
        description="Read an RAO file (" + "; ".join(f.description for f in formats("rao"))
                    + ") and summarise it: DOFs, "
                    "frequency/heading/speed ranges, the long-wave-limit check per DOF, resonance periods.")
    p.add_argument("file", type=Path, help="RAO file")
    p.add_argument("--json", action="store_true", help="print the summary as one JSON object")
    p.add_argument("--plot", type=Path, metavar="PATH", help="draw amplitude and phase against period (PNG)")
    p.add_argument("--headings", default="180,135,90,45,0",
                   help="relative headings to plot, deg, waves towards (180 = head seas; default 180,135,90,45,0)")
    p.add_argument("--speed-kn", type=float, default=0.0, help="speed for the plot, kn (default 0)")
    p.add_argument("--ulen", type=float, help="WAMIT length scale ULEN, m (default: from the .gdf beside)")
    p.add_argument("--roll-damping-pct", type=float, default=0.0,
                   help="Capytaine: extra linear roll damping, %% of critical (default 0)")
    p.set_defaults(handler=_run_rao)


def _run_rao(args: argparse.Namespace) -> int:
    from marinesim.constants import KNOT
    from marinesim.vessel import read_rao
    from marinesim.vessel.plot import plot_rao
    from marinesim.vessel.summary import format_rao_summary, rao_summary

    headings = _number_list("--headings", args.headings, "degrees")
    table = read_rao(args.file, ulen=args.ulen, roll_damping=require_finite("roll damping", args.roll_damping_pct) / 100)
    report = rao_summary(table)
    print(json.dumps(report) if args.json else format_rao_summary(report))
    if args.plot:
        with atomic_path(args.plot) as temp:
            plot_rao(table, temp, headings, require_finite("speed", args.speed_kn) * KNOT)
        if not args.json:
            print(f"wrote {args.plot}")
    return 0


def _add_export(commands: argparse._SubParsersAction) -> None:
    p = commands.add_parser(
        "export", help="write the vessel's motion time series (CSV + JSON sidecar)",
        description="Compute the vessel's 6-DOF motions, velocities, accelerations, named points and the wave "
                    "elevation for a scenario and write them atomically, with a JSON sidecar beside.")
    p.add_argument("scenario", type=Path, help="scenario TOML file (needs a [vessel] section)")
    p.add_argument("--out", type=Path, required=True, help="output file (e.g. motions.csv)")
    p.add_argument("--duration", type=float, help="run length, s (default: the scenario's)")
    p.add_argument("--dt", type=float, help="time step, s (default: the scenario's)")
    p.add_argument("--seed", type=int, help="random seed (default: the scenario's)")
    p.add_argument("--format", choices=("csv", "parquet"), default="csv", help="table format (default csv)")
    p.add_argument("--quiet", action="store_true", help="no progress bar")
    p.set_defaults(handler=_run_export)


def _run_export(args: argparse.Namespace) -> int:
    from marinesim.scenario import load_scenario
    from marinesim.session.assembly import Assembly
    from marinesim.session.export import export_motions, with_run

    scenario = with_run(load_scenario(args.scenario), args.duration, args.dt, args.seed)
    with reporting(_bars(args.quiet)):
        result = export_motions(Assembly(scenario), args.out, args.format)
    print(f"wrote {result.rows} rows x {len(result.columns)} columns to {result.table} "
          f"(metadata: {result.sidecar})")
    return 0


def _add_sea(commands: argparse._SubParsersAction) -> None:
    p = commands.add_parser(
        "sea", help="synthesise a sea state and report it",
        description="Build a sea state, synthesise it on FFT cascades and report Hs, Tp, Tz and "
        "mean direction from the spectrum and measured on the surface. Directions are compass "
        "degrees the waves come FROM.",
    )
    g = p.add_argument_group("wave system")
    g.add_argument("--spectrum", choices=SPECTRUM_TYPES, default="jonswap", help="spectrum type (default jonswap)")
    g.add_argument("--hs", type=float, default=3.0, help="significant wave height, m (default 3)")
    g.add_argument("--tp", type=float, default=9.0, help="peak period, s (default 9)")
    g.add_argument("--gamma", type=float, help="JONSWAP peak enhancement (default: DNV from Hs, Tp)")
    g.add_argument("--u10", type=float, help="wind speed at 10 m, m/s: JONSWAP from wind and fetch")
    g.add_argument("--fetch-km", type=float, default=100.0, help="fetch, km (with --u10; default 100)")
    g.add_argument("--height", type=float, default=2.0, help="regular wave height, m (default 2)")
    g.add_argument("--period", type=float, default=10.0, help="regular wave period, s (default 10)")
    g.add_argument("--from-deg", type=float, default=0.0, help="compass direction waves come from (default 0)")
    g.add_argument("--spreading", choices=SPREADING_TYPES,
                   help="directional spreading (default cos2s with --spreading-s, else long-crested)")
    g.add_argument("--spreading-s", type=float,
                   help="spreading exponent: s of cos-2s, s at the peak for mitsuyasu, n for cos2n-halfplane")
    s = p.add_argument_group("swell (a second system, JONSWAP)")
    s.add_argument("--swell-hs", type=float, help="swell Hs, m (adds a swell system)")
    s.add_argument("--swell-tp", type=float, default=14.0, help="swell peak period, s (default 14)")
    s.add_argument("--swell-gamma", type=float, help="swell peak enhancement (default: DNV)")
    s.add_argument("--swell-from-deg", type=float, default=0.0, help="compass direction the swell comes from")
    s.add_argument("--swell-spreading-s", type=float, help="cos-2s s of the swell (default long-crested)")
    o = p.add_argument_group("ocean")
    o.add_argument("--depth", type=float, default=math.inf, help="water depth, m (default infinite)")
    o.add_argument("--tiles", type=int, default=4, help="number of FFT cascades (default 4)")
    o.add_argument("--resolution", type=int, default=256, help="samples per tile side N, a power of two (default 256)")
    o.add_argument("--seed", type=int, default=0, help="random seed (default 0)")
    o.add_argument("--deterministic-amplitudes", action="store_true",
                   help="amplitudes sqrt(2 S dk^2) with random phases instead of complex Gaussian")
    o.add_argument("--choppiness", type=float, default=1.0, help="horizontal displacement factor (default 1)")
    o.add_argument("--time", type=float, default=0.0, help="time of the surface measurement, s (default 0)")
    out = p.add_argument_group("output")
    out.add_argument("--json", action="store_true", help="print the summary as one JSON object")
    out.add_argument("--spectrum-csv", type=Path, metavar="PATH", help="write S(w) (omega_rad_s, S_m2s_rad)")
    out.add_argument("--plot", type=Path, metavar="PATH", help="draw the spectrum and a height map (PNG)")
    p.set_defaults(handler=_run_sea)


def sea_from_args(args: argparse.Namespace) -> SeaState:
    """The sea state the ``sea`` options describe."""
    systems = [wave_system(
        args.spectrum, from_deg=args.from_deg, hs=args.hs, tp=args.tp, gamma=args.gamma, u10=args.u10,
        fetch_km=args.fetch_km, height=args.height, period=args.period, spreading=args.spreading,
        spreading_s=args.spreading_s, depth=args.depth,
    )]
    if args.swell_hs is not None:
        try:
            systems.append(wave_system("jonswap", from_deg=args.swell_from_deg, hs=args.swell_hs,
                                       tp=args.swell_tp, gamma=args.swell_gamma,
                                       spreading_s=args.swell_spreading_s))
        except ParameterError as error:
            raise ParameterError(f"swell: {error}") from None
    return SeaState(tuple(systems), depth=args.depth)


def _run_sea(args: argparse.Namespace) -> int:
    require_finite("time", args.time)
    sea = sea_from_args(args)
    ocean = Ocean(sea, tile_count=args.tiles, resolution=args.resolution, seed=args.seed,
                  random_amplitudes=not args.deterministic_amplitudes, choppiness=args.choppiness)
    report = summary(ocean, args.time)
    if args.spectrum_csv:
        _write_spectrum_csv(sea, args.spectrum_csv)
    if args.plot:
        from marinesim.sea.plot import plot_sea

        with atomic_path(args.plot) as temp:
            plot_sea(ocean, temp, args.time)
    if args.json:
        print(json.dumps(report, indent=2))
    else:
        print(_format_summary(report))
    for label, path in (("spectrum", args.spectrum_csv), ("plot", args.plot)):
        if path and not args.json:
            print(f"wrote {label}: {path}")
    return 0


def _write_spectrum_csv(sea: SeaState, path: Path) -> None:
    """The 1-D spectrum of the continuous systems on 0 .. 5 wp (regular waves carry no density)."""
    import pandas as pd

    omega = np.linspace(0.0, 5.0 * 2.0 * math.pi / sea.tp, 1001)
    frame = pd.DataFrame({"omega_rad_s": omega, "S_m2s_rad": sea.density(omega)})
    with atomic_path(path) as temp:
        frame.to_csv(temp, index=False)


def _format_summary(r: dict) -> str:
    lines = [
        f"{'':22}{'Hs [m]':>9}{'Tp [s]':>9}{'Tz [s]':>9}{'from [deg]':>12}",
        f"{'spectrum':22}{r['hs_spectrum_m']:9.2f}{r['tp_spectrum_s']:9.2f}{r['tz_spectrum_s']:9.2f}"
        f"{r['mean_from_deg_spectrum']:12.1f}",
        f"{'surface at t=' + format(r['time_s'], 'g') + ' s':22}{r['hs_surface_m']:9.2f}"
        f"{r['tp_surface_s']:9.2f}{r['tz_surface_s']:9.2f}{r['mean_from_deg_surface']:12.1f}",
        "",
        f"depth: {'infinite' if r['depth_m'] is None else format(r['depth_m'], 'g') + ' m'}, seed {r['seed']}",
        f"{len(r['tiles'])} tiles carry {100 * r['m0_fraction']:.2f}% of m0 in {r['components']:,} components:",
    ]
    for i, t in enumerate(r["tiles"], 1):
        kind = "  (regular wave)" if t["regular_wave"] else ""
        lines.append(
            f"  tile {i}: {t['size_m']:9.1f} m, {t['resolution']}^2, spacing {t['spacing_m']:.3f} m, "
            f"wavelengths {t['wavelengths_m'][0]:.2f} .. {t['wavelengths_m'][1]:.1f} m{kind}"
        )
    return "\n".join(lines)
