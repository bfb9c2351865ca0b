"""WAMIT force control file (``.frc``): density, centre of gravity, mass matrix and external matrices.

Two layouts (WAMIT user manual, "The Force Control File", alternative forms 1 and 2), told apart by
``IALTFRC`` in the ``.cfg`` beside it or, without one, by the shape of the fifth line:

* ``IALTFRC = 1``: header, ``IOPTN(1..9)``, ``VCG``, the 3 x 3 radii of gyration ``XPRDCT`` (m), then
  ``NBETAH`` ... The body's mass is the displaced mass ``rho V``, its centre of gravity
  ``(XB, YB, VCG)`` (horizontally at the centre of buoyancy) and its inertia about the body origin
  ``I_ij = rho V XPRDCT_ij |XPRDCT_ij|``. ``rho`` is not in the file.
* ``IALTFRC = 2``: header, ``IOPTN(1..9)``, ``RHO``, ``XCG YCG ZCG``, ``IMASS`` and (if 1) the 6 x 6 mass
  matrix, ``IDAMP`` and the external damping matrix, ``ISTIF`` and the external stiffness matrix, all
  dimensional (SI) about the body origin, then ``NBETAH`` ...

Frames: WAMIT's body coordinates (x forward, y to port, z up, origin of the ``.gdf``), marinesim's body
frame B with the RAO reference point at that origin (docs/CONVENTIONS.md).
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

import numpy as np

from marinesim.errors import FileFormatError
from marinesim.tokens import leading_numbers, parse_float, parse_int, read_text

MATRICES = ("mass (IMASS)", "external damping (IDAMP)", "external stiffness (ISTIF)")
RHO_RANGE = (500.0, 2000.0)
"""Water density a WAMIT run can have (kg/m^3): fresh water to brine, with room for model tests."""


@dataclass(frozen=True)
class ForceControl:
    """What a ``.frc`` gives: ``form`` (IALTFRC 1 or 2); ``rho`` (kg/m^3, None in form 1); ``cog`` (m, body
    frame; form 1: only z is given, None here); ``radii`` (3 x 3 radii of gyration, m, form 1); ``mass``
    (6 x 6, kg, kg m, kg m^2; None in form 1 or with IMASS = 0); ``damping`` and ``stiffness`` (6 x 6
    external matrices, SI, zero when not given)."""

    form: int
    rho: float | None
    vcg: float
    cog: tuple[float, float, float] | None
    radii: np.ndarray | None
    mass: np.ndarray | None
    damping: np.ndarray
    stiffness: np.ndarray


def read_frc(path: Path, form: int | None = None) -> ForceControl:
    """Read the ``.frc`` at ``path``; ``form`` is IALTFRC from the ``.cfg`` (None: told from the layout)."""
    text = read_text(path).splitlines()
    rows = [(number, leading_numbers(line)) for number, line in enumerate(text[1:], 2) if line.split()]
    if len(rows) < 4:
        raise FileFormatError(path, len(text) or None, "file ends early: expected IOPTN, then RHO or VCG, "
                                                       "XCG YCG ZCG or XPRDCT, ...")
    shape_form = 2 if len(rows[3][1]) == 1 else 1
    if form is None:
        form = shape_form
    elif form not in (1, 2):
        raise FileFormatError(path, None, f"IALTFRC {form} (in the .cfg) is not supported: give the .frc in "
                                          "alternative form 1 or 2")
    elif form != shape_form:
        raise FileFormatError(path, rows[3][0], f"the .cfg says IALTFRC = {form}, but line {rows[3][0]} has "
                                                f"{len(rows[3][1])} value(s), as in form {shape_form}")
    at = 1  # rows[0] is IOPTN
    if form == 1:
        vcg = _number(path, rows, at, "VCG (m)")
        radii = np.array([[_number(path, rows, at + 1 + r, f"XPRDCT({r + 1},{c + 1}) (m)", c) for c in range(3)]
                          for r in range(3)])
        zero = np.zeros((6, 6))
        return ForceControl(1, None, vcg, None, radii, None, zero, zero.copy())
    rho = _number(path, rows, at, "RHO (kg/m^3)")
    if not RHO_RANGE[0] <= rho <= RHO_RANGE[1]:
        raise FileFormatError(path, rows[at][0], f"RHO must be in {RHO_RANGE[0]:g}..{RHO_RANGE[1]:g} kg/m^3, "
                                                 f"got {rho:g}")
    if len(rows[at + 1][1]) != 3:
        raise FileFormatError(path, rows[at + 1][0], "expected XCG YCG ZCG (one body; "
                                                     f"got {len(rows[at + 1][1])} values)")
    cog = tuple(_number(path, rows, at + 1, name, c) for c, name in enumerate(("XCG", "YCG", "ZCG")))
    at += 2
    matrices: list[np.ndarray | None] = []
    for name in MATRICES:
        if at >= len(rows):
            raise FileFormatError(path, rows[-1][0], f"file ends early: expected the {name} flag 0 or 1")
        number, parts = rows[at]
        flag = parse_int(path, number, parts[0] if parts else "", f"{name} flag 0 or 1")
        if flag not in (0, 1) or len(parts) != 1:
            raise FileFormatError(path, number, f"expected the {name} flag alone, 0 or 1, got {' '.join(parts)}")
        at += 1
        if flag == 0:
            matrices.append(None)
            continue
        matrix = np.array([[_number(path, rows, at + r, f"{name} row {r + 1} column {c + 1}", c, width=6)
                            for c in range(6)] for r in range(6)])
        matrices.append(matrix)
        at += 6
    mass, damping, stiffness = matrices
    return ForceControl(2, rho, cog[2], cog, None, mass,
                        np.zeros((6, 6)) if damping is None else damping,
                        np.zeros((6, 6)) if stiffness is None else stiffness)


def _number(path: Path, rows: list[tuple[int, list[str]]], at: int, name: str, column: int = 0,
            width: int | None = None) -> float:
    """Value ``column`` of the ``at``-th non-empty line after the header; ``width``: the count it must have."""
    if at >= len(rows):
        raise FileFormatError(path, rows[-1][0], f"file ends early: expected {name}")
    number, parts = rows[at]
    if width is not None and len(parts) != width:
        raise FileFormatError(path, number, f"expected {width} values ({name.split(' row')[0]} matrix row; "
                                            f"one body), got {len(parts)}")
    if column >= len(parts):
        raise FileFormatError(path, number, f"expected {name}, the line has {len(parts)} value(s)")
    return parse_float(path, number, parts[column], name)
