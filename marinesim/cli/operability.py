"""``marinesim operability``: limiting sea states and operability of a scenario's operation over a scatter
diagram, in the frequency domain, optionally checked in the time domain on Dask."""

from __future__ import annotations

import argparse
import math
import sys
from pathlib import Path

from marinesim.atomic import strict_json
from marinesim.cli.common import bars, number_list
from marinesim.errors import ParameterError


def add(commands: argparse._SubParsersAction) -> None:
    p = commands.add_parser(
        "operability", help="limiting Hs and operability over a wave scatter diagram",
        description="For every peak period of the scatter diagram and every heading, each criterion's value in "
                    "a sea of Hs 1 m from the response spectra, the limiting Hs (limit / that value) and the "
                    "criterion that governs it; the operability per heading is the probability of the sea "
                    "states below the limit. Writes DIR/operability.nc, DIR/summary.csv and three pictures.")
    p.add_argument("scenario", type=Path, help="scenario TOML: the vessel, its [[criteria]] and the sea's shape")
    p.add_argument("--scatter", type=Path, required=True,
                   help="scatter CSV (hs_m, tp_s or tz_s, probability or count); configs/scatter holds three")
    p.add_argument("--out", type=Path, required=True, help="folder for the study's files")
    p.add_argument("--headings", default="0:360:15",
                   help="relative wave headings, deg (0 following, 90 from starboard, 180 head seas): "
                        "START:STOP:STEP (STOP excluded) or a comma list (default 0:360:15)")
    p.add_argument("--duration-h", type=float, default=3.0, help="exposure of one sea state, h (default 3)")
    alpha = p.add_mutually_exclusive_group()
    alpha.add_argument("--alpha", type=float, default=1.0,
                       help="DNV-ST-N001 alpha factor: every limiting Hs times it (forecast uncertainty; default 1)")
    alpha.add_argument("--planned-period-h", type=float, metavar="T_POP",
                       help="the operation's planned period T_POP, h (without contingency; at most 72 h in the "
                            "base case): alpha from the alpha table's row for T_POP at each limiting Hs")
    p.add_argument("--alpha-table", type=Path,
                   help="alpha table CSV for --planned-period-h (default configs/alpha/dnv_base_case.csv, the "
                        "base case of DNV-OS-H101 Table 4-1 / DNV-ST-N001 Table 2-1)")
    p.add_argument("--time-domain", type=int, metavar="SEEDS",
                   help="also simulate SEEDS records of every selected cell at every heading (Dask)")
    p.add_argument("--cells", help="scatter cells (0-based rows) for --time-domain, comma list (default all)")
    p.add_argument("--scheduler", help="an existing Dask scheduler, tcp://host:port (default: a LocalCluster)")
    p.add_argument("--workers", type=int, help="LocalCluster worker processes (default: the CPUs)")
    p.add_argument("--json", action="store_true", help="print the operability as JSON")
    p.add_argument("--quiet", action="store_true", help="no progress bar")
    p.set_defaults(handler=handle)


def headings(text: str) -> list[float]:
    """``"0:360:15"`` or ``"90,180"`` as degrees; ParameterError otherwise."""
    if ":" in text:
        try:
            start, stop, step = (float(part) for part in text.split(":"))
        except ValueError:
            raise ParameterError(f"--headings must be START:STOP:STEP or a comma list, got {text!r}") from None
        if not step > 0 or not stop > start or (stop - start) / step > 360:
            raise ParameterError(f"--headings {text!r}: STEP must be > 0, STOP > START, at most 360 headings")
        count = math.ceil((stop - start) / step - 1e-9)
        return [start + i * step for i in range(count)]
    return list(number_list("--headings", text, "degrees"))


def handle(args: argparse.Namespace) -> int:
    import numpy as np

    from marinesim.progress import reporting
    from marinesim.scenario import load_scenario
    from marinesim.study import run
    from marinesim.study.alpha import default_table, read_alpha_table

    study = run.prepare(load_scenario(args.scenario), args.scatter, np.array(headings(args.headings)),
                        args.duration_h)
    log = (lambda line: print(line, file=sys.stderr)) if args.json else print
    alpha_table = None
    if args.planned_period_h is not None:
        alpha_table = read_alpha_table(args.alpha_table or default_table())
    elif args.alpha_table is not None:
        raise ParameterError("--alpha-table needs --planned-period-h (the operation's T_POP, h)")
    estimates, result = run.evaluate(study, args.alpha, alpha_table, args.planned_period_h)
    attrs = run.attributes(study, args.alpha, alpha_table, args.planned_period_h)
    extra = None
    if args.time_domain is not None:
        cells = (np.arange(study.scatter.hs.size) if args.cells is None
                 else np.array(number_list("--cells", args.cells, "cell indices"), int))
        with reporting(bars(args.quiet)):
            extra = run.time_domain(study, estimates, args.time_domain, cells, args.out / "time_domain.zarr",
                                    args.scheduler, args.workers)
    written = run.write(study, estimates, result, args.out, attrs, extra)
    summary = {"operability_pct": {f"{h:g}": round(float(p), 3) for h, p in
                                   zip(result.headings_deg, result.operability_pct)},
               "best_heading_deg": result.best_heading_deg, "overall_pct": round(result.overall_pct, 3),
               "overall": "the best heading in each sea state"}
    if args.json:
        print(strict_json(summary, indent=2))
    else:
        for line in table(study, result):
            log(line)
        if alpha_table is not None:
            log(f"limits are forecast limits: alpha of T_POP {args.planned_period_h:g} h at each limiting Hs from "
                f"{alpha_table.source}")
        elif args.alpha != 1.0:
            log(f"limits are forecast limits: alpha {args.alpha:g}")
        if extra is not None:
            for line in check_table(study, extra):
                log(line)
    log(f"wrote {', '.join(p.name for p in written)} in {args.out}")
    return 0


def table(study, result) -> list[str]:
    """Operability per heading with the governing criterion where it most often limits."""
    import numpy as np

    lines = [f"{study.scenario.name}: {study.scatter.hs.size} sea states of {study.scatter.source}, "
             f"{result.headings_deg.size} headings",
             f"{'heading':>8}  {'operability':>11}  governing (most of the lost probability)"]
    for i, heading in enumerate(result.headings_deg):
        lost = ~result.workable[:, i]
        column = np.searchsorted(study.tp, study.cell_tp)
        governing = result.governing[i, column]
        weights = np.bincount(governing[lost], weights=study.scatter.probability[lost], minlength=len(study.names))
        name = study.names[int(np.argmax(weights))] if lost.any() else "-"
        lines.append(f"{heading:7g}°  {result.operability_pct[i]:10.1f}%  {name}")
    lines.append(f"overall {result.overall_pct:.1f} % with the best heading in each sea state; best single heading "
                 f"{result.best_heading_deg:g}°")
    return lines


def check_table(study, extra: dict) -> list[str]:
    """The time-domain check beside the spectral values (first heading of each checked cell, every criterion)."""
    mean, error, spectral = (extra[k][1] for k in ("time_domain_mean", "time_domain_stderr", "spectral_value"))
    cells = extra["check_cell_index"][1]
    lines = ["time-domain check (mean over seeds +- standard error | spectral):"]
    for k, cell in enumerate(cells):
        for i, heading in enumerate(study.headings_deg):
            parts = [f"{name} {mean[k, i, c]:.3g}+-{error[k, i, c]:.2g} | {spectral[k, i, c]:.3g}"
                     for c, name in enumerate(study.names)]
            lines.append(f"  cell {cell} (Hs {study.scatter.hs[cell]:g} m, Tp {study.cell_tp[cell]:.3g} s) "
                         f"{heading:g}°: " + "; ".join(parts))
    return lines
