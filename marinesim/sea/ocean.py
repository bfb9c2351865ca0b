"""The ocean: seeded wave components on FFT cascades, fields per frame, point sampling.

Every grid cell ``q`` of every tile is one Airy component (docs/CONVENTIONS.md)
``eta = Re{a exp(i(w t - q.x))}``, travelling towards ``q``, with ``w = w(|q|)`` from the
dispersion relation. Its complex amplitude is ``a = sqrt(E) xi``: ``E`` the cell's variance
(:func:`~marinesim.sea.cascades.cell_variances`), ``xi`` a seeded complex Gaussian with
``<|xi|^2> = 2`` (or ``sqrt(2) exp(i phi)`` for deterministic amplitudes with random phases).

The field of a tile is ``f(x) = sum_q F[q] exp(+i q.x)``, one inverse FFT, with the Hermitian
spectrum ``C[q] = (a[-q] e^{iwt} + conj(a[q]) e^{-iwt}) / 2`` for the height and

- horizontal (choppy) displacement ``D = i lambda (q/|q|) C`` (Gerstner: crests sharpen),
- slopes ``i q C``,
- displacement derivatives ``dDx/dx = -lambda qx^2/|q| C`` (and ``yy``, ``xy``) giving the
  Jacobian ``J = (1 + dDx/dx)(1 + dDy/dy) - (dDx/dy)^2`` (below 1 the surface is compressed,
  below 0 it folds: where waves break),

the eight real fields packed two per complex FFT (``F + iG`` is the spectrum of ``f + ig``).
Only the cells of each tile's band are touched per frame, and the tiles are split into lanes
(:mod:`marinesim.sea.synthesis`) that run side by side on worker threads, each pinned to CPUs
of its own.
"""

from __future__ import annotations

import functools
import math
from concurrent.futures import wait
from dataclasses import dataclass

import numpy as np

from marinesim.errors import (ParameterError, require_at_least, require_finite, require_memory, require_positive,
                             require_within)
from marinesim.recent import Recent
from marinesim.sea.cascades import Tile, cell_variances, choose_tiles, regular_tile
from marinesim.sea.dispersion import omega_from_k
from marinesim.sea.fft import available_cpus, mirrored
from marinesim.sea.kinds import CHOPPINESS_RANGE
from marinesim.sea.seastate import SeaState
from marinesim.sea.synthesis import Lane, lane_workers

FIELD_PAIRS = (("height", "displacement_xy"), ("displacement_x", "displacement_y"),
               ("slope_x", "slope_y"), ("1 + displacement_xx", "1 + displacement_yy"))
"""The real fields packed as (real, imaginary) parts of the four transforms per tile."""
BYTES_PER_CELL = 160
"""Memory per grid cell of every tile (bytes): noise and amplitudes (complex128, 32), the variance while it is
computed (8), the per-cell states kept over ramps (32), the four packed complex64 transforms, their FFT work
space and the Jacobian (~80), masks (~8)."""


@dataclass(frozen=True)
class TileFields:
    """The fields of one tile at one time, each ``[iy, ix]`` float32 on the tile's grid.

    Views into the ocean's buffers: the next :meth:`Ocean.fields` call overwrites them.
    """

    tile: Tile
    height: np.ndarray          # m
    displacement_x: np.ndarray  # m, horizontal (choppy) displacement, east
    displacement_y: np.ndarray  # m, north
    slope_x: np.ndarray         # d eta / dx
    slope_y: np.ndarray         # d eta / dy
    jacobian: np.ndarray        # of the horizontal map x -> x + D


@dataclass(frozen=True)
class Components:
    """Wave components ``eta = Re sum a exp(i(w t - kx x - ky y))`` (rad/s, rad/m, m)."""

    omega: np.ndarray
    kx: np.ndarray
    ky: np.ndarray
    amplitude: np.ndarray  # complex, m
    tile: np.ndarray       # index of the tile each component lives on

    @functools.cached_property
    def direction(self) -> np.ndarray:
        """The math angle (rad, E frame) each component travels towards, (n,), read-only: ``atan2(ky, kx)``."""
        out = np.arctan2(self.ky, self.kx)
        out.flags.writeable = False
        return out

    @property
    def variance(self) -> float:
        """Expected elevation variance ``sum |a|^2 / 2`` (m^2)."""
        return float(np.sum(np.abs(self.amplitude) ** 2) / 2.0)

    def __len__(self) -> int:
        return self.omega.size

    def elevation(self, x: float, y: float, times: np.ndarray, chunk: int = 256) -> np.ndarray:
        """Elevation (m) at the fixed point (x, y) (m, E frame) at each of ``times`` (s)."""
        times = np.asarray(times, dtype=float)
        at_point = self.amplitude * np.exp(-1j * (self.kx * x + self.ky * y))
        out = np.empty(times.size)
        for lo in range(0, times.size, chunk):
            hi = min(lo + chunk, times.size)
            out[lo:hi] = (np.exp(1j * np.outer(times[lo:hi], self.omega)) @ at_point).real
        return out


@dataclass(frozen=True)
class PointSample:
    """Elevation (m), choppy displacement (m) and slopes at points, by direct summation."""

    elevation: np.ndarray
    displacement_x: np.ndarray
    displacement_y: np.ndarray
    slope_x: np.ndarray
    slope_y: np.ndarray


@dataclass(frozen=True, eq=False)
class PreparedSea:
    """A sea state with the amplitude of every cell of ``ocean`` computed (:meth:`Ocean.prepare`)."""

    ocean: Ocean
    sea: SeaState
    amplitudes: np.ndarray  # complex, m, (tiles, N, N)


@dataclass(frozen=True)
class _Ramp:
    start: float
    duration: float
    source: int  # state at the ramp's start
    target: int  # state after the ramp: its sea's amplitudes


@dataclass(frozen=True)
class _Frozen:
    """A state that is the blend ``state[before] + weight (state[after] - state[before])``, frozen when a ramp
    started during another one."""

    before: int
    after: int
    weight: float


class Ocean:
    """Seeded random sea on FFT cascades; fields and point samples are pure functions of t.

    ``tiles`` default to :func:`choose_tiles` (``tile_count`` cascades of ``resolution``^2).
    ``random_amplitudes=False`` gives deterministic amplitudes ``sqrt(2 E)`` with random
    phases. ``choppiness`` scales the horizontal displacement (1 = Gerstner). ``threads``
    (default: every CPU the process may use) synthesise the fields, one lane of tiles each, each
    lane's thread pinned to CPUs of its own; with one lane the calling thread does the work.
    """

    def __init__(
        self,
        sea: SeaState,
        *,
        tiles: list[Tile] | None = None,
        tile_count: int = 4,
        resolution: int = 256,
        seed: int = 0,
        random_amplitudes: bool = True,
        choppiness: float = 1.0,
        fft_backend: str = "auto",
        threads: int | None = None,
    ) -> None:
        if isinstance(seed, bool) or not isinstance(seed, (int, np.integer)) or seed < 0:
            raise ParameterError(f"seed must be a non-negative integer, got {seed!r}")
        self.sea = sea
        self.seed = int(seed)
        self.tiles = list(tiles) if tiles is not None else choose_tiles(sea, tile_count, resolution)
        sizes = {t.resolution for t in self.tiles}
        if len(sizes) != 1:
            raise ParameterError(f"all tiles must share one resolution, got {sorted(sizes)}")
        self.resolution = sizes.pop()
        require_memory(f"an ocean of {len(self.tiles)} tiles of {self.resolution}^2",
                       BYTES_PER_CELL * len(self.tiles) * self.resolution**2)
        self._noise = np.stack([self._tile_noise(i, random_amplitudes) for i in range(len(self.tiles))])
        self._amplitude0, self.represented_m0 = self._amplitudes_for(sea)
        """Expected variance (m^2) the tiles carry of the initial sea: sum of cell variances."""
        self.m0_fraction = self.represented_m0 / sea.moment(0)
        """Fraction of the sea state's m0 that the tiles carry."""
        self._ramps: list[_Ramp] = []
        self._kinds: list[SeaState | _Frozen] = [sea]
        """What each state is: a sea's amplitudes, or a blend of two earlier states frozen at a ramp's start."""
        self._states = Recent(self._state)
        """Amplitudes of every cell in states 0, 1, 2, ... (the newest kept, older recomputed)."""
        self._used = self._amplitude0 != 0
        self._used |= mirrored(self._used)
        self._choppiness = require_within("choppiness", choppiness, *CHOPPINESS_RANGE)
        if threads is None:
            threads = len(available_cpus())
        if isinstance(threads, bool) or not isinstance(threads, (int, np.integer)) or threads < 1:
            raise ParameterError(f"threads must be a positive integer, got {threads!r}")
        self._threads = int(threads)
        self.lane_count = min(self._threads, len(self.tiles))
        """Lanes of tiles synthesised in parallel, one per thread."""
        self._workers = lane_workers(self.lane_count) if self.lane_count > 1 else []
        groups = np.array_split(np.arange(len(self.tiles)), self.lane_count)
        self._lanes = [Lane(int(g[0]), g.size, self.resolution, fft_backend, max(1, self._threads // len(groups)))
                       for g in groups]
        self._index_cells()
        self._settle()

    # -- construction ---------------------------------------------------------------------

    def _tile_noise(self, index: int, random_amplitudes: bool) -> np.ndarray:
        """Seeded ``xi`` per cell: depends on (seed, tile index, N) only, not on the sea state."""
        n = self.resolution
        rng = np.random.default_rng([self.seed, index])
        if not random_amplitudes:
            return math.sqrt(2.0) * np.exp(1j * rng.uniform(0.0, 2.0 * math.pi, (n, n)))
        return rng.standard_normal((n, n)) + 1j * rng.standard_normal((n, n))

    def _amplitudes_for(self, sea: SeaState) -> tuple[np.ndarray, float]:
        """Complex amplitude of every cell, shape (tiles, N, N): ``sqrt(E) xi``, regular waves exact.

        Also returns the expected variance the tiles carry (m^2): the sum of the cell variances.
        """
        self.check(sea)
        variance = np.stack([cell_variances(tile, sea) for tile in self.tiles])
        amplitude = np.sqrt(variance) * self._noise
        for wave in sea.regular_waves:
            tile = regular_tile(wave, sea, self.resolution)
            ix, iy = tile.wave_index
            amplitude[self.tiles.index(tile), iy % self.resolution, ix % self.resolution] += (
                0.5 * wave.height * np.exp(1j * wave.phase))
        return amplitude, float(variance.sum()) + sum(w.variance for w in sea.regular_waves)

    def _index_cells(self) -> None:
        """Flat per-frame arrays over the cells that carry a wave in any state.

        The cells are ordered as ``h`` representatives followed by their mirrors ``-q`` in the
        same order, so ``C`` is computed for half of them and conjugated for the rest.
        """
        n = self.resolution
        tile, iy, ix = np.nonzero(self._used)
        mirror_iy, mirror_ix = (-iy) % n, (-ix) % n
        first = (iy * n + ix) < (mirror_iy * n + mirror_ix)  # DC and Nyquist cells are never used
        tile = np.concatenate([tile[first], tile[first]])
        iy = np.concatenate([iy[first], mirror_iy[first]])
        ix = np.concatenate([ix[first], mirror_ix[first]])
        self._cell = (tile, iy, ix)
        self._half = int(np.count_nonzero(first))
        qx = np.empty(tile.size)
        qy = np.empty(tile.size)
        for t, spec_tile in enumerate(self.tiles):
            on = tile == t
            gx, gy = spec_tile.wavenumbers()
            qx[on], qy[on] = gx[iy[on], ix[on]], gy[iy[on], ix[on]]
        self._qx, self._qy = qx, qy
        self._omega = omega_from_k(np.hypot(qx, qy), self.sea.depth, self.sea.g)
        self._multipliers = self._multipliers_for(qx, qy)
        self._lane_cells = self._assign_cells(n)

    def _settle(self) -> None:
        """Keep the spectrum's parts after the last ramp: every frame after it reuses them."""
        newest = len(self._kinds) - 1  # the last ramp's target
        self._settled_amplitudes = self._half_amplitudes(self._states.get(newest, newest)[self._cell])

    def _assign_cells(self, n: int) -> list[tuple[slice, np.ndarray]]:
        """Give each lane its cells. Per lane: the slice of its representative cells and the
        indices of all its cells (representatives, then mirrors) into the flat cell arrays."""
        tile, iy, ix = self._cell
        h = self._half
        bounds = np.searchsorted(tile[:h], [lane.first for lane in self._lanes] + [len(self.tiles)])
        assigned = []
        for lane, lo, hi in zip(self._lanes, bounds[:-1], bounds[1:], strict=True):
            cells = np.r_[lo:hi, h + lo:h + hi]
            lane.set_cells(self._omega[lo:hi], self._multipliers[:, cells], tile[cells] - lane.first,
                           iy[cells] * n + ix[cells])
            assigned.append((slice(lo, hi), cells))
        return assigned

    def _multipliers_for(self, qx: np.ndarray, qy: np.ndarray) -> np.ndarray:
        """Complex multipliers turning C into the four packed spectra (see FIELD_PAIRS)."""
        lam = self._choppiness
        q = np.hypot(qx, qy)
        q = np.where(q > 0, q, 1.0)
        return np.stack([
            1.0 - 1j * lam * qx * qy / q,
            1j * lam * qx / q - lam * qy / q,
            1j * qx - qy,
            -lam * qx**2 / q - 1j * lam * qy**2 / q,
        ]).astype(np.complex64)

    def _half_amplitudes(self, amplitude: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """The cosine and sine parts of ``C[q] = (a[-q] e^{iwt} + conj(a[q]) e^{-iwt}) / 2`` for the
        representative cells: ``(a[-q] + conj(a[q])) / 2`` and ``i (a[-q] - conj(a[q])) / 2``."""
        h = self._half
        plus, minus = 0.5 * amplitude[h:], 0.5 * np.conj(amplitude[:h])
        return (plus + minus).astype(np.complex64), (1j * (plus - minus)).astype(np.complex64)

    # -- state over time ------------------------------------------------------------------

    @property
    def choppiness(self) -> float:
        return self._choppiness

    @choppiness.setter
    def choppiness(self, value: float) -> None:
        self._choppiness = require_within("choppiness", value, *CHOPPINESS_RANGE)
        self._multipliers = self._multipliers_for(self._qx, self._qy)
        for lane, (_, cells) in zip(self._lanes, self._lane_cells, strict=True):
            lane.set_multipliers(self._multipliers[:, cells])

    def check(self, sea: SeaState) -> None:
        """Refuse a sea this ocean cannot ramp to (a new depth, a regular wave off its tiles); cheap."""
        if sea.depth != self.sea.depth:
            raise ParameterError("the depth cannot change while the ocean runs")
        for wave in sea.regular_waves:
            if regular_tile(wave, sea, self.resolution) not in self.tiles:
                raise ParameterError(
                    f"the ocean's tiles cannot carry a regular wave of {wave.period:g} s in this "
                    "direction (build the ocean with it, ramps change heights only)"
                )

    def prepare(self, sea: SeaState) -> PreparedSea:
        """The amplitudes :meth:`ramp_to` needs for ``sea`` (the costly part of a change: the
        cells' variances). Safe to call on another thread while the ocean runs, as the viewer
        does so that a live change costs its frames nothing: it reads only what never changes."""
        return PreparedSea(self, sea, self._amplitudes_for(sea)[0])

    def ramp_to(self, sea: SeaState | PreparedSea, start: float, duration: float) -> None:
        """Change to ``sea`` smoothly over ``[start, start + duration]`` s (smoothstep in time).

        The tiles and the seeded noise stay, so the surface changes shape without a jump: each
        cell's amplitude moves from its value at ``start`` to its new value. A ramp may start while
        the previous one is under way (not before that one's start): it then starts from the blend
        of the moment, and the previous ramp ends there.
        """
        start = require_finite("ramp start", start)
        duration = require_positive("ramp duration", duration)
        if self._ramps and start < self._ramps[-1].start:
            raise ParameterError("a sea-state ramp must not start before the previous one's start "
                                 f"({self._ramps[-1].start:g} s), got {start:g} s")
        prepared = sea if isinstance(sea, PreparedSea) else self.prepare(sea)
        if prepared.ocean is not self:
            raise ParameterError("a sea prepared by another ocean cannot ramp this one")
        before, after, weight = self.blend(start)
        if before == after or weight == 0.0:
            source = before
        else:  # under way: its blend at ``start`` becomes a state of its own
            frozen = self._mix(before, after, weight)  # the amplitudes at ``start``, to the bit
            source = len(self._kinds)
            self._kinds.append(_Frozen(before, after, weight))
            self._states.put(source, frozen)
        self._kinds.append(prepared.sea)
        self._ramps.append(_Ramp(start, duration, source, len(self._kinds) - 1))
        self._states.put(len(self._kinds) - 1, prepared.amplitudes)
        used = prepared.amplitudes != 0
        used |= mirrored(used)
        if np.any(used & ~self._used):  # new cells: every per-cell array grows
            self._used |= used
            self._index_cells()
        self._settle()

    def _state(self, index: int) -> np.ndarray:
        """Complex amplitude of every cell in state ``index``, shape (tiles, N, N)."""
        if index == 0:
            return self._amplitude0
        kind = self._kinds[index]
        if isinstance(kind, _Frozen):
            return self._mix(kind.before, kind.after, kind.weight)
        return self._amplitudes_for(kind)[0]

    def _mix(self, before: int, after: int, weight: float) -> np.ndarray:
        """``state[before] + weight (state[after] - state[before])``, shape (tiles, N, N)."""
        newest = len(self._kinds) - 1
        state = self._states.get(after, newest)
        if before == after:
            return state
        earlier = self._states.get(before, newest)
        return earlier + weight * (state - earlier)

    def amplitudes(self, t: float) -> np.ndarray:
        """Complex amplitude of every cell at time ``t`` (s), shape (tiles, N, N).

        Only the newest states stay in memory, so live changes do not add up: a time in an older
        ramp costs recomputing its states (``cell_variances``), to the same bits.
        """
        return self._mix(*self.blend(t))

    def blend(self, t: float) -> tuple[int, int, float]:
        """The amplitudes at ``t`` (s) as states: ``(before, after, weight)``, the amplitudes being
        ``state[before] + weight (state[after] - state[before])``, and ``before == after`` (weight 0)
        outside a ramp. A state is an int id, always the same amplitudes (:meth:`spectrum_state`): 0
        the initial sea, then each ramp's sea, and the blend of the moment where a ramp started
        during another."""
        started = sum(1 for ramp in self._ramps if t > ramp.start)
        if started == 0:
            return 0, 0, 0.0
        ramp = self._ramps[started - 1]
        s = (t - ramp.start) / ramp.duration
        if s >= 1.0:
            return ramp.target, ramp.target, 0.0
        return ramp.source, ramp.target, float(smoothstep(s))

    def spectrum_state(self, state: int) -> np.ndarray:
        """The cosine and sine parts of every cell's ``C[q]`` (see :meth:`_half_amplitudes`) in state ``state``,
        on the full grid (mirror cells ``C[-q] = conj(C[q])`` included): float32 (tiles, N, N, 4) of
        ``(even.real, even.imag, odd.real, odd.imag)``, m. What the GPU synthesis takes at a sea change."""
        amplitude = self._states.get(state, len(self._kinds) - 1)
        plus, minus = 0.5 * mirrored(amplitude), 0.5 * np.conj(amplitude)
        even, odd = plus + minus, 1j * (plus - minus)
        return np.stack([even.real, even.imag, odd.real, odd.imag], axis=-1).astype(np.float32)

    def grid_omega(self) -> np.ndarray:
        """Circular frequency ``w(|q|)`` of every cell of every tile (rad/s), float64 (tiles, N, N)."""
        return np.stack([omega_from_k(np.hypot(*tile.wavenumbers()), self.sea.depth, self.sea.g)
                         for tile in self.tiles])

    def _settled(self, t: float) -> bool:
        """Whether ``t`` (s) is after the last ramp (or there is none): the amplitudes no longer change."""
        return not self._ramps or t >= self._ramps[-1].start + self._ramps[-1].duration

    # -- fields per frame -----------------------------------------------------------------

    def fields(self, t: float, reproducible: bool = False) -> list[TileFields]:
        """All fields of every tile at time ``t`` (s): 4 inverse FFTs per tile, the lanes in parallel.

        ``reproducible``: by numpy.fft instead of the planned FFTW (4-5x slower: for reports and
        plots, not frames), the same bits whatever the saved plans, the cache and the CPU count.
        """
        if self._settled(t):
            even, odd = self._settled_amplitudes
        else:
            even, odd = self._half_amplitudes(self.amplitudes(t)[self._cell])
        rows = [r for r, _ in self._lane_cells]
        if self._workers:
            running = [worker.submit(lane.run, t, even[r], odd[r], reproducible)
                       for worker, lane, r in zip(self._workers, self._lanes, rows, strict=True)]
            wait(running)  # every lane done before a result is read (or its error raised)
            outputs = [future.result() for future in running]
        else:
            outputs = [self._lanes[0].run(t, even[rows[0]], odd[rows[0]], reproducible)]
        return [
            TileFields(self.tiles[lane.first + i], out[i, 0].real, out[i, 1].real, out[i, 1].imag,
                       out[i, 2].real, out[i, 2].imag, jacobian[i])
            for lane, (out, jacobian) in zip(self._lanes, outputs, strict=True) for i in range(lane.count)
        ]

    # -- components and direct summation --------------------------------------------------

    def components(self, t: float = 0.0, variance_fraction: float = 1.0) -> Components:
        """The wave components at time ``t`` (amplitudes change only during ramps).

        ``variance_fraction < 1`` keeps only the largest components that together carry at
        least that fraction of the variance (the vessel response needs far fewer than the FFT).
        """
        fraction = require_at_least("variance fraction", variance_fraction, 0.0)
        if not 0.0 < fraction <= 1.0:
            raise ParameterError(f"variance fraction must be in (0, 1], got {variance_fraction!r}")
        amplitude = self.amplitudes(t)[self._cell]
        power = np.abs(amplitude) ** 2
        keep = np.flatnonzero(power > 0)
        if fraction < 1.0:
            order = keep[np.argsort(power[keep])[::-1]]
            cumulative = np.cumsum(power[order])
            count = int(np.searchsorted(cumulative, fraction * cumulative[-1])) + 1
            keep = np.sort(order[:count])
        return Components(self._omega[keep], self._qx[keep], self._qy[keep], amplitude[keep],
                          self._cell[0][keep])

    def sample(self, x: np.ndarray, y: np.ndarray, t: float, tiles: list[int] | None = None,
               chunk: int = 2048) -> PointSample:
        """Elevation, displacement and slopes at points ``(x, y)`` (m, E frame) by direct summation.

        ``tiles`` restricts the sum to those tiles' components (to compare with one FFT field).
        """
        x = np.asarray(x, dtype=float).ravel()
        y = np.asarray(y, dtype=float).ravel()
        c = self.components(t)
        if tiles is not None:
            on = np.isin(c.tile, tiles)
            c = Components(c.omega[on], c.kx[on], c.ky[on], c.amplitude[on], c.tile[on])
        k = np.hypot(c.kx, c.ky)
        lam = self._choppiness
        fields = np.zeros((5, x.size))
        weights = np.stack([np.ones_like(k), -1j * lam * c.kx / k, -1j * lam * c.ky / k,
                            -1j * c.kx, -1j * c.ky]) * (c.amplitude * np.exp(1j * c.omega * t))
        for lo in range(0, x.size, chunk):
            hi = min(lo + chunk, x.size)
            waves = np.exp(-1j * (np.outer(x[lo:hi], c.kx) + np.outer(y[lo:hi], c.ky)))
            fields[:, lo:hi] = (waves @ weights.T).real.T
        return PointSample(*fields)


def smoothstep(s: float | np.ndarray) -> float | np.ndarray:
    """The weight ``3 s^2 - 2 s^3`` of the new state at fraction ``s`` of a ramp (0 to 1, flat at both ends)."""
    return 3.0 * s * s - 2.0 * s**3
