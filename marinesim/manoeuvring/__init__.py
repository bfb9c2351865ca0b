"""Own-ship dynamics: a ship that answers her helm and her engine.

Manoeuvring models behind one interface (:class:`~marinesim.manoeuvring.ship.Model`): the MMG standard method
(:mod:`.mmg`), Son & Nomoto's 4-DOF container ship (:mod:`.container`), a model from main particulars
(:mod:`.clarke`); the steering gear and the engine (:mod:`.actuators`), the heading autopilot (:mod:`.autopilot`),
stepped together (:mod:`.ship`); a vessel without a model (:mod:`.station`); the voyage under orders given in time
(:mod:`.voyage`); the IMO standard manoeuvres (:mod:`.trials`, drawn by :mod:`.plot`). Axes: :mod:`.state`.
"""
