"""The viewer: rendering the sea, the vessel and its wake (moderngl), cameras, HUD, video."""
