"""Capytaine results (NetCDF) -> :class:`RaoTable`, by solving the equation of motion.

Capytaine writes complex variables split along a ``complex`` dimension (``re``, ``im``) and uses
the time factor ``exp(-i w t)`` with the incident wave ``Re{A exp(i(k x cos b + k y sin b - w t))}``
(``b`` = ``wave_direction``, travelling towards, from +x: marinesim's ``beta_rel``). Per
frequency and direction this module solves

    [-w^2 (M + A(w)) - i w (B(w) + B_roll) + K] X = F(w, b)

with M the inertia matrix, A and B the added mass and radiation damping, K the hydrostatic
stiffness and F the excitation (diffraction + Froude-Krylov), and converts once to marinesim's
``exp(+i w t)``: ``H = conj(X)``. ``roll_damping`` adds a linear roll damping ``B_roll`` as a
fraction of critical, ``2 sqrt(K44 (M44 + A44(w_n)))`` at the roll natural frequency: potential
flow has no viscous roll damping, so radiation-only RAOs overpredict roll at resonance.

The reference point is the dataset's ``rotation_center`` ``(xc, yc, zc)``, the point X rotates
about. Capytaine's forces, hence X, are per unit wave at the mesh origin (0, 0), while the RAO is
per unit wave at the reference point (CONVENTIONS, "Transfer functions"), whose incident wave is
``exp(-i k (xc cos b + yc sin b))`` times the one at the origin (marinesim's convention), so

    H = conj(X) exp(i k (xc cos b + yc sin b))

with ``k`` from ``w^2 = g k tanh(k h)`` in the dataset's ``water_depth`` h, which the table keeps
(:attr:`RaoTable.depth`). Capytaine 2.x datasets store no ``rotation_center``: the mesh origin
is then assumed (reference point (0, 0, 0), no shift) and a note says so.

A dataset of several bodies (DOFs named ``<body>__Surge`` ...) is solved as the coupled system of all
of them, every body free, and the table is the motions of the one named by ``body`` about its own
rotation centre. Needs ``xarray`` with
a NetCDF engine (``pip install 'marinesim[capytaine]'``).
"""

from __future__ import annotations

import contextlib
import gc
import math
import sys
from pathlib import Path
from typing import Iterator

import numpy as np

from marinesim.errors import FileFormatError, MarinesimError, ParameterError
from marinesim.formats import check_file
from marinesim.vessel.body import RigidBody, gravity_stiffness
from marinesim.vessel.rao import DOFS, RaoTable, make_table, refer_phases

NEEDED = ("added_mass", "radiation_damping", "inertia_matrix", "hydrostatic_stiffness")


def sniff(head: bytes) -> bool:
    """Whether the file starts as NetCDF does (HDF5 or classic CDF signature)."""
    return head.startswith((b"\x89HDF", b"CDF"))


def read_capytaine(path: str | Path, *, roll_damping: float = 0.0, body: str | None = None,
                   rigid_body: RigidBody | None = None) -> RaoTable:
    """RAOs from a Capytaine dataset; ``roll_damping`` is the extra roll damping (fraction of critical) of the
    body whose motions are read; ``body`` names that body in a dataset of several (required there);
    ``rigid_body`` (the scenario's) replaces that body's inertia and adds its external stiffness and damping."""
    path = Path(path)
    if not (math.isfinite(roll_damping) and 0.0 <= roll_damping < 1.0):
        raise ParameterError(f"roll damping must be in [0, 1) of critical, got {roll_damping!r}")
    dataset = _open(path)
    try:
        return _solve(path, dataset, roll_damping, body, rigid_body or RigidBody())
    except MarinesimError:
        raise
    except (KeyError, ValueError, IndexError, TypeError) as error:  # a dataset shaped unlike Capytaine's
        raise FileFormatError(path, None, f"unexpected dataset structure ({type(error).__name__}: {error})") from None


def _solve(path: Path, dataset, roll_damping: float, body: str | None, rigid_body: RigidBody) -> RaoTable:
    """The RAO table from an opened dataset (see the module docstring)."""
    missing = [name for name in NEEDED if name not in dataset]
    has_excitation = "excitation_force" in dataset or {"diffraction_force", "Froude_Krylov_force"} <= set(dataset)
    if missing or not has_excitation:
        missing += [] if has_excitation else ["excitation_force (or diffraction_force + Froude_Krylov_force)"]
        raise FileFormatError(path, None, "a Capytaine dataset needs hydrodynamic coefficients, inertia and "
                                          f"hydrostatic stiffness to give RAOs; missing: {', '.join(missing)}")
    speed = float(dataset["forward_speed"]) if "forward_speed" in dataset.coords else 0.0
    if speed != 0.0:
        raise FileFormatError(path, None, f"forward speed {speed:g} m/s: only zero-speed Capytaine results are supported")
    if "omega" not in dataset.coords:
        raise FileFormatError(path, None, "no 'omega' coordinate (angular frequency)")
    frequency_dim = dataset["omega"].dims[0]
    dataset = dataset.sortby("omega")
    dofs = [str(v) for v in dataset["radiating_dof"].values]
    chosen = _body_dofs(path, dofs, body)

    def matrix(name: str, per_frequency: bool) -> np.ndarray:
        data = _dof_ordered(path, _complex(dataset[name]), ("influenced_dof", "radiating_dof"), dofs)
        dims = ((frequency_dim,) if per_frequency else ()) + ("influenced_dof", "radiating_dof")
        try:
            return np.asarray(data.transpose(*dims).values)
        except ValueError:
            raise FileFormatError(path, None, f"{name} has dimensions {data.dims}, expected {dims}") from None

    omega = np.asarray(dataset["omega"].values, dtype=float)
    mass = matrix("inertia_matrix", False).real
    stiffness = matrix("hydrostatic_stiffness", False).real
    added = matrix("added_mass", True).real
    damping = matrix("radiation_damping", True).real
    force = _excitation(path, dataset, frequency_dim, dofs)
    directions = np.asarray(dataset["wave_direction"].values, dtype=float)
    for name, array in (("inertia_matrix", mass), ("hydrostatic_stiffness", stiffness)):
        if not np.all(np.isfinite(array)):
            raise FileFormatError(path, None, f"{name} has non-finite values")
    notes = [f"Capytaine {dataset.attrs.get('capytaine_version', '?')}; equation of motion solved per frequency"]
    omega, added, damping, force, dropped = _usable_frequencies(path, omega, added, damping, force)
    if dropped:
        notes.append(dropped)
    own = np.ix_(chosen, chosen)
    g = float(dataset["g"]) if "g" in dataset.coords else 9.81
    reference = _reference(path, dataset, body, notes)
    stiffness = stiffness.copy()
    if rigid_body.mass_kg is not None:
        # the dataset's stiffness holds the weight of its own inertia matrix's mass at its centre of gravity
        mass = mass.copy()
        scenario = rigid_body.mass_matrix(about=reference)
        stiffness[own] += gravity_stiffness(scenario, g) - gravity_stiffness(mass[own], g)
        mass[own] = scenario
    stiffness[own] += rigid_body.stiffness()
    if rigid_body.given:
        notes.append(rigid_body.describe())
    extra = np.zeros_like(mass)
    extra[own] = rigid_body.damping()
    roll = chosen[3]
    if roll_damping > 0.0:
        own_added = added[:, chosen][:, :, chosen]
        critical = roll_damping * _critical_roll_damping(path, omega, mass[own], own_added, stiffness[own])
        extra[roll, roll] += critical
        notes.append(f"extra linear roll damping {100 * roll_damping:g} % of critical ({critical:.10g} N m s/rad)")
    impedance = (-omega[:, None, None] ** 2 * (mass + added) - 1j * omega[:, None, None] * (damping + extra)
                 + stiffness)
    try:
        motion = np.linalg.solve(impedance[:, None], force[..., None])[..., 0][..., chosen]  # (omega, direction, 6)
    except np.linalg.LinAlgError:
        raise FileFormatError(path, None, "the equation of motion is singular at some frequency") from None
    rho = float(dataset["rho"]) if "rho" in dataset.coords else 1025.0
    depth = float(dataset["water_depth"]) if "water_depth" in dataset.coords else math.inf
    if not depth > 0.0:
        raise FileFormatError(path, None, f"water_depth must be > 0 m (inf: deep water), got {depth:g}")
    if len(dofs) > 6:
        notes.append(f"body {body!r} of a dataset of {len(dofs) // 6} bodies, solved coupled with every body free")
    values = refer_phases(np.conj(motion).transpose(1, 0, 2), omega, np.degrees(directions), reference[:2], depth,
                          g)[None]
    try:
        return make_table(omega, directions, [0.0], values, reference_point=reference, rho=rho, g=g,
                          source=str(path), source_format="capytaine", notes=tuple(notes), depth=depth)
    except ParameterError as error:
        raise FileFormatError(path, None, str(error)) from None


def _reference(path: Path, dataset, body: str | None, notes: list[str]) -> tuple[float, float, float]:
    """The body's rotation centre (m), the reference point of its RAOs; the mesh origin, with a note, where the
    dataset stores none (Capytaine 2.x)."""
    if "rotation_center" not in dataset.coords:
        notes.append("the dataset stores no rotation_center (Capytaine 2.x): the motions are taken as about "
                     "the mesh origin (0, 0, 0), the reference point, and per unit wave there; if the body's "
                     "DOFs rotate about another point, export the dataset with Capytaine 3")
        return (0.0, 0.0, 0.0)
    centre = dataset["rotation_center"]
    if "body" in centre.dims:
        centre = centre.sel(body=body)
    reference = tuple(float(v) for v in np.ravel(centre.values))
    if len(reference) != 3 or not all(math.isfinite(v) for v in reference):
        raise FileFormatError(path, None, f"rotation_center must be three finite numbers, got {reference}")
    return reference


def _usable_frequencies(path: Path, omega: np.ndarray, added: np.ndarray, damping: np.ndarray,
                        force: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray, str]:
    """The frequencies at which Capytaine gave everything an RAO needs, and a note on those dropped: omega = 0 and
    infinity (added-mass limits; no wave there, so no excitation) and frequencies with non-finite coefficients
    (Capytaine leaves NaN where its finite-depth Green function is not defined, kh < 0.1). Refuses a dataset
    with none left."""
    finite = (np.isfinite(added).all(axis=(1, 2)) & np.isfinite(damping).all(axis=(1, 2))
              & np.isfinite(force).all(axis=(1, 2)))
    limits = ~np.isfinite(omega) | (omega <= 0.0)
    keep = finite & ~limits
    if not keep.any():
        raise FileFormatError(path, None, "no frequency with finite coefficients and excitation: nothing to solve")
    parts = []
    if limits.any():
        parts.append("omega " + " and ".join(f"{w:g}" for w in omega[limits]) + " (added-mass limits, no waves)")
    if (~finite & ~limits).any():
        parts.append(", ".join(f"{w:.4g}" for w in omega[~finite & ~limits]) + " rad/s (non-finite coefficients, "
                     "as Capytaine leaves them where its finite-depth Green function fails, kh < 0.1)")
    note = f"frequencies dropped: {'; '.join(parts)}" if parts else ""
    return omega[keep], added[keep], damping[keep], force[keep], note


def _open(path: Path):
    try:
        import xarray
    except ImportError:
        raise FileFormatError(path, None, "reading Capytaine NetCDF needs xarray and a NetCDF engine: "
                                          "pip install 'marinesim[capytaine]'") from None
    check_file(path)
    with _unraisable_ignored():
        try:
            return xarray.open_dataset(path).load()
        except Exception as error:  # xarray raises many kinds for unreadable files
            # its first line: xarray's "no IO backend" message goes on with lines of links
            reason = f"{type(error).__name__}: {(str(error).strip().splitlines() or [''])[0]}"
        gc.collect()  # the half-opened file objects go now, while their complaints are ignored
    raise FileFormatError(path, None, f"not a readable NetCDF dataset ({reason})")


@contextlib.contextmanager
def _unraisable_ignored() -> Iterator[None]:
    """Exceptions raised where Python cannot raise them (``__del__``) ignored: h5netcdf's file object of
    a damaged file fails to close when collected and would print an "Exception ignored" traceback."""
    hook = sys.unraisablehook
    sys.unraisablehook = lambda unraisable: None
    try:
        yield
    finally:
        sys.unraisablehook = hook


def _complex(array):
    """Merge Capytaine's split ``complex`` dimension (``re``, ``im``) back into complex values."""
    if "complex" not in array.dims:
        return array
    return array.sel(complex="re") + 1j * array.sel(complex="im")


def _body_dofs(path: Path, dofs: list[str], body: str | None) -> list[int]:
    """Indices into ``dofs`` (the dataset's, in its order) of the chosen body's surge ... yaw, in :data:`DOFS`
    order: the six of a single body (named ``Surge`` ...), or those named ``<body>__Surge`` ... of several."""
    lower = [name.lower() for name in dofs]
    if sorted(lower) == sorted(DOFS):
        if body is not None:
            raise FileFormatError(path, None, f"the dataset holds one body: a body name ({body!r}) is for datasets "
                                              "of several")
        return [lower.index(d) for d in DOFS]
    bodies = list(dict.fromkeys(name.rsplit("__", 1)[0] for name in dofs if "__" in name))
    if len(bodies) < 2 or any("__" not in name for name in dofs):
        raise FileFormatError(path, None, f"radiating_dof is {dofs}, expected the six rigid-body DOFs "
                                          f"{', '.join(DOFS)} of one body, or <body>__<dof> of several")
    if body is None or body not in bodies:
        given = "" if body is None else f"no body {body!r}; "
        raise FileFormatError(path, None, f"{given}a dataset of bodies {', '.join(bodies)}: name the one whose "
                                          "motions to read (marinesim rao --body, [vessel] rao_body)")
    own = {name.rsplit("__", 1)[1].lower(): i for i, name in enumerate(dofs) if name.rsplit("__", 1)[0] == body}
    missing = [d for d in DOFS if d not in own]
    if missing:
        raise FileFormatError(path, None, f"body {body!r} has no {', '.join(missing)} DOF: six rigid-body DOFs needed")
    return [own[d] for d in DOFS]


def _dof_ordered(path: Path, array, dims: tuple[str, ...], dofs: list[str]):
    """``array`` with its DOF dimensions in the order of ``dofs`` (the radiating DOFs of the dataset)."""
    for dim in dims:
        if dim not in array.dims:
            continue
        names = [str(v) for v in array[dim].values]
        if sorted(names) != sorted(dofs):
            raise FileFormatError(path, None, f"{array.name}: {dim} is {names}, expected {dofs}")
        array = array.isel({dim: [names.index(d) for d in dofs]})
    return array


def _excitation(path: Path, dataset, frequency_dim: str, dofs: list[str]) -> np.ndarray:
    if "excitation_force" in dataset:
        force = _complex(dataset["excitation_force"])
    else:
        force = _complex(dataset["diffraction_force"]) + _complex(dataset["Froude_Krylov_force"])
    force.name = "excitation_force"
    force = _dof_ordered(path, force, ("influenced_dof",), dofs)
    return np.asarray(force.transpose(frequency_dim, "wave_direction", "influenced_dof").values, dtype=complex)


def _critical_roll_damping(path: Path, omega: np.ndarray, mass: np.ndarray, added: np.ndarray,
                           stiffness: np.ndarray) -> float:
    """``2 sqrt(K44 (M44 + A44(w_n)))`` with w_n the roll natural frequency found by fixed point."""
    k44 = stiffness[3, 3]
    if k44 <= 0:
        raise ParameterError(f"{path}: roll damping in % of critical needs a positive roll stiffness, got K44 = {k44:g}")
    a44 = added[:, 3, 3]
    natural = math.sqrt(k44 / (mass[3, 3] + a44[0]))
    for _ in range(50):
        natural = math.sqrt(k44 / (mass[3, 3] + float(np.interp(natural, omega, a44))))
    return 2.0 * math.sqrt(k44 * (mass[3, 3] + float(np.interp(natural, omega, a44))))
