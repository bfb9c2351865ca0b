"""What several commands share: strict JSON, progress bars, number lists, hull placement and view options, an output
refused where it is one of the command's inputs, the sea options, and the motions of a vessel from ``--rao`` and
those options instead of a scenario file."""

from __future__ import annotations

import argparse
import contextlib
import math
import sys
from collections.abc import Callable
from pathlib import Path
from typing import TYPE_CHECKING, Any

import marinesim.vessel  # noqa: F401  registers the RAO formats --rao lists
from marinesim.atomic import atomic_path, check_replaceable, note_input, refuse_input, sidecar_path
from marinesim.errors import MarinesimError, ParameterError, require_finite
from marinesim.formats import check_file, formats
from marinesim.progress import Bar, Reporter
from marinesim.render import CAMERAS, CASCADES, HUDS
from marinesim.sea.kinds import APPLIES_TO, SPECTRUM_TYPES, SPREADING_TYPES, refusal

if TYPE_CHECKING:
    from marinesim.scenario import Scenario


def bars(quiet: bool) -> Reporter | None:
    """A progress reporter on stderr (None when ``quiet``): tqdm bars on a terminal, else plain lines
    (:func:`marinesim.progress.lines`: a log gets no carriage returns or escape sequences)."""
    if quiet:
        return None
    if not sys.stderr.isatty():
        from marinesim.progress import lines

        return lines(sys.stderr)
    from tqdm import tqdm

    def bar(name: str, total: int, unit: str) -> Bar:
        return tqdm(total=total, desc=name, unit=unit, file=sys.stderr, mininterval=0.5)
    return bar


def number_list(option: str, text: str, unit: str) -> list[float]:
    """Comma-separated finite numbers, or a ParameterError naming the option."""
    try:
        return [require_finite(option, float(v)) for v in text.split(",")]
    except ValueError:
        raise ParameterError(f"{option} must be comma-separated {unit}, got {text!r}") from None


def add_hull_options(p: argparse.ArgumentParser) -> None:
    g = p.add_argument_group("hull placement (meshes carry no units and often other axes)")
    g.add_argument("--units", default="m", help="mesh length units: m, cm, mm, ft, in (default m)")
    g.add_argument("--scale", type=float, default=1.0, help="geometric scale of a model mesh, e.g. 50 for 1:50")
    g.add_argument("--axes", default="x,y,z", help="mesh axes that become body x (forward), y (port), z (up), "
                                                   "e.g. 'x,-z,y' for a y-up mesh (default x,y,z)")
    g.add_argument("--draft", type=float, help="draft, m: the lowest point goes to z = -draft (default: the "
                                               "mesh's z = 0 is the waterline)")
    g.add_argument("--trim-deg", type=float, default=0.0, help="trim, deg, bow down positive (default 0)")


def hull_from_args(args: argparse.Namespace):
    """The hull the ``hull`` argument and the placement options describe."""
    from marinesim.hull import load_hull

    return load_hull(args.hull, units=args.units, scale=args.scale, axes=args.axes, draft=args.draft,
                     trim_deg=args.trim_deg)


def add_view_options(p: argparse.ArgumentParser) -> None:
    g = p.add_argument_group("view")
    g.add_argument("--camera", default="orbit", metavar="NAME",
                   help=f"{', '.join(CAMERAS)} (default orbit), or one of the scenario's [[cameras]]")
    g.add_argument("--solver", choices=("auto", "on", "off"), default="auto",
                   help="the local wave solver around the hull: auto = on with a GPU, off on a software renderer")
    g.add_argument("--cascades", choices=CASCADES, default="auto",
                   help="where the ocean's waves are synthesised each frame: auto = gpu with a GPU, cpu (pyfftw) "
                        "on a software renderer")
    g.add_argument("--no-wake", action="store_true", help="do not draw the Kelvin wake")
    g.add_argument("--hud", choices=HUDS, default="strip",
                   help="strip (default: a compact strip), panels (text, strip charts, every criterion) or off; "
                        "TAB toggles strip and panels in the window")


def render_options(args: argparse.Namespace):
    """The renderer's options from the view options."""
    from marinesim.render.renderer import RenderOptions

    return RenderOptions(wake=not args.no_wake, cascades=args.cascades, hud=args.hud)


def refuse_overwriting(output: Path | None, option: str, sidecar: bool = False) -> None:
    """Refuse (one line naming ``option``) an ``output`` (with ``sidecar``, its sidecar too) that is one of the
    files the command has read so far, by any path or link: checked once the inputs are read, before the work,
    so that nothing is computed for an output that would be refused (:func:`marinesim.atomic.refuse_input`)."""
    if output is not None and output.name:  # an empty path is refused where it is written
        for path in (output, sidecar_path(output)) if sidecar else (output,):
            refuse_input(path, f"{option} {path}")


SEA_OPTIONS: dict[str, tuple[tuple[str, dict[str, Any]], ...]] = {
    "wave system": (
        ("--spectrum", {"choices": SPECTRUM_TYPES, "default": "jonswap", "help": "spectrum type (default jonswap)"}),
        ("--hs", {"type": float, "help": "significant wave height, m (default 3)"}),
        ("--tp", {"type": float, "help": "peak period, s (default 9)"}),
        ("--gamma", {"type": float, "help": "JONSWAP peak enhancement (default: DNV from Hs, Tp)"}),
        ("--u10", {"type": float, "help": "wind speed at 10 m, m/s: JONSWAP from wind and fetch"}),
        ("--fetch-km", {"type": float, "help": "fetch, km (with --u10; default 100)"}),
        ("--height", {"type": float, "help": "regular wave height, m (default 2)"}),
        ("--period", {"type": float, "help": "regular wave period, s (default 10)"}),
        ("--from-deg", {"type": float, "default": 0.0, "help": "compass direction waves come from (default 0)"}),
        ("--spreading", {"choices": SPREADING_TYPES,
                         "help": "directional spreading (default cos2s with --spreading-s, else long-crested)"}),
        ("--spreading-s", {"type": float, "help": "spreading exponent: s of cos-2s, s at the peak for mitsuyasu, n "
                                                  "for cos2n-halfplane"}),
    ),
    "swell (a second system, JONSWAP)": (
        ("--swell-hs", {"type": float, "help": "swell Hs, m (adds a swell system)"}),
        ("--swell-tp", {"type": float, "default": 14.0, "help": "swell peak period, s (default 14)"}),
        ("--swell-gamma", {"type": float, "help": "swell peak enhancement (default: DNV)"}),
        ("--swell-from-deg", {"type": float, "default": 0.0, "help": "compass direction the swell comes from"}),
        ("--swell-spreading-s", {"type": float, "help": "cos-2s s of the swell (default long-crested)"}),
    ),
    "ocean": (
        ("--depth", {"type": float, "default": math.inf, "help": "water depth, m (default infinite)"}),
        ("--tiles", {"type": int, "default": 4, "help": "number of FFT cascades (default 4)"}),
        ("--resolution", {"type": int, "default": 256,
                          "help": "samples per tile side N, a power of two (default 256)"}),
        ("--choppiness", {"type": float, "default": 1.0, "help": "horizontal displacement factor (default 1)"}),
    ),
}
"""The sea options of ``sea``, and of ``export`` and ``run`` with ``--rao``: group title -> (option, its argparse
keywords, with its default)."""
WAVE_DEFAULTS = {"hs": 3.0, "tp": 9.0, "fetch_km": 100.0, "height": 2.0, "period": 10.0}
"""The wave-system options' defaults, each given only to the kinds of wave system that take it."""
VESSEL_OPTIONS: tuple[tuple[str, dict[str, Any]], ...] = (
    ("--hull", {"type": Path, "metavar": "FILE", "help": "her hull mesh (as [vessel] hull): the Kelvin wake, drawn "
                                                         "and in the run's plots; the motions need none"}),
    ("--speed-kn", {"type": float, "default": 0.0, "help": "her speed, kn (default 0; within the RAO table's speeds "
                                                           "where it has several)"}),
    ("--heading-deg", {"type": float, "default": 0.0, "help": "compass heading her bow points to, deg: 0 north, 90 "
                                                              "east (default 0); equal to --from-deg in head seas"}),
)
"""The vessel's options besides ``--rao``: option -> its argparse keywords, with its default."""


def _dest(option: str) -> str:
    return option.removeprefix("--").replace("-", "_")


def add_sea_options(p: argparse.ArgumentParser, defaults: bool = True) -> dict[str, argparse._ArgumentGroup]:
    """The sea options (:data:`SEA_OPTIONS`) in their groups (title -> group, for a command to add its own). Without
    ``defaults`` an option not given is left out of the arguments (so that a command can tell which were given):
    :func:`option_values` gives every value."""
    groups = {}
    for title, options in SEA_OPTIONS.items():
        groups[title] = p.add_argument_group(title)
        for option, keywords in options:
            groups[title].add_argument(option, **keywords | {"default": keywords.get("default") if defaults
                                                                 else argparse.SUPPRESS})
    return groups


def add_motion_options(p: argparse.ArgumentParser, kept: str) -> None:
    """``--rao`` and what goes with it: the vessel's options, ``--save-scenario`` (``kept``: where the scenario goes
    without it) and the sea options, none given without ``--rao`` (:func:`motion_scenario`)."""
    g = p.add_argument_group("motions without a scenario file: --rao FILE instead of SCENARIO, with the sea "
                             "options below")
    g.add_argument("--rao", type=Path, metavar="FILE",
                   help="the vessel's RAO file (as [vessel] rao: " + ", ".join(f.name for f in formats("rao"))
                        + "): her motions in the sea the sea options describe")
    for option, keywords in VESSEL_OPTIONS:
        g.add_argument(option, **keywords | {"default": argparse.SUPPRESS})
    g.add_argument("--save-scenario", type=Path, metavar="FILE", default=argparse.SUPPRESS,
                   help="where the scenario these options make goes (TOML, paths relative to its folder): the very "
                        f"one run, to edit or run again (default {kept})")
    add_sea_options(p, defaults=False)


def option_values(args: argparse.Namespace) -> dict[str, Any]:
    """Every sea and vessel option (by its ``args`` name): as given, else its default (None where it has none)."""
    options = [*(o for group in SEA_OPTIONS.values() for o in group), *VESSEL_OPTIONS]
    return {_dest(option): getattr(args, _dest(option), keywords.get("default")) for option, keywords in options}


def wave_systems(args: argparse.Namespace) -> list[dict[str, Any]]:
    """The wave systems the sea options describe, as :func:`~marinesim.sea.build.wave_system`'s arguments (``kind``,
    ``from_deg``, the parameters given, and :data:`WAVE_DEFAULTS` where the kind takes them): the wave system, then
    with ``--swell-hs`` the swell."""
    values = option_values(args)
    kind = values["spectrum"]
    given = {name: values[name] for name in APPLIES_TO if values.get(name) is not None}
    for name, value in WAVE_DEFAULTS.items():
        if name not in given and refusal(kind, name, given) is None:
            given[name] = value
    systems = [{"kind": kind, "from_deg": values["from_deg"], **given}]
    if values["swell_hs"] is not None:
        swell = {name: values[f"swell_{name}"] for name in ("hs", "tp", "gamma", "spreading_s")}
        systems.append({"kind": "jonswap", "from_deg": values["swell_from_deg"],
                        **{name: value for name, value in swell.items() if value is not None}})
    return systems


def motion_scenario(args: argparse.Namespace, kept: Callable[[Path], Path], default: Path | None = None,
                    tables: tuple[Path, ...] = (), make_folder: bool = False) -> Scenario:
    """The scenario of ``export`` or ``run``: the file ``args.scenario`` (else ``default``) with the run's options
    (``--duration``, ``--dt``, ``--seed``), or, with ``--rao``, the one the options describe. That one is made as
    TOML text once, loaded as a file is (:mod:`marinesim.scenario.from_options`) and written, before anything runs,
    to ``--save-scenario`` (else ``kept(rao)``, its folder made if missing with ``make_folder``): the run's sidecars
    and logs name it. Refused (one line): ``--rao`` with a scenario file; the other motion options without ``--rao``; no
    scenario at all; a scenario file that would be written over one of the command's inputs, or over one of the
    ``tables`` it writes or their sidecars."""
    from marinesim.scenario import load_scenario, with_run

    run = {"duration": args.duration, "dt": args.dt, "seed": args.seed}
    if args.rao is None:
        given = [f"--{name.replace('_', '-')}" for name in (*option_values(args), "save_scenario") if name in args]
        if given:
            raise ParameterError(f"{', '.join(given)} appl{'y' if len(given) > 1 else 'ies'} only with --rao FILE"
                                 + (f", not with a scenario file ({args.scenario}: it gives its own sea and vessel)"
                                    if args.scenario is not None else ""))
        if args.scenario is None and default is None:
            raise ParameterError("give a scenario file (SCENARIO), or the vessel's RAO file and the sea as options "
                                 "(--rao FILE --hs M --tp S ...)")
        return with_run(load_scenario(args.scenario or default), **run)
    if args.scenario is not None:
        raise ParameterError(f"give a scenario file ({args.scenario}) or --rao {args.rao}, not both")
    saved = "save_scenario" in args
    return _options_scenario(args, args.save_scenario if saved else kept(args.rao), run, tables,
                             make_folder and not saved)


def _options_scenario(args: argparse.Namespace, path: Path, run: dict[str, float | int | None],
                      tables: tuple[Path, ...], make_folder: bool) -> Scenario:
    """The scenario of the options, written to ``path`` (see :func:`motion_scenario`)."""
    from marinesim.scenario.from_options import load_text, scenario_text, sea_table

    values = option_values(args)
    check_file(args.rao, "RAO file")  # named as given, before the scenario names it from its own folder
    if values["hull"] is not None:
        check_file(values["hull"], "hull mesh")
    option = "--save-scenario" if "save_scenario" in args else "the scenario of the options"
    if not path.name:
        raise ParameterError(f"{option}: {str(path)!r} names no file")
    for output in (file for table in tables for file in (table, sidecar_path(table))):
        check_replaceable(output)
        if path.resolve() == output.resolve():
            raise ParameterError(f"{option} {path} is an output of the command too: choose another path")
    sections = {
        "ocean": {"depth_m": None if values["depth"] == math.inf else values["depth"],  # deep water: no depth_m
                  **{key: values[key] for key in ("tiles", "resolution", "choppiness")}},
        "sea": [sea_table(**system) for system in wave_systems(args)],
        "vessel": {"rao": args.rao, "hull": values["hull"], "speed_kn": values["speed_kn"],
                   "heading_deg": values["heading_deg"]},
        "run": {"duration_s": run["duration"], "dt_s": run["dt"], "seed": run["seed"]},
    }
    made = [folder for folder in (path.parent, *path.parent.parents) if not folder.exists()]
    if made and not make_folder:
        raise MarinesimError(f"cannot write {path}: folder {path.parent} does not exist")
    path.parent.mkdir(parents=True, exist_ok=True)
    try:
        text = scenario_text(sections, path.parent)
        scenario = load_text(text, path)
        refuse_overwriting(path, option)
        with atomic_path(path) as temp:
            temp.write_text(text, encoding="utf-8")
    except BaseException:
        for folder in made:  # refused before anything was written in them
            with contextlib.suppress(OSError):
                folder.rmdir()
        raise
    note_input(path)  # the run reads it: no output of the command may be written over it
    return scenario


def next_log(name: str, folder: Path = Path("sessions")) -> Path:
    """``folder/<name>-NNN.jsonl`` with the first number not taken: no session overwrites another."""
    taken = {p.name for p in folder.glob(f"{name}-*.jsonl")} if folder.is_dir() else set()
    number = next(n for n in range(1, len(taken) + 2) if f"{name}-{n:03d}.jsonl" not in taken)
    return folder / f"{name}-{number:03d}.jsonl"


def add_stream_options(p: argparse.ArgumentParser) -> None:
    """``--nmea`` and ``--dis``: own-ship's state out to real equipment, each second."""
    p.add_argument("--nmea", metavar="udp://HOST:PORT", help="stream NMEA 0183 (GGA, RMC, VTG, HDT, ROT, RSA, "
                                                           "PASHR) at 1 Hz to this UDP address (an ECDIS, a helideck "
                                                           "monitoring system); needs [environment] latitude_deg, "
                                                           "longitude_deg")
    p.add_argument("--dis", metavar="udp://HOST:PORT", help="send IEEE 1278.1 DIS Entity State PDUs for own-ship at "
                                                          "1 Hz to this UDP address")


def open_streams(args: argparse.Namespace, scenario):
    """The NMEA and DIS streams ``--nmea`` and ``--dis`` ask for (None: neither), placed at the scenario's
    ``[environment]`` position, their clock its ``time_utc`` (or midnight UTC, 1 January 2000)."""
    if not (args.nmea or args.dis):
        return None
    from datetime import datetime, timezone

    from marinesim.errors import ScenarioError
    from marinesim.net.geo import Origin
    from marinesim.net.streams import Streams

    environment = scenario.environment
    if environment.latitude_deg is None or environment.longitude_deg is None:
        raise ScenarioError(f"{scenario.path}: --nmea and --dis need where the exercise is: [environment] "
                            "latitude_deg and longitude_deg")
    start = environment.time_utc or datetime(2000, 1, 1, tzinfo=timezone.utc)
    return Streams(args.nmea, args.dis, Origin(environment.latitude_deg, environment.longitude_deg), start)
