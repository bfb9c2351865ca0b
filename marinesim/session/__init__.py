"""The session layer: a scenario assembled once, its timeline, the export and the headless run.

Everything above the physics calls this: the viewer and the offscreen renders (through the
timeline's :class:`~marinesim.session.timeline.Simulation`), ``marinesim export`` and
``marinesim run`` without a display. It imports the physics packages and never the renderer.
"""
