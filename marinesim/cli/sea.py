"""``marinesim sea``: synthesise a sea state on the FFT cascades and report it."""

from __future__ import annotations

import argparse
import math
from pathlib import Path

from marinesim.cli.common import add_sea_options, wave_systems
from marinesim.errors import ParameterError


def add(commands: argparse._SubParsersAction) -> None:
    p = commands.add_parser(
        "sea", help="synthesise a sea state and report it",
        description="Build a sea state, synthesise it on FFT cascades and report Hs, Tp, Tz and "
        "mean direction from the spectrum and measured on the surface. Directions are compass "
        "degrees the waves come FROM.",
    )
    o = add_sea_options(p)["ocean"]
    o.add_argument("--seed", type=int, default=0, help="random seed (default 0)")
    o.add_argument("--deterministic-amplitudes", action="store_true",
                   help="amplitudes sqrt(2 S dk^2) with random phases instead of complex Gaussian")
    o.add_argument("--time", type=float, default=0.0, help="time of the surface measurement, s (default 0)")
    out = p.add_argument_group("output")
    out.add_argument("--json", action="store_true", help="print the summary as one JSON object")
    out.add_argument("--spectrum-csv", type=Path, metavar="PATH", help="write S(w) (omega_rad_s, S_m2s_rad)")
    out.add_argument("--plot", type=Path, metavar="PATH", help="draw the spectrum and a height map (PNG)")
    p.set_defaults(handler=handle)


def sea_from_args(args: argparse.Namespace):
    """The :class:`~marinesim.sea.SeaState` the ``sea`` options describe."""
    from marinesim.sea import SeaState
    from marinesim.sea.build import wave_system

    wave, *swell = wave_systems(args)
    systems = [wave_system(depth=args.depth, **wave)]
    for system in swell:
        try:
            systems.append(wave_system(**system))
        except ParameterError as error:
            raise ParameterError(f"swell: {error}") from None
    return SeaState(tuple(systems), depth=args.depth)


def handle(args: argparse.Namespace) -> int:
    from marinesim.atomic import atomic_path, strict_json
    from marinesim.sea import Ocean
    from marinesim.sea.summary import summary

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
        print(strict_json(report, indent=2))
    else:
        print(_format_summary(report))
    for label, path in (("spectrum", args.spectrum_csv), ("plot", args.plot)):
        if path and not args.json:
            print(f"wrote {label}: {path}")
    return 0


def _write_spectrum_csv(sea, path: Path) -> None:
    """The 1-D spectrum of the continuous systems of ``sea`` on 0 .. 5 wp (regular waves carry no density)."""
    import numpy as np
    import pandas as pd

    from marinesim.atomic import atomic_path

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
