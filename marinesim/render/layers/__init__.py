"""The renderer's layers, one class per kind of surface data, each owning its GL resources, programs and uniforms.

Drawn passes: :mod:`~.sky`, :mod:`~.ocean` (the ring grid and the water's program), :mod:`~.vessel`.
Data the ocean samples: :mod:`~.cascades` (the tiles' fields and slopes), :mod:`~.foam` (the held
Jacobian), :mod:`~.wake` (the Kelvin wakes), :mod:`~.solver_field` (the local solver's height) and
:mod:`~.hull_mask` (no water inside the waterplane). :class:`~marinesim.render.renderer.Renderer`
composes them; :mod:`~.base` holds what they share.
"""
