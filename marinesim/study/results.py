"""What an operability study writes into its folder, as one unit: ``operability.nc`` (an xarray Dataset in
NetCDF, CF-style names and units), ``summary.csv`` (limiting Hs per heading and Tp, with the governing
criterion) and three pictures (``operability_polar.png``, ``limiting_hs.png``, ``governing.png``). The same
study gives the same bytes in every file."""

from __future__ import annotations

import io
from pathlib import Path

import numpy as np

from marinesim.atomic import AtomicFile, commit_together, output_lock, writing
from marinesim.errors import MarinesimError
from marinesim.study import plots
from marinesim.study.operability import Operability
from marinesim.study.scatter import Scatter

FILES = ("operability.nc", "summary.csv", "operability_polar.png", "limiting_hs.png", "governing.png")


def dataset(result: Operability, value1: np.ndarray, names: list[str], units: list[str], limits: np.ndarray,
            scatter: Scatter, cell_tp: np.ndarray, attrs: dict):
    """The study as an :class:`xarray.Dataset`: ``limiting_hs_m`` (heading, tp_s, criterion),
    ``limiting_hs_m_all`` and ``governing_criterion`` (heading, tp_s), ``operability_pct`` (heading),
    ``value_at_hs_1m`` (heading, tp_s, criterion), the scatter's cells and ``workable`` (cell, heading);
    ``attrs`` (inputs, hashes, settings) become global attributes."""
    import xarray as xr

    coords = {"heading_deg": ("heading_deg", result.headings_deg,
                              {"long_name": "relative wave heading (0 following, 90 from starboard, 180 head seas)",
                               "units": "degree"}),
              "tp_s": ("tp_s", result.tp, {"long_name": "spectral peak period", "units": "s"}),
              "criterion": ("criterion", np.array(names, dtype=object), {"long_name": "criterion name"}),
              "cell": ("cell", np.arange(scatter.hs.size), {"long_name": "scatter diagram cell"})}
    governing_flags = {"long_name": "index of the criterion that sets the limiting Hs",
                       "flag_values": np.arange(len(names), dtype=np.int32),
                       "flag_meanings": " ".join(n.replace(" ", "_") for n in names)}
    data = {
        "limiting_hs_m": (("heading_deg", "tp_s", "criterion"), result.limiting_hs,
                          {"long_name": "largest significant wave height within the criterion's limit", "units": "m"}),
        "limiting_hs_m_all": (("heading_deg", "tp_s"), result.limiting_hs_all,
                              {"long_name": "largest significant wave height within every limit", "units": "m"}),
        "governing_criterion": (("heading_deg", "tp_s"), result.governing.astype(np.int32), governing_flags),
        "operability_pct": (("heading_deg",), result.operability_pct,
                            {"long_name": "probability of the workable sea states at the heading", "units": "%"}),
        "value_at_hs_1m": (("heading_deg", "tp_s", "criterion"), np.moveaxis(value1, 1, 0),
                           {"long_name": "criterion value in a sea state of Hs 1 m", "units": "criterion's unit"}),
        "limit": (("criterion",), np.asarray(limits, float), {"long_name": "criterion limit"}),
        "unit": (("criterion",), np.array(units, dtype=object), {"long_name": "unit of the criterion and its limit"}),
        "cell_hs_m": (("cell",), scatter.hs, {"long_name": "significant wave height of the cell", "units": "m"}),
        "cell_tp_s": (("cell",), cell_tp, {"long_name": "peak period of the cell", "units": "s"}),
        "cell_probability": (("cell",), scatter.probability, {"long_name": "probability of the cell", "units": "1"}),
        "workable": (("cell", "heading_deg"), result.workable.astype(np.int8),
                     {"long_name": "1 where the cell's sea state is within every limit at the heading"}),
    }
    base = {"title": "marinesim operability study", "Conventions": "CF-1.8",
            "overall_pct": result.overall_pct, "best_heading_deg": result.best_heading_deg}
    return xr.Dataset(data, coords, attrs=base | attrs)


def summary_csv(result: Operability, names: list[str]) -> str:
    """One row per (heading, Tp): limiting Hs (m, ``inf`` where nothing limits), the governing criterion,
    each criterion's limiting Hs, and the heading's operability (%)."""
    header = ["heading_deg", "tp_s", "limiting_hs_m", "governing", *[f"limiting_hs_m[{n}]" for n in names],
              "operability_pct"]
    lines = [",".join(header)]
    for i, heading in enumerate(result.headings_deg):
        for j, tp in enumerate(result.tp):
            per = [f"{v:.4g}" for v in result.limiting_hs[i, j]]
            lines.append(",".join([f"{heading:g}", f"{tp:g}", f"{result.limiting_hs_all[i, j]:.4g}",
                                   _quoted(names[result.governing[i, j]]), *per,
                                   f"{result.operability_pct[i]:.3f}"]))
    return "\n".join(lines) + "\n"


def pictures(result: Operability, scatter: Scatter, cell_tp: np.ndarray, names: list[str],
             title: str) -> dict[str, bytes]:
    """The study's three pictures, file name -> PNG bytes."""
    return {"operability_polar.png": plots.polar_plot(result, title),
            "limiting_hs.png": plots.limiting_hs_plot(result, scatter, cell_tp, title),
            "governing.png": plots.governing_plot(result, names, title)}


def write_study(out_dir: Path, data, summary: str, pictures: dict[str, bytes]) -> list[Path]:
    """Write the Dataset ``data``, the ``summary`` CSV and ``pictures`` (file name -> PNG) into ``out_dir``
    (made if absent) as one unit: an interrupted write leaves the previous study's files, all of them."""
    out_dir = Path(out_dir)
    if out_dir.exists() and not out_dir.is_dir():
        raise MarinesimError(f"cannot write the study into {out_dir}: it is not a folder")
    out_dir.mkdir(parents=True, exist_ok=True)
    contents = {"operability.nc": _netcdf(data), "summary.csv": summary.encode()} | pictures
    with output_lock(out_dir / "operability.nc", [out_dir / name for name in contents]):
        files = [AtomicFile(out_dir / name) for name in contents]
        with writing(*files):
            for file, payload in zip(files, contents.values()):
                file.temp.write_bytes(payload)
            commit_together(files)
    return [file.path for file in files]


def _netcdf(data) -> bytes:
    """``data`` as NetCDF-3 bytes (scipy's writer: no HDF5 library, no time stamp, the same bytes each time)."""
    buffer = io.BytesIO()
    data.to_netcdf(buffer, engine="scipy")
    return buffer.getvalue()


def _quoted(text: str) -> str:
    return f'"{text}"' if any(c in text for c in ',"\n') else text
