"""The served exercise (:mod:`~marinesim.net.server`: an instructor's web page and the stations of
:mod:`~marinesim.net.station`) and own-ship's state out to real equipment: NMEA 0183 (:mod:`~marinesim.net.nmea`)
and DIS (:mod:`~marinesim.net.dis`) over UDP (:mod:`~marinesim.net.streams`), placed on WGS84
(:mod:`~marinesim.net.geo`). The protocol and the outputs: ``docs/NETWORK.md``."""
