"""The waterplane: the waterline loops of a hull from trimesh's section, and the cells inside them.

The loops give the viewer's hull mask (no water drawn inside the hull) and the topsides of open
hulls; a waterline that assumed one star-shaped loop would join a catamaran's two hulls across
the water between them.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from marinesim.hull import box_hull, hydrostatics, load_hull, make_hull, wigley_hull
from marinesim.hull.waterplane import inside, signed_area, waterline_loops
from marinesim.render.vessel_mesh import vessel_mesh

from conftest import ROOT


def catamaran(separation: float = 30.0):
    """Two Wigley demi-hulls (100 m x 10 m) with their centrelines ``separation`` apart, one closed mesh each."""
    hull = wigley_hull()
    shift = np.array([0.0, separation / 2.0, 0.0])
    vertices = np.concatenate([hull.vertices + shift, hull.vertices - shift])
    faces = np.concatenate([hull.faces, hull.faces + len(hull.vertices)])
    return make_hull(vertices, faces, "catamaran")


def test_a_box_barge_waterline_is_its_rectangle():
    """A 100 x 20 m box: one loop, counter-clockwise seen from above, enclosing 2000 m^2 (the waterplane)."""
    (loop,) = waterline_loops(box_hull(100.0, 20.0, 5.0))
    assert signed_area(loop) == pytest.approx(2000.0, rel=1e-6)
    assert np.ptp(loop[:, 0]) == pytest.approx(100.0) and np.ptp(loop[:, 1]) == pytest.approx(20.0)


def test_the_wigley_waterline_encloses_its_analytic_waterplane():
    """Wigley's waterline y = (B/2)(1 - (2x/L)^2) encloses 2 B L / 3 (= 666.7 m^2 for 100 x 10 m); the
    polygon through the mesh's waterline points falls short only by the chords between them."""
    (loop,) = waterline_loops(wigley_hull())
    assert signed_area(loop) == pytest.approx(2.0 * 10.0 * 100.0 / 3.0, rel=2e-3)


def test_a_wetted_surface_mesh_open_at_the_waterline_gives_its_loop():
    """The WAMIT tanker's .gdf holds only the wetted surface, open exactly at z = 0: its loop still encloses
    the waterplane area, as the divergence theorem gives it from the wetted surface alone (within 0.5 %)."""
    hull = load_hull(ROOT / "hulls" / "tanker.gdf")
    (loop,) = waterline_loops(hull)
    assert signed_area(loop) == pytest.approx(hydrostatics(hull).waterplane_area_m2, rel=5e-3)


def test_a_catamaran_has_two_loops_and_the_water_between_them_stays_water():
    """Two demi-hulls 30 m apart: two loops, each a demi-hull's waterplane; the mask covers both hulls and
    leaves the 20 m of water between them (a single star-shaped outline would have covered it)."""
    hull = catamaran(30.0)
    loops = waterline_loops(hull)
    assert len(loops) == 2
    assert sorted(np.mean(loop[:, 1]) for loop in loops) == pytest.approx([-15.0, 15.0], abs=1e-6)
    for loop in loops:
        assert signed_area(loop) == pytest.approx(2000.0 / 3.0, rel=2e-3)
    x, y = np.array([0.0]), np.array([-15.0, -5.0, 0.0, 5.0, 15.0])
    assert inside(loops, x, y)[:, 0].tolist() == [True, False, False, False, True]


def test_an_open_catamaran_gets_topsides_on_each_hull_and_none_over_the_gap():
    """Drawn topsides and deck come from each loop: no deck triangle lies over the water between the hulls."""
    hull = catamaran(30.0)
    wet = hull.vertices[:, 2] <= 0.0
    faces = hull.faces[wet[hull.faces].all(axis=1)]
    open_hull = make_hull(hull.vertices, faces, "open catamaran")
    mesh = vessel_mesh(open_hull)
    deck = mesh.positions[mesh.positions[:, 2] > 0.1]
    assert len(deck) > 0 and np.all(np.abs(np.abs(deck[:, 1]) - 15.0) <= 5.0 + 1e-6)


def test_the_mask_is_the_union_of_the_loops():
    """Overlapping obstacles (a quay and a pier on it) stay land where they overlap, as the solver needs."""
    square = np.array([[0.0, 0.0], [10.0, 0.0], [10.0, 10.0], [0.0, 10.0]])
    mask = inside([square, square + 5.0], np.array([2.0, 7.0, 12.0, 20.0]), np.array([7.0]))
    assert mask[0].tolist() == [True, True, True, False]
    assert math.isclose(signed_area(square[::-1]), -100.0)
