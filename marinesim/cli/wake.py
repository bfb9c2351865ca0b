"""``marinesim wake``: the Kelvin wake and wave resistance of a hull at one or more speeds."""

from __future__ import annotations

import argparse
from pathlib import Path

import marinesim.hull  # noqa: F401  registers the mesh formats listed below
from marinesim.cli.common import add_hull_options, bars, hull_from_args, number_list, refuse_overwriting
from marinesim.errors import ParameterError
from marinesim.formats import extensions


def add(commands: argparse._SubParsersAction) -> None:
    p = commands.add_parser(
        "wake", help="compute the Kelvin wake and wave resistance of a hull",
        description="Integrate Tuck's amplitude function A(theta) exactly over the wetted triangles of the hull "
                    f"({', '.join(extensions('mesh'))}), "
                    "give Michell's wave resistance, and compute the far-field wake on a grid in the vessel "
                    "frame. Results are cached; --out writes the field, its grid and the parameters (.npz).")
    p.add_argument("hull", type=Path, help="hull mesh file")
    p.add_argument("--speed-kn", required=True,
                   help="speed, kn; several comma-separated speeds are precomputed in one call")
    add_hull_options(p)
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
    p.set_defaults(handler=handle)


def handle(args: argparse.Namespace) -> int:
    import time

    from marinesim.atomic import atomic_path, strict_json
    from marinesim.constants import KNOT
    from marinesim.hull import hydrostatics
    from marinesim.progress import reporting
    from marinesim.wake.cache import cached_wake
    from marinesim.wake.compute import MAX_SPEEDS, WakeGrid, compute_wake, thin_ship_note
    from marinesim.wake.plot import plot_wake

    speeds = list(dict.fromkeys(number_list("--speed-kn", args.speed_kn, "knots")))  # a repeated speed: once
    if len(speeds) > MAX_SPEEDS:
        raise ParameterError(f"--speed-kn gives {len(speeds)} different speeds, more than {MAX_SPEEDS} (one a knot up "
                             "to 40 kn): give fewer")
    if any(v <= 0 for v in speeds):
        raise ParameterError(f"--speed-kn must be > 0 (a hull at rest makes no wake), got {args.speed_kn}")
    for path in (args.out, args.plot):
        if path is not None and not path.resolve().parent.is_dir():
            raise ParameterError(f"cannot write {path}: folder {path.resolve().parent} does not exist")
    grid = WakeGrid(args.nx, args.ny, args.spacing)
    hull = hull_from_args(args)
    for flag, option, suffix in ((args.out, "--out", ".npz"), (args.plot, "--plot", ".png")):
        for speed_kn in speeds if flag else ():
            refuse_overwriting(_named(flag, speed_kn, len(speeds) > 1, suffix), option)
    thin = thin_ship_note(hydrostatics(hull))  # from the hull, not the wake: a cached wake may predate the note
    reports = []
    for speed_kn in speeds:
        started = time.perf_counter()
        with reporting(bars(args.quiet)):
            if args.no_cache:
                wake, cached = compute_wake(hull, speed_kn * KNOT, grid), False
            else:
                wake, cached = cached_wake(hull, speed_kn * KNOT, grid)
        report = {key: wake.info[key] for key in ("speed_m_s", "speed_kn", "froude", "wave_resistance_N",
                                                  "wave_resistance_coefficient", "kelvin_half_angle_deg",
                                                  "transverse_wavelength_m", "measured_transverse_wavelength_m")}
        report |= {key: wake.info[key] for key in ("validity_note", "grid_note", "measurement_note") if key in wake.info}
        if thin:
            report["thin_ship_note"] = thin
        report |= {"seconds": time.perf_counter() - started, "cached": cached,
                   "seconds_computing": sum(wake.timings.values())}  # 0 from the cache; never in a file
        for flag, suffix in ((args.out, ".npz"), (args.plot, ".png")):
            if flag:
                path = _named(flag, speed_kn, len(speeds) > 1, suffix)
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
        print(strict_json(reports[0] if len(reports) == 1 else reports))
    return 0


def _named(flag: Path, speed_kn: float, many: bool, suffix: str) -> Path:
    """The file ``flag`` names for the wake at ``speed_kn``: itself, or with several speeds ``NAME_<speed>kn``."""
    return flag.with_name(f"{flag.stem}_{speed_kn:g}kn{flag.suffix or suffix}") if many else flag


def _format_wake(r: dict, notes: tuple[str, ...]) -> str:
    angle = r["kelvin_half_angle_deg"]
    lines = [f"{r['speed_kn']:.3g} kn ({r['speed_m_s']:.3f} m/s), Fn {r['froude']:.3f}: wave resistance "
             f"{r['wave_resistance_N'] / 1e3:,.1f} kN (Cw {r['wave_resistance_coefficient']:.3e})",
             "  Kelvin half-angle measured on the field: "
             + (f"{angle:.2f} deg (theory 19.47)" if angle is not None else "not measured (see the note)"),
             f"  transverse wavelength {r['transverse_wavelength_m']:.2f} m (2 pi U^2 / g)",
             f"  {r['seconds']:.2f} s" + (" (from the cache)" if r["cached"] else "")]
    lines += [f"  wrote {r[key]}" for key in ("out", "plot") if key in r]
    lines += [f"note: {r[key]}" for key in ("thin_ship_note", "validity_note", "grid_note", "measurement_note")
              if r.get(key)]
    lines += [f"note: {note}" for note in notes]
    return "\n".join(lines)
