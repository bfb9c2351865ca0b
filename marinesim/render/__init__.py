"""The viewer: rendering the sea, the vessel and its wake (moderngl), cameras, HUD, video."""

from marinesim.views import CAMERAS

CASCADES = ("auto", "gpu", "cpu")
"""Where the ocean's cascades are synthesised each frame (``RenderOptions.cascades``)."""
HUDS = ("strip", "panels", "off")
"""What the HUD shows at first (``RenderOptions.hud``): a compact strip of the figures that matter, the full panels
(text block, strip charts, every criterion), or nothing; TAB toggles strip and panels in the window."""
