"""The vessel: RAO tables from real programs and the 6-DOF response they give in the ocean.

``read_rao`` reads WAMIT, VERES, Capytaine and marinesim's own tables into :class:`RaoTable`
(internal convention, docs/CONVENTIONS.md); :class:`Response` turns the ocean's wave components
and a :class:`Track` into motions of the vessel and of points on board.

Importing the package registers its file formats (RAO and mean drift tables) in :mod:`marinesim.formats`
and nothing more: the names below are imported on first use, so that listing the formats (``marinesim
--help``) imports neither numpy nor a reader.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from marinesim.formats import Format, register

if TYPE_CHECKING:
    from marinesim.vessel.rao import DOFS, RaoTable, long_wave_limit, make_table
    from marinesim.vessel.read import read_rao
    from marinesim.vessel.response import Response, Track, motion_columns

__all__ = ["DOFS", "RaoTable", "Response", "Track", "long_wave_limit", "make_table", "motion_columns",
           "read_rao"]


def __getattr__(name: str) -> object:
    """The names of ``__all__``, each imported from its module on first use."""
    if name in ("DOFS", "RaoTable", "long_wave_limit", "make_table"):
        from marinesim.vessel import rao as module
    elif name == "read_rao":
        from marinesim.vessel import read as module
    elif name in ("Response", "Track", "motion_columns"):
        from marinesim.vessel import response as module
    else:
        raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
    value = globals()[name] = getattr(module, name)
    return value


register(Format("wamit", "rao", "WAMIT .4 motion RAOs (numeric output)", (".4",),
                "marinesim.vessel.wamit:read_wamit", "marinesim.vessel.wamit:sniff", options=("ulen", "body")))
register(Format("veres", "rao", "VERES/ShipX .re1 motion transfer functions", (".re1",),
                "marinesim.vessel.veres:read_veres", "marinesim.vessel.veres:sniff"))
register(Format("capytaine", "rao", "Capytaine NetCDF dataset (.nc) with hydrodynamic coefficients", (".nc",),
                "marinesim.vessel.capytaine:read_capytaine", "marinesim.vessel.capytaine:sniff",
                options=("roll_damping", "body", "rigid_body")))
register(Format("native", "rao", "marinesim table (.csv, .txt, .rao; see marinesim/vessel/native.py)",
                (".csv", ".txt", ".rao"), "marinesim.vessel.native:read_native", "marinesim.vessel.native:sniff"))
register(Format("wamit-forces", "rao", "WAMIT .1, .3, .hst and .frc side by side: RAOs solved from forces and mass",
                (".3", ".1", ".hst", ".frc"), "marinesim.vessel.wamit_forces:read_wamit_forces",
                "marinesim.vessel.wamit_forces:sniff", options=("ulen", "rigid_body", "body")))
register(Format("wamit-out", "rao", "WAMIT report (.out, or any name: found by its banner, as other programs "
                "write .out too): its motions, or RAOs solved from its forces and the scenario's mass", (),
                "marinesim.vessel.wamit_out:read_wamit_out",
                "marinesim.vessel.wamit_out:sniff", options=("ulen", "rigid_body")))
register(Format("hydrostar", "rao", "HydroStar/HAMS .rao motion RAOs (one DOF per file, the six side by side)",
                (".rao",), "marinesim.vessel.hydrostar:read_hydrostar", "marinesim.vessel.hydrostar:sniff"))
register(Format("orcaflex", "rao", "OrcaFlex vessel type displacement RAOs (.yml, .yaml)", (".yml", ".yaml"),
                "marinesim.vessel.orcaflex:read_orcaflex", "marinesim.vessel.orcaflex:sniff"))
register(Format("aqwa", "rao", "ANSYS AQWA listing (.lis): position RAOs of structure 1", (".lis",),
                "marinesim.vessel.aqwa:read_aqwa", "marinesim.vessel.aqwa:sniff"))
register(Format("nemoh", "rao", "NEMOH v2/v3 project, given by its Nemoh.cal: Motion/RAO.dat, or RAOs solved from "
                "its forces, coefficients and mass", (".cal",), "marinesim.vessel.nemoh:read_nemoh",
                "marinesim.vessel.nemoh:sniff", options=("rigid_body",)))
register(Format("wamit-drift", "drift", "WAMIT .8 (momentum) or .9 (pressure) mean drift", (".8", ".9"),
                "marinesim.vessel.wamit_drift:read_drift", options=("ulen",)))
register(Format("aqwa-drift", "drift", "ANSYS AQWA listing (.lis): its wave-drift loads of structure 1", (".lis",),
                "marinesim.vessel.aqwa_drift:read_aqwa_drift", options=("axisymmetric",)))
register(Format("nemoh-drift", "drift", "NEMOH v3 QTF module's OUT_QTFM_N.dat (its diagonal)", (".dat",),
                "marinesim.vessel.nemoh_drift:read_nemoh_drift", options=("axisymmetric",)))
