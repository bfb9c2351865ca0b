"""A ship drawn from a hull alone (marinesim/render/vessel_mesh.py): what a scenario without a visual mesh shows.

Checked by casting rays through the drawn triangles from the bridge point, as the bridge camera looks,
and by the paint where a deck officer would look for it. What would be wrong: an eye outside the wheelhouse or
inside a wall, wings that stop short of the ship's side (no view down her side when berthing), a funnel hidden in
the house, the boot-top missing, a deck layout key that changes nothing."""

from __future__ import annotations

import numpy as np
import pytest

from conftest import DEFAULT, ray_hits
from marinesim.render.vessel_mesh import (BOOT_TOP, BOOT_TOP_M, BOTTOM, FUNNEL, HATCH, HOUSE, WINDOW, VesselMesh,
                                          vessel_mesh)
from marinesim.scenario import load_scenario


@pytest.fixture(scope="module")
def tanker():
    vessel = load_scenario(DEFAULT).vessel
    return vessel.hull, tuple(vessel.points["bridge"])


def colours_of(mesh: VesselMesh) -> np.ndarray:
    return mesh.colours.reshape(-1, 3, 3)[:, 0]


def first_hit(mesh: VesselMesh, origin, direction) -> tuple[float, np.ndarray]:
    """Distance (m) to the first triangle along the ray, and its colour."""
    t, faces = ray_hits(mesh.positions.reshape(-1, 3, 3), origin, direction)
    assert len(t), f"the ray from {origin} along {direction} misses the ship"
    return float(t[0]), colours_of(mesh)[faces[0]]


def test_the_bridge_camera_looks_out_of_a_wheelhouse_window(tanker):
    hull, bridge = tanker
    mesh = vessel_mesh(hull, house_at=bridge)
    ahead, colour = first_hit(mesh, bridge, (1.0, 0.0, 0.0))
    assert 1.5 < ahead < 2.5 and np.allclose(colour, WINDOW), "the eye is not 2 m behind the front windows"
    above, _ = first_hit(mesh, bridge, (0.0, 0.0, 1.0))
    below, _ = first_hit(mesh, bridge, (0.0, 0.0, -1.0))
    assert above < 1.0 and below < 1.0, "the eye is not in the window band (a wall or no wheelhouse around it)"


def test_wings_reach_the_side_and_the_funnel_stands_over_the_house(tanker):
    hull, bridge = tanker
    mesh = vessel_mesh(hull, house_at=bridge)
    corners, colours = mesh.positions.reshape(-1, 3, 3), colours_of(mesh)
    beam = float(np.ptp(hull.vertices[:, 1]))
    house = corners[np.all(colours == HOUSE, axis=1)]
    assert np.abs(house[..., 1]).max() >= 0.5 * beam, "the bridge wings stop short of the ship's side"
    funnel = corners[np.all(colours == FUNNEL, axis=1)]
    assert funnel[..., 2].max() > house[..., 2].max() + 2.0, "the funnel does not stand over the house"
    assert funnel[..., 0].max() < house[..., 0][house[..., 1].max(axis=1) < 0.4 * beam].min() + 1e-6, (
        "the funnel is not abaft the accommodation")


def test_the_hull_is_painted_bottom_boot_top_and_topsides(tanker):
    hull, bridge = tanker
    topsides = (0.2, 0.3, 0.5)
    mesh = vessel_mesh(hull, house_at=bridge, topsides=topsides)
    corners, colours = mesh.positions.reshape(-1, 3, 3), colours_of(mesh)
    side = (np.abs(np.cross(corners[:, 1] - corners[:, 0], corners[:, 2] - corners[:, 0])[:, 2]) < 1e-6)
    z = corners[..., 2].mean(axis=1)
    for low, high, paint in ((-30.0, BOOT_TOP_M[0], BOTTOM), (BOOT_TOP_M[0], BOOT_TOP_M[1], BOOT_TOP),
                             (BOOT_TOP_M[1], 5.0, topsides)):
        band = side & (z > low) & (z < high) & ~np.all(colours == HOUSE, axis=1)
        assert band.any() and np.all(np.isclose(colours[band], paint).all(axis=1) | np.isclose(
            colours[band], HATCH).all(axis=1) | np.isclose(colours[band], FUNNEL).all(axis=1)), (low, high)


def test_a_hatches_deck_has_hatch_covers_and_a_flat_one_none(tanker):
    hull, bridge = tanker
    flat = colours_of(vessel_mesh(hull, house_at=bridge))
    hatches = vessel_mesh(hull, house_at=bridge, deck_layout="hatches")
    covers = hatches.positions.reshape(-1, 3, 3)[np.all(colours_of(hatches) == HATCH, axis=1)]
    assert not np.all(flat == HATCH, axis=1).any()
    length = float(np.ptp(hull.vertices[:, 0]))
    assert covers.size and np.ptp(covers[..., 0]) > 0.5 * length, "hatch covers over less than half the length"
    assert covers[..., 0].min() > bridge[0], "hatch covers abaft the bridge of an aft-bridge ship"
