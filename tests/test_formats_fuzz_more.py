"""Fuzzing the registered formats that tests/test_formats_fuzz.py leaves out: Capytaine NetCDF and the
meshes trimesh reads (STL binary and ASCII, PLY, OFF, glTF binary). Same contract: every reader returns
a valid object or raises a one-line :class:`MarinesimError`, never another exception, and ends (a read that
has not ended after :data:`~conftest.HANG_S` fails as a hang; no deadline of a few seconds, which a loaded machine
misses). ``MARINESIM_FUZZ_EXAMPLES`` sets the cases per format.

The NetCDF source is a small barge solved here with Capytaine once per module; hypothesis drops
variables, writes NaN, inf, huge or negative values, cuts dimensions, renames DOFs, or truncates and
flips the file's bytes. The meshes are hulls/wigley.stl and hulls/barge_visual.glb written in each
format by trimesh, then cut, flipped or given hostile numbers.
"""

from __future__ import annotations

import math
import os
import tempfile
from collections.abc import Callable
from functools import partial
from pathlib import Path

import numpy as np
import pytest
import trimesh
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from conftest import hang_guard, outcome
from marinesim.errors import MarinesimError
from marinesim.hull import Hull, load_hull
from marinesim.hull.visual import VisualMesh, load_visual_mesh
from marinesim.vessel.rao import RaoTable
from marinesim.vessel.read import read_rao

ROOT = Path(__file__).resolve().parents[1]
DEFAULT_EXAMPLES = 30
FUZZ = settings(max_examples=int(os.environ.get("MARINESIM_FUZZ_EXAMPLES", DEFAULT_EXAMPLES)),
                deadline=None, derandomize=True, database=None,
                suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large,
                                       HealthCheck.function_scoped_fixture])
HOSTILE_NUMBERS = [math.nan, math.inf, -math.inf, 1e308, -1e308, 1e-300, -1.0, 0.0, -1e6]
HOSTILE_TOKENS = st.one_of(
    st.sampled_from(["0", "-1", "1e308", "-1e308", "1e-300", "nan", "inf", "-inf", "99999999999", "x", "",
                     "-0", "4294967295", "-2147483649"]),
    st.floats(allow_nan=True, allow_infinity=True).map(repr),
    st.integers(min_value=-10**12, max_value=10**12).map(str),
)


# --- Capytaine NetCDF ------------------------------------------------------------------------------------

def small_capytaine_dataset():
    """A 20 x 6 m barge (draft 2 m) solved by Capytaine at 4 frequencies and 3 directions."""
    import capytaine
    import xarray

    mesh = capytaine.mesh_parallelepiped(size=(20.0, 6.0, 3.0), resolution=(6, 2, 2), center=(0.0, 0.0, -0.5))
    body = capytaine.FloatingBody(mesh=mesh, dofs=capytaine.rigid_body_dofs(rotation_center=(0, 0, 0)),
                                  center_of_mass=(0.0, 0.0, -0.5)).immersed_part()
    body.inertia_matrix = body.compute_rigid_body_inertia(rho=1025.0)
    body.hydrostatic_stiffness = body.compute_hydrostatic_stiffness(rho=1025.0)
    problems = xarray.Dataset(coords={"omega": [0.3, 0.7, 1.1, 1.6], "wave_direction": [0.0, math.pi / 2, math.pi],
                                      "radiating_dof": list(body.dofs), "water_depth": [np.inf], "rho": [1025.0]})
    return capytaine.BEMSolver().fill_dataset(problems, body)


@pytest.fixture(scope="module")
def capytaine_dataset():
    return small_capytaine_dataset()


@pytest.fixture(scope="module")
def capytaine_file(capytaine_dataset, tmp_path_factory) -> Path:
    """The barge's NetCDF as Capytaine writes it."""
    import capytaine

    path = tmp_path_factory.mktemp("capytaine") / "barge.nc"
    capytaine.export_dataset(path, capytaine_dataset)
    return path


DATASET_EDIT = st.tuples(
    st.sampled_from(["drop", "value", "cut", "rename_dof", "transpose", "scalar"]),
    st.integers(min_value=0), st.sampled_from(HOSTILE_NUMBERS), st.integers(min_value=0))


def mutate_dataset(dataset, edits):
    """``dataset`` after each edit (what, variable index, hostile number, position; indices wrap)."""
    for what, which, number, position in edits:
        names = sorted(dataset.data_vars) + sorted(str(c) for c in dataset.coords)
        if not names:
            break
        name = names[which % len(names)]
        array = dataset[name]
        if what == "drop":
            dataset = dataset.drop_vars(name)
        elif what == "value" and array.size and array.dtype.kind in "fc":
            values = np.array(array.values, dtype=array.dtype)
            values.flat[position % values.size] = number
            dataset = dataset.assign({name: (array.dims, values)}) if name in dataset.data_vars \
                else dataset.assign_coords({name: (array.dims, values)})
        elif what == "cut" and array.dims:
            dim = array.dims[position % len(array.dims)]
            dataset = dataset.isel({dim: slice(0, position % max(dataset.sizes[dim], 1))})
        elif what == "rename_dof" and "influenced_dof" in dataset.coords:
            dofs = [str(v) for v in dataset["influenced_dof"].values]
            if dofs:
                dofs[position % len(dofs)] = "Yawn" if number < 0 else dofs[0]
                dataset = dataset.assign_coords(influenced_dof=dofs)
        elif what == "transpose" and array.ndim > 1 and name in dataset.data_vars:
            dataset = dataset.assign({name: (array.dims, array.values.swapaxes(0, -1).reshape(array.shape))})
        elif what == "scalar" and name in dataset.data_vars:
            dataset = dataset.assign({name: ((), number)})
    return dataset


@pytest.mark.slow
@FUZZ
@given(edits=st.lists(DATASET_EDIT, min_size=1, max_size=3))
def test_mutated_capytaine_datasets_give_a_table_or_one_clean_error(capytaine_dataset, edits):
    """A dataset with a variable missing, a NaN or inf, a cut dimension or an unknown DOF must not reach the user
    as a traceback (KeyError, LinAlgError, ...) from xarray or numpy."""
    import capytaine

    dataset = mutate_dataset(capytaine_dataset, edits)
    with tempfile.TemporaryDirectory() as folder:
        path = Path(folder) / "b.nc"
        try:
            capytaine.export_dataset(path, dataset)
        except Exception:  # capytaine itself cannot write this dataset: nothing for a user to read
            return
        with hang_guard(f"reading a NetCDF after the edits {edits}"):
            outcome(read_rao, RaoTable, path)


@pytest.mark.slow
@FUZZ
@given(cut=st.floats(0.0, 1.0), flips=st.lists(st.tuples(st.floats(0.0, 1.0), st.integers(0, 255)), max_size=6))
def test_damaged_capytaine_bytes_give_a_table_or_one_clean_error(capytaine_file, cut, flips):
    """A truncated or corrupted NetCDF file must be one line, not an h5py or netCDF traceback."""
    data = bytearray(capytaine_file.read_bytes())
    for where, value in flips:
        data[int(where * (len(data) - 1))] = value
    with tempfile.TemporaryDirectory() as folder:
        path = Path(folder) / "b.nc"
        path.write_bytes(bytes(data[: max(4, int(cut * len(data)))]))
        with hang_guard(f"reading a NetCDF cut at {cut} with the bytes {flips}"):
            outcome(read_rao, RaoTable, path)


# --- meshes trimesh reads ----------------------------------------------------------------------------------

def _wigley() -> trimesh.Trimesh:
    return trimesh.load(ROOT / "hulls" / "wigley.stl", force="mesh")


MESHES: dict[str, tuple[Callable[[], bytes], str, Callable[[Path], object], type]] = {
    "stl-binary": (lambda: _wigley().export(file_type="stl"), "h.stl", load_hull, Hull),
    "stl-ascii": (lambda: _wigley().export(file_type="stl_ascii").encode(), "h.stl", load_hull, Hull),
    "ply-binary": (lambda: _wigley().export(file_type="ply", encoding="binary"), "h.ply", load_hull, Hull),
    "ply-ascii": (lambda: _wigley().export(file_type="ply", encoding="ascii"), "h.ply", load_hull, Hull),
    "off": (lambda: _wigley().export(file_type="off").encode(), "h.off", load_hull, Hull),
    "glb-hull": (lambda: _wigley().export(file_type="glb"), "h.glb", load_hull, Hull),
    "glb-visual": (lambda: (ROOT / "hulls" / "barge_visual.glb").read_bytes(), "v.glb",
                   partial(load_visual_mesh, units="cm", axes="x,-z,y"), VisualMesh),  # in cm, y up (hulls/README.md)
}
"""Case name -> (the file's bytes, its name, the reader, what it returns)."""
_BYTES: dict[str, bytes] = {}


def mesh_bytes(name: str) -> bytes:
    if name not in _BYTES:
        data = MESHES[name][0]()
        _BYTES[name] = data if isinstance(data, bytes) else str(data).encode()
    return _BYTES[name]


BYTE_EDIT = st.tuples(st.sampled_from(["truncate", "flip", "token", "delete_line", "zero_run"]),
                      st.floats(0.0, 1.0), HOSTILE_TOKENS, st.integers(0, 255))


def mutate_bytes(data: bytes, edits) -> bytes:
    """``data`` after each edit (what, where as a fraction, hostile token, byte value)."""
    data = bytearray(data)
    for what, where, token, value in edits:
        if not data:
            break
        at = int(where * (len(data) - 1))
        if what == "truncate":
            del data[at:]
        elif what == "flip":
            data[at] = value
        elif what == "zero_run":
            data[at:at + 16] = bytes(min(16, len(data) - at))
        elif what == "delete_line":
            end = data.find(b"\n", at)
            del data[at: len(data) if end < 0 else end + 1]
        else:  # a number (or, in binary files, 8 bytes) replaced by a hostile token
            start = at
            while start > 0 and data[start - 1:start] not in (b" ", b"\n", b"\t"):
                start -= 1
            end = at
            while end < len(data) and data[end:end + 1] not in (b" ", b"\n", b"\t"):
                end += 1
            end = min(end, start + 8)
            data[start:end] = token.encode()
    return bytes(data)


@pytest.mark.parametrize("name", sorted(MESHES))
@FUZZ
@given(edits=st.lists(BYTE_EDIT, min_size=1, max_size=4))
def test_mutated_meshes_give_a_result_or_one_clean_error(name, edits):
    """A damaged STL, PLY, OFF or GLB must give a hull (or visual mesh) or one line, never a traceback from
    trimesh or numpy (struct.error, IndexError, MemoryError, ...) nor a hang."""
    _, file_name, read, valid = MESHES[name]
    with tempfile.TemporaryDirectory() as folder:
        path = Path(folder) / file_name
        path.write_bytes(mutate_bytes(mesh_bytes(name), edits))
        with hang_guard(f"reading {file_name} ({name}) after the edits {edits}"):
            outcome(read, valid, path)


@pytest.mark.parametrize("name", sorted(MESHES))
def test_each_mesh_source_reads(name, tmp_path):
    """The fuzz is worthless if the unmutated file is already refused."""
    _, file_name, read, valid = MESHES[name]
    path = tmp_path / file_name
    path.write_bytes(mesh_bytes(name))
    assert isinstance(read(path), valid)


def test_the_unmutated_capytaine_dataset_reads(capytaine_file):
    """The fuzz is worthless if the unmutated dataset is already refused."""
    assert isinstance(read_rao(capytaine_file), RaoTable)


@pytest.mark.parametrize("size", [0, 4, 8])
def test_a_netcdf_cut_inside_its_signature_is_one_line(capytaine_file, tmp_path, size):
    """Regression (found by the fuzz): a file cut to its first bytes, which no xarray backend claims, gave
    xarray's message with its lines of links, so the user saw several lines instead of one."""
    path = tmp_path / "b.nc"
    path.write_bytes(capytaine_file.read_bytes()[:size])
    with pytest.raises(MarinesimError) as raised:
        read_rao(path)
    assert "\n" not in str(raised.value) and str(path) in str(raised.value)
