"""The world around own-ship: other vessels and structures on their routes, the crane and its load, the helicopter,
and the geometry of traffic (closest point of approach, COLREG encounters)."""
