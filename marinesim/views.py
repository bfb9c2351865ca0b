"""The viewer's own cameras by name: the scenario's named cameras (``[[cameras]]``) take other names, and the
renderer makes these three for every scene."""

CAMERAS = ("orbit", "bridge", "free")
"""Orbiting the vessel, on her bridge, flying free (keys 1, 2, 3)."""
