"""Writes hulls/barge_visual.glb: the box barge (100 x 20 m, 10 m deep, 5 m draft) with a deckhouse and a
mast aft, vertex-coloured, exported as CAD tools often do: centimetres, y up, origin at the keel at the
stern. In a scenario: visual_mesh_units = "cm", visual_mesh_axes = "x,-z,y", visual_mesh_offset_m = [-50, 0, -5].

Run from the repository root: python hulls/make/barge_visual.py
"""

from pathlib import Path

import numpy as np
import trimesh

PARTS = (  # body-frame corners (m, from the keel at the stern: x forward, y to port, z up) and RGB
    ((0.0, -10.0, 0.0), (100.0, 10.0, 5.0), (115, 23, 18)),  # bottom, keel to waterline: anti-fouling red
    ((0.0, -10.0, 5.0), (100.0, 10.0, 10.0), (26, 31, 41)),  # topsides up to the deck
    ((6.0, -8.0, 10.0), (18.0, 8.0, 22.0), (219, 219, 214)),  # deckhouse
    ((11.8, -0.2, 22.0), (12.2, 0.2, 30.0), (230, 180, 30)),  # mast, its top 25 m above the waterline
)
Y_UP_CM = np.array([[100.0, 0.0, 0.0], [0.0, 0.0, 100.0], [0.0, -100.0, 0.0]])  # body (x, y, z) m -> (x, z, -y) cm

if __name__ == "__main__":
    boxes = []
    for lower, upper, rgb in PARTS:
        box = trimesh.creation.box(bounds=[lower, upper])
        box.visual.vertex_colors = (*rgb, 255)
        boxes.append(box)
    model = trimesh.util.concatenate(boxes)
    model.vertices = model.vertices @ Y_UP_CM.T  # a rotation about x: the faces keep their outward side
    model.export(Path(__file__).resolve().parents[1] / "barge_visual.glb")
