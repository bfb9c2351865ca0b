"""``marinesim sea``: synthesise a sea state on the FFT cascades and report it."""

from __future__ import annotations

import argparse
import math
from pathlib import Path

from marinesim.cli.common import json_text
from marinesim.errors import ParameterError
from marinesim.sea.kinds import APPLIES_TO, SPECTRUM_TYPES, SPREADING_TYPES, refusal

DEFAULTS = {"hs": 3.0, "tp": 9.0, "fetch_km": 100.0, "height": 2.0, "period": 10.0}
"""The wave-system options' defaults, each given only to the kinds of wave system that take it."""


NEEDS = ("marinesim.sea", "marinesim.sea.build", "marinesim.sea.summary")
"""The modules the command loads before it starts (Ctrl-C is held until they are in)."""

def add(commands: argparse._SubParsersAction) -> None:
    p = commands.add_parser(
        "sea", help="synthesise a sea state and report it",
        description="Build a sea state, synthesise it on FFT cascades and report Hs, Tp, Tz and "
        "mean direction from the spectrum and measured on the surface. Directions are compass "
        "degrees the waves come FROM.",
    )
    g = p.add_argument_group("wave system")
    g.add_argument("--spectrum", choices=SPECTRUM_TYPES, default="jonswap", help="spectrum type (default jonswap)")
    g.add_argument("--hs", type=float, help="significant wave height, m (default 3)")
    g.add_argument("--tp", type=float, help="peak period, s (default 9)")
    g.add_argument("--gamma", type=float, help="JONSWAP peak enhancement (default: DNV from Hs, Tp)")
    g.add_argument("--u10", type=float, help="wind speed at 10 m, m/s: JONSWAP from wind and fetch")
    g.add_argument("--fetch-km", type=float, help="fetch, km (with --u10; default 100)")
    g.add_argument("--height", type=float, help="regular wave height, m (default 2)")
    g.add_argument("--period", type=float, help="regular wave period, s (default 10)")
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
    p.set_defaults(handler=handle)


def sea_from_args(args: argparse.Namespace):
    """The :class:`~marinesim.sea.SeaState` the ``sea`` options describe."""
    from marinesim.sea import SeaState
    from marinesim.sea.build import wave_system

    given = {name: getattr(args, name) for name in APPLIES_TO if getattr(args, name, None) is not None}
    for name, value in DEFAULTS.items():
        if name not in given and refusal(args.spectrum, name, given) is None:
            given[name] = value
    systems = [wave_system(args.spectrum, from_deg=args.from_deg, depth=args.depth, **given)]
    if args.swell_hs is not None:
        try:
            systems.append(wave_system("jonswap", from_deg=args.swell_from_deg, hs=args.swell_hs,
                                       tp=args.swell_tp, gamma=args.swell_gamma,
                                       spreading_s=args.swell_spreading_s))
        except ParameterError as error:
            raise ParameterError(f"swell: {error}") from None
    return SeaState(tuple(systems), depth=args.depth)


def handle(args: argparse.Namespace) -> int:
    from marinesim.atomic import atomic_path
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
        print(json_text(report, indent=2))
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
