"""The file-format registry: every registered format reads a real file, detection, refusals.

Each registered format must have an entry in ``SAMPLES``: a function giving a real file of that
format (shipped in rao/ or hulls/, or written here by a real program: marinesim's own writer,
Capytaine, trimesh's exporters) and the check that reading it gave the right numbers.
"""

import math
import os
import shutil
import subprocess
import sys
from collections.abc import Callable
from pathlib import Path

import numpy as np
import pytest
import trimesh

from conftest import ROOT
from marinesim import formats
from marinesim.errors import FileFormatError, MarinesimError, ParameterError
from marinesim.hull import hydrostatics, load_hull, load_visual_mesh, wigley_hull
from marinesim.vessel import read_rao
from marinesim.vessel.native import write_native
from marinesim.vessel.read import OPTION_LIMITS

TANKER_RAO = ROOT / "rao" / "tanker" / "tanker.4"
S175 = ROOT / "rao" / "s175" / "input.re1"
WIGLEY = ROOT / "hulls" / "wigley.stl"


def capytaine_dataset(folder: Path) -> Path:
    """A 40 x 10 m barge at 3 m draft, solved by Capytaine at three frequencies, as Capytaine writes it."""
    import capytaine
    import xarray

    mesh = capytaine.mesh_parallelepiped(size=(40.0, 10.0, 4.0), resolution=(6, 2, 2), center=(0.0, 0.0, -1.0))
    body = capytaine.FloatingBody(mesh=mesh, dofs=capytaine.rigid_body_dofs(rotation_center=(0, 0, 0)),
                                  center_of_mass=(0.0, 0.0, -0.5)).immersed_part()
    body.inertia_matrix = body.compute_rigid_body_inertia(rho=1025.0)
    body.hydrostatic_stiffness = body.compute_hydrostatic_stiffness(rho=1025.0)
    problems = xarray.Dataset(coords={"omega": [0.1, 0.5, 1.0], "wave_direction": [0.0, math.pi / 2, math.pi],
                                      "radiating_dof": list(body.dofs), "water_depth": [np.inf], "rho": [1025.0]})
    path = folder / "barge.nc"
    capytaine.export_dataset(path, capytaine.BEMSolver().fill_dataset(problems, body))
    return path


def native_table(folder: Path) -> Path:
    """The S175 table written by marinesim's own writer."""
    path = folder / "s175.csv"
    write_native(read_rao(S175), path)
    return path


def exported_wigley(suffix: str) -> Callable[[Path], Path]:
    """The shipped Wigley hull re-exported by trimesh in another format."""
    def write(folder: Path) -> Path:
        mesh = trimesh.load(WIGLEY, force="mesh")
        path = folder / f"wigley{suffix}"
        mesh.export(path)
        return path
    return write


def check_rao(path: Path, name: str) -> None:
    """Read as ``name``, and heave tends to 1 at the table's longest wave in head seas."""
    table = read_rao(path)
    assert table.source_format == name
    heave = table(table.omega[:1], np.array([math.pi]), table.speed[0])[0, 2]
    assert abs(heave) == pytest.approx(1.0, abs=0.05), f"{name}: long-wave heave {abs(heave):.3f}, not 1"


def check_wigley(path: Path, name: str) -> None:
    """The Wigley hull's hydrostatics, as made by its generator."""
    made = hydrostatics(wigley_hull(100.0, 10.0, 6.25, nx=80, nz=16))
    read = hydrostatics(load_hull(path))
    assert read.volume_m3 == pytest.approx(made.volume_m3, rel=1e-6), name
    assert read.wetted_area_m2 == pytest.approx(made.wetted_area_m2, rel=1e-6), name


def check_tanker_gdf(path: Path, name: str) -> None:
    """The tanker's waterplane area equals WAMIT's own C33 for these panels (ISY mirror applied)."""
    hst = {(int(i), int(j)): v for i, j, v in np.loadtxt(ROOT / "rao" / "tanker" / "tanker.hst")}
    assert hydrostatics(load_hull(path)).waterplane_area_m2 == pytest.approx(hst[3, 3], rel=1e-5)


def check_hams_cylinder(path: Path, name: str) -> None:
    """HAMS's cylinder displaces its 1604 kg of mass over rho (HAMS's Hydrostatic.in; tests/test_hull_pnl.py)."""
    assert hydrostatics(load_hull(path)).volume_m3 == pytest.approx(1604.0 / 1025.0, rel=1e-4)


def check_nemoh_cube(path: Path, name: str) -> None:
    """NEMOH's verification cube is a 10 x 10 x 5 m box (tests/test_hull_nemoh_mesh.py)."""
    assert hydrostatics(load_hull(path)).volume_m3 == pytest.approx(500.0, rel=1e-12)


def check_barge_visual(path: Path, name: str) -> None:
    """The barge's visual mesh (cm, y up): 100 m long, 25 m mast on top, with its vertex colours."""
    mesh = load_visual_mesh(path, units="cm", axes="x,-z,y", offset=(-50.0, 0.0, -5.0))
    assert np.ptp(mesh.vertices[:, 0]) == pytest.approx(100.0) and mesh.vertices[:, 2].max() == pytest.approx(25.0)
    assert mesh.colours is not None


def check_gmsh_barge(path: Path, name: str) -> None:
    """gmsh's 40 x 10 m box barge, draft 3 m: its displaced volume exactly."""
    assert hydrostatics(load_hull(path)).volume_m3 == pytest.approx(1200.0, rel=1e-9)


def tanker_report(folder: Path) -> Path:
    """WAMIT's report of the tanker (three of its periods, tests/data/mss), unpacked."""
    import lzma

    path = folder / "tanker.out"
    path.write_bytes(lzma.decompress((ROOT / "tests" / "data" / "mss" / "tanker.out.xz").read_bytes()))
    return path


def check_tanker_report(path: Path, name: str) -> None:
    """The report's RAOs are WAMIT's .4 of the same run, to the report's whole-degree phases."""
    table, numeric = read_rao(path), read_rao(TANKER_RAO)
    assert table.source_format == name
    picked = np.isin(np.round(2 * np.pi / numeric.omega, 2), [7.86, 10.44, 13.91])
    np.testing.assert_allclose(table.values, numeric.values[:, :, picked], rtol=0.01, atol=1e-4)


DRIFT = ROOT / "tests" / "data" / "drift"


def check_drift(path: Path, name: str) -> None:
    """A mean drift table read through the registry pushes the body astern in head seas in the upper half of its
    frequencies (the AQWA cylinder and the NEMOH spar turned round the circle: each covers few headings)."""
    fmt = formats.get(name, "drift")
    table = formats.reader(fmt)(path, **({"axisymmetric": True} if "axisymmetric" in fmt.options else {}))
    omega = table.omega[len(table.omega) * 2 // 3]
    assert table(np.array([omega]), np.array([np.pi]))[0, 0] < 0.0


SAMPLES: dict[str, tuple[Callable[[Path], Path], Callable[[Path, str], None]]] = {
    "wamit": (lambda folder: TANKER_RAO, check_rao),
    "wamit-forces": (lambda folder: TANKER_RAO.with_suffix(".3"), check_rao),
    "wamit-out": (tanker_report, check_tanker_report),
    "veres": (lambda folder: S175, check_rao),
    "capytaine": (capytaine_dataset, check_rao),
    "native": (native_table, check_rao),
    "hydrostar": (lambda folder: ROOT / "tests" / "data" / "hams" / "cylinder" / "Output" / "Hydrostar_format"
                  / "Motion_3.rao", check_rao),
    "orcaflex": (lambda folder: ROOT / "tests" / "data" / "orcaflex" / "cylinder_vessel_type.yml", check_rao),
    "aqwa": (lambda folder: ROOT / "tests" / "data" / "aqwa" / "cylinder_excerpt.LIS", check_rao),
    "nemoh": (lambda folder: ROOT / "tests" / "data" / "nemoh" / "oc3_hywind" / "Nemoh.cal", check_rao),
    "wamit-drift": (lambda folder: ROOT / "rao" / "tanker" / "tanker.9", check_drift),
    "aqwa-drift": (lambda folder: DRIFT / "aqwa_cylinder_drift.LIS", check_drift),
    "nemoh-drift": (lambda folder: DRIFT / "nemoh_oc3" / "results" / "QTF" / "OUT_QTFM_N_0.dat", check_drift),
    "gdf": (lambda folder: ROOT / "hulls" / "tanker.gdf", check_tanker_gdf),
    "pnl": (lambda folder: ROOT / "tests" / "data" / "hams" / "cylinder" / "Input" / "HullMesh.pnl",
            check_hams_cylinder),
    "nemoh-mesh": (lambda folder: ROOT / "tests" / "data" / "nemoh" / "cube" / "Cube.dat", check_nemoh_cube),
    "gmsh": (lambda folder: ROOT / "tests" / "data" / "gmsh" / "barge.msh", check_gmsh_barge),
    "stl": (lambda folder: WIGLEY, check_wigley),
    "obj": (exported_wigley(".obj"), check_wigley),
    "ply": (exported_wigley(".ply"), check_wigley),
    "gltf": (lambda folder: ROOT / "hulls" / "barge_visual.glb", check_barge_visual),
    "off": (exported_wigley(".off"), check_wigley),
}


def test_every_registered_format_has_a_real_file_check():
    """A format registered without a sample here (or a sample left for a removed format) would go
    untested: adding a format must add a real file of it and a check of what it reads."""
    assert sorted(f.name for f in formats.formats()) == sorted(SAMPLES)


@pytest.mark.parametrize("name", sorted(SAMPLES))
def test_each_format_reads_a_real_file(name, tmp_path):
    """The file is detected as its format and read to the right numbers: a failure means the
    registry routes the extension to another reader, or that reader misreads the file."""
    make, check = SAMPLES[name]
    path = make(tmp_path)
    fmt = next(f for f in formats.formats() if f.name == name)
    assert formats.detect(path, fmt.kind) == fmt
    check(path, name)


@pytest.mark.parametrize("name", [f.name for f in formats.formats("rao") if f.sniffer])
def test_content_decides_for_an_unknown_extension(name, tmp_path):
    """A sample copied to an extension no format claims is still recognised by its first bytes:
    a failure means that format's sniffer misses its own files or another sniffer claims them."""
    path = tmp_path / "motions.dat"
    shutil.copyfile(SAMPLES[name][0](tmp_path), path)
    assert formats.detect(path, "rao").name == name


def test_unknown_formats_are_refused_listing_the_registered_ones(tmp_path):
    """What no format claims is refused with every registered format of its kind named (else the user
    cannot tell what would be read), and a format name of the other kind is not accepted."""
    notes = tmp_path / "notes.dat"
    notes.write_text("hello world\n")
    with pytest.raises(FileFormatError,
                       match=r"unknown RAO format '\.dat' \(nor does its content match one\); supported: ") as error:
        read_rao(notes)
    assert all(f"{f.name} ({f.description})" in str(error.value) for f in formats.formats("rao"))
    model = tmp_path / "model.fbx"
    model.write_text("not a mesh")
    with pytest.raises(FileFormatError,
                       match=r"unknown hull format '\.fbx' \(nor does its content match one\); supported: ") as error:
        load_hull(model)
    assert all(f.name in str(error.value) for f in formats.formats("mesh"))
    with pytest.raises(ParameterError, match="unknown RAO format 'gdf'; supported: wamit, veres, capytaine, native"):
        read_rao(TANKER_RAO, file_format="gdf")


def test_options_are_refused_by_formats_that_do_not_declare_them():
    """ULEN is WAMIT's and roll damping Capytaine's: another format given one must refuse it rather
    than ignore it; and read_rao must know the message of every option a format declares."""
    assert {option for f in formats.formats("rao") for option in f.options} == set(OPTION_LIMITS)
    assert read_rao(TANKER_RAO, ulen=2.0).source_format == "wamit"
    with pytest.raises(ParameterError, match="ULEN applies to WAMIT files only, not veres"):
        read_rao(S175, ulen=2.0)
    with pytest.raises(ParameterError, match="extra roll damping applies to Capytaine datasets only .*, not wamit"):
        read_rao(TANKER_RAO, roll_damping=0.05)


def test_registering_a_clash_is_refused():
    """Two formats claiming one name or one extension would make detection depend on order; a refused
    registration must leave the registry as it was."""
    before = formats.formats()
    with pytest.raises(ValueError, match="already registered"):
        formats.register(formats.Format("wamit", "rao", "again", (".w",), "marinesim.vessel.wamit:read_wamit"))
    with pytest.raises(ValueError, match=r"\.4 already read as 'wamit'"):
        formats.register(formats.Format("other", "rao", "other", (".4",), "marinesim.vessel.wamit:read_wamit"))
    assert formats.formats() == before


def test_listing_formats_imports_no_reader():
    """Listing the formats (``marinesim --help`` does, importing the packages that register them) must import
    neither numpy, trimesh nor any reader: a failure means a registering package pulls in the readers'
    dependencies when imported."""
    code = ("import sys, marinesim.vessel, marinesim.hull; from marinesim import formats; listed = formats.formats(); "
            "formats.extensions('mesh'); readers = {spec.partition(':')[0] for f in listed for spec in (f.reader, "
            "f.sniffer) if spec}; print(len(listed), sorted(m for m in sys.modules if m in readers or m.split('.')[0] "
            "in ('numpy', 'trimesh', 'scipy', 'xarray')))")
    result = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True,
                            env=os.environ | {"PYTHONPATH": str(ROOT)})
    assert result.stdout.strip() == f"{len(SAMPLES)} []"


@pytest.mark.parametrize("kind", sorted(formats.SIZE_LIMITS))
def test_every_kind_of_input_is_bounded_before_it_is_read(kind, tmp_path):
    """A file one byte over its kind's limit is refused in one line naming it, its size and the limit, before a
    byte of it is read (the file is sparse: nothing is allocated); one at the limit passes the check. If this
    fails, a kind of input can make marinesim read (and hold) a file of any size."""
    limit = formats.SIZE_LIMITS[kind]
    path = tmp_path / "input"
    with open(path, "wb") as file:
        file.truncate(limit + 1)
    with pytest.raises(MarinesimError) as refused:
        formats.check_file(path, kind)
    message = str(refused.value)
    assert "\n" not in message and str(path) in message and f"{limit + 1:,} bytes" in message, message
    assert f"{limit:,} bytes" in message and kind in message, message
    with open(path, "r+b") as file:
        file.truncate(limit)
    formats.check_file(path, kind)


def test_a_scenario_file_over_its_limit_is_refused_by_the_loader(tmp_path):
    """The scenario loader bounds its file too: 2 MiB of TOML is refused before it is parsed."""
    from marinesim.scenario import load_scenario

    path = tmp_path / "huge.toml"
    with open(path, "wb") as file:
        file.truncate(2 * formats.SIZE_LIMITS["scenario file"])
    with pytest.raises(MarinesimError, match="one scenario file may have"):
        load_scenario(path)


def test_a_file_read_again_gives_its_own_copy_and_a_changed_file_is_read_anew(tmp_path):
    """A VERES file read twice (parsed once, :func:`~marinesim.tokens.by_content`) gives equal tables, each the
    caller's own (changing one leaves the next read alone); the same bytes at another path, or through a link, name
    that path; rewritten in place with the same size and time stamp, it is read anew (a heave RAO changed in the
    file changes only heave in the table); made unreadable, it is refused each time. What would be wrong: a vessel
    moving with the RAOs of a file that has since changed, or one caller's edit showing in another's table."""
    path = tmp_path / "s175.re1"
    shutil.copyfile(S175, path)
    first, second = read_rao(path), read_rao(path)
    assert np.array_equal(first.values, second.values) and first.values is not second.values
    first.values[...] = 0.0
    assert np.array_equal(read_rao(path).values, second.values)
    elsewhere = tmp_path / "copy.re1"
    shutil.copyfile(S175, elsewhere)
    assert read_rao(elsewhere).source == str(elsewhere) and read_rao(path).source == str(path)
    link = tmp_path / "link.re1"
    link.symlink_to(path)
    assert read_rao(link).source == str(link) and read_rao(path).source == str(path), "each spelling its own name"

    lines = path.read_bytes().splitlines(keepends=True)
    stamp = os.stat(path).st_mtime_ns
    heave = next(i for i, line in enumerate(lines) if line.split()[:1] == [b"3"] and len(line.split()) == 3)
    real = lines[heave].split()[1]
    doubled = f"{2.0 * float(real):.8E}".encode()
    assert len(doubled) == len(real)
    before = read_rao(path)
    lines[heave] = lines[heave].replace(real, doubled, 1)  # the first heave RAO's real part doubled, in place
    path.write_bytes(b"".join(lines))
    os.utime(path, ns=(stamp, stamp))
    assert os.path.getsize(path) == os.path.getsize(elsewhere)
    after = read_rao(path)
    changed = np.argwhere(after.values != before.values)
    assert changed.size and set(changed[:, -1]) == {2}, "the changed file was not read again, or read wrong"

    path.write_bytes(b"\xff\xfe not a VERES file")
    for _ in range(2):
        with pytest.raises(FileFormatError):
            read_rao(path)
