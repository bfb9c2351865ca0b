"""The HUD's radar picture on Mesa's software OpenGL: a contact lands where her bearing and range put her on the
scope, own ship sits at the centre on her heading, the range rings at their radii, the panel keeps to its corner
clear of the other panels, and a frame without a radar has none of it; the rings' intervals and the CPA line."""

from __future__ import annotations

import math

import numpy as np
import pytest

from marinesim.constants import NAUTICAL_MILE as NM
from marinesim.render.hud import (ALARM_COLOR, CONTACT_COLOR, DANGER_COLOR, OWN_SHIP_COLOR, RADAR_PANEL_COLOR,
                                  RING_COLOR, Banner, Contact, Footprint, Hud, Radar, Slider, StripChart,
                                  font_px_for, ring_interval_m)

SMALL = (640, 360)
BACKGROUND = (0.2, 0.2, 0.9)
"""The frames' clear colour: blue, so that the dark panels show against it."""


@pytest.fixture(scope="module")
def ctx(gl_context):
    yield gl_context
    _targets.clear()  # the framebuffers go before their context


@pytest.fixture(scope="module")
def huds(ctx):
    made = {size: Hud(ctx, font_px_for(size)) for size in (SMALL, (1280, 720))}
    yield made
    for hud in made.values():
        hud.release()


_targets: dict[tuple[int, int], object] = {}


def render(ctx, hud: Hud, size: tuple[int, int], **kwargs) -> np.ndarray:
    """``hud.draw(size, [], **kwargs)`` on the blue background, as (h, w, 3) uint8 with row 0 at the top."""
    if size not in _targets:
        _targets[size] = ctx.simple_framebuffer(size)
    fbo = _targets[size]
    fbo.use()
    fbo.clear(*BACKGROUND, 1.0)
    hud.draw(size, kwargs.pop("lines", []), **kwargs)
    assert ctx.error == "GL_NO_ERROR"
    return np.frombuffer(fbo.read(components=3), np.uint8).reshape(size[1], size[0], 3)[::-1]


def colored(image: np.ndarray, color, tolerance: int = 12) -> np.ndarray:
    """Pixels of an opaque ``color`` (lines, symbols)."""
    return (np.abs(image.astype(int) - np.round(np.array(color[:3]) * 255)) <= tolerance).all(axis=2)


def over_background(color) -> tuple[float, ...]:
    """A translucent panel colour as it shows on the blue background."""
    alpha = color[3]
    return tuple(alpha * c + (1 - alpha) * b for c, b in zip(color[:3], BACKGROUND))


def scope_of(hud: Hud, size: tuple[int, int]) -> tuple[float, float, float]:
    rect = hud.radar_rect(size)
    assert rect is not None
    return hud.radar_scope(*rect)


def still_radar(contacts=(), heading_deg: float = 0.0, range_m: float = 2 * NM) -> Radar:
    """Own ship stopped (no vector), no track."""
    return Radar(heading_deg, np.zeros(2), np.empty((0, 2)), range_m, tuple(contacts))


@pytest.mark.parametrize("east, north", [(1.0, 0.0), (0.0, 1.5)])
def test_a_contact_due_east_at_half_range_is_drawn_there(ctx, huds, east, north):
    """A stopped, unnamed contact 1 nm due east on the 2 nm scale: what she adds to the frame is her triangle,
    centred half the outer ring's radius right of the scope's centre on its row; one 1.5 nm due north, three
    quarters of it above the centre (a compass bearing read as a math angle, or north drawn downwards, would put
    them elsewhere; so would a range scaled to the panel, not the ring)."""
    hud = huds[SMALL]
    cx, cy, radius = scope_of(hud, SMALL)
    contact = Contact("", np.array([east * NM, north * NM]), np.zeros(2), 0.0)
    empty = render(ctx, hud, SMALL, radar=still_radar()).astype(int)
    with_contact = render(ctx, hud, SMALL, radar=still_radar([contact])).astype(int)
    rows, cols = np.nonzero(np.abs(with_contact - empty).sum(axis=2) > 30)
    assert rows.size > 10
    expected = (cx + east / 2 * radius, cy - north / 2 * radius)
    assert abs(cols.mean() + 0.5 - expected[0]) < 1.0 and abs(rows.mean() + 0.5 - expected[1]) < 1.0
    assert np.ptp(cols) <= hud.line_height and np.ptp(rows) <= hud.line_height
    assert colored(with_contact, CONTACT_COLOR)[rows, cols].mean() > 0.9


@pytest.mark.parametrize("heading_deg", [0.0, 90.0])
def test_own_ship_is_at_the_centre_along_her_heading(ctx, huds, heading_deg):
    """Own ship's symbol (stopped: no vector) is centred on the scope, its long side north-south heading 000 and
    east-west heading 090, pointed towards the bow (more of it abaft the middle than before it)."""
    hud = huds[SMALL]
    cx, cy, radius = scope_of(hud, SMALL)
    image = render(ctx, hud, SMALL, radar=still_radar(heading_deg=heading_deg))
    rows, cols = np.nonzero(colored(image, OWN_SHIP_COLOR))
    near = np.hypot(cols + 0.5 - cx, rows + 0.5 - cy) < radius  # the title, in the same green, is above the scope
    rows, cols = rows[near], cols[near]
    length = max(hud.line_height, 10)
    along, across = (rows, cols) if heading_deg == 0.0 else (cols, rows)
    centre_along, centre_across = (cy, cx) if heading_deg == 0.0 else (cx, cy)
    assert abs((along.min() + along.max() + 1) / 2 - centre_along) <= 1.0
    assert abs((across.min() + across.max() + 1) / 2 - centre_across) <= 1.0
    assert abs(np.ptp(along) + 1 - length) <= 2 and np.ptp(across) + 1 <= 0.5 * length
    bow_side = along < centre_along if heading_deg == 0.0 else along > centre_along
    assert bow_side.sum() < (~bow_side).sum()


def test_the_range_rings_are_at_their_radii(ctx, huds):
    """On the 2 nm scale at 1280 x 720 the rings are 0.5 nm apart: their pixels lie on circles of a quarter,
    half, three quarters and all of the outer ring's radius, each nearly complete, and hardly any between them
    (only the heading line crosses there)."""
    size = (1280, 720)
    hud = huds[size]
    cx, cy, radius = scope_of(hud, size)
    image = render(ctx, hud, size, radar=still_radar())
    rows, cols = np.nonzero(colored(image, RING_COLOR))
    distance = np.hypot(cols + 0.5 - cx, rows + 0.5 - cy)
    for k in (1, 2, 3, 4):
        on_ring = np.abs(distance - k * radius / 4) < 1.0
        assert on_ring.sum() > 0.6 * 2 * math.pi * k * radius / 4, k
    for k in (0.62, 1.38, 2.62, 3.38):  # between the rings, clear of the symbol and the ticks
        assert (np.abs(distance - k * radius / 4) < 1.0).sum() <= 3, k


def test_a_frame_without_a_radar_has_none_of_it(ctx, huds):
    """Without ``radar`` the frame is the background alone; with it, everything drawn lies inside the panel's
    square at the bottom-right corner."""
    hud = huds[SMALL]
    contacts = [Contact("TUG", np.array([NM, 0.0]), np.array([-3.0, 0.0]), 270.0)]
    radar = Radar(45.0, np.array([3.0, 3.0]), np.array([[-500.0, -600.0], [0.0, 0.0]]), 2 * NM, tuple(contacts))
    bare = render(ctx, hud, SMALL)
    # one level either way: GL lets an implementation round a float colour to 8 bits either way (NVIDIA and Mesa do)
    assert (np.abs(bare.astype(int) - np.round(np.array(BACKGROUND) * 255)) <= 1).all()
    assert len(np.unique(bare.reshape(-1, bare.shape[-1]), axis=0)) == 1
    drawn = np.nonzero(np.abs(render(ctx, hud, SMALL, radar=radar).astype(int) - bare).sum(axis=2) > 0)
    x, y, side = hud.radar_rect(SMALL)
    assert x + side == SMALL[0] - hud.margin and y + side == SMALL[1] - hud.margin
    assert drawn[1].min() == x and drawn[1].max() == x + side - 1
    assert drawn[0].min() == y and drawn[0].max() == y + side - 1


def test_the_radar_keeps_clear_of_the_other_panels(ctx, huds):
    """At 1280 x 720 with the text block, criteria, footprint, two charts, the slider and an alarm: the radar's
    square sits at the right edge, above the slider and below the footprint, on no pixel the other panels cover
    (drawn without it), and the alarm's banner is centred between the charts and the radar."""
    size = (1280, 720)
    hud = huds[size]
    t = np.linspace(0.0, 60.0, 601)
    others = dict(lines=["t 60.0 s   Hs 3.0 m"], charts=[StripChart("heave", "m", t, np.sin(t))] * 2,
                  panel=[("roll 2.1 < 5 deg", "ok")] * 3, slider=Slider(0.4, label="replay"),
                  footprint=Footprint(np.array([0.0, 1.0]), np.array([0.0, 1.0]), 5.0))
    alone = render(ctx, hud, size, **others).astype(int)
    covered = np.abs(alone - np.round(np.array(BACKGROUND) * 255)).sum(axis=2) > 0
    radar = still_radar([Contact("A", np.array([NM, NM]), np.array([-2.0, -2.0]), 225.0)])
    image = render(ctx, hud, size, banners=[Banner("ALARM pitch 3.2 > 3.0 deg", ALARM_COLOR)], radar=radar, **others)
    rows, cols = np.nonzero(colored(image, over_background(RADAR_PANEL_COLOR), 2))
    x0, x1, y0, y1 = cols.min(), cols.max() + 1, rows.min(), rows.max() + 1
    assert x1 == size[0] - hud.margin and abs((x1 - x0) - (y1 - y0)) <= 1 and x1 - x0 > 200
    assert not covered[y0 - hud.margin // 2:y1 + hud.margin // 2, x0 - hud.margin // 2:x1].any()
    assert covered[y1:y1 + hud.margin + 2, x0:x1].any(), "the slider's panel is a margin below"
    assert covered[:y0, x0:x1].any(), "the footprint plot is above"
    rows, cols = np.nonzero(colored(image, over_background(ALARM_COLOR), 2))
    charts_right = hud.margin + hud.chart_size[0]
    assert abs((cols.min() - charts_right) - (x0 - cols.max() - 1)) <= 1


def test_ring_intervals_follow_a_radars_range_scales():
    """The rings of the standard range scales, as radars set them: 0.25 nm on 0.75 and 1.5 nm, 0.5 on 3, 1 on 6,
    2 on 12, 4 on 24; a scale off the table (4 nm) gets 1 nm rings, and a small scope allowed 4 rings gets 2 nm
    rings on 6 nm."""
    for scale, interval in ((0.75, 0.25), (1.5, 0.25), (3, 0.5), (6, 1), (12, 2), (24, 4), (4, 1)):
        assert ring_interval_m(scale * NM) == pytest.approx(interval * NM), scale
    assert ring_interval_m(6 * NM, most=4) == pytest.approx(2 * NM)


def test_the_cpa_line_names_the_nearest_closing_contact_and_reds_a_dangerous_one(ctx, huds):
    """Own ship north at 5 m/s: a contact closing head-on, 0.42 nm off her track, 7.5 min from the CPA
    (amber: over 12 min it would be, under 0.5 nm it is red); one passing closer but already opening (tcpa < 0),
    which the line ignores; one beyond the scale, closing to 1 nm. The line and the red pixels of the CPA row say
    so; with the danger moved out to 0.6 nm the row is amber."""
    own = np.array([0.0, 5.0])
    tanker = Contact("TANKER", np.array([0.42 * NM, 4500.0]), np.array([0.0, -5.0]), 180.0)
    opened = Contact("PASSED", np.array([100.0, -300.0]), np.array([0.0, -5.0]), 180.0)
    far = Contact("FAR", np.array([NM, 3 * NM]), np.array([0.0, -5.0]), 180.0)
    radar = Radar(0.0, own, np.empty((0, 2)), 2 * NM, (far, opened, tanker))
    assert radar.cpa_line() == ("CPA 0.42 nm in 7.5 min  TANKER", DANGER_COLOR)
    assert Radar(0.0, own, np.empty((0, 2)), 2 * NM, (opened,)).cpa_line()[0] == "CPA --  no target closing"
    safer = Contact("TANKER", np.array([0.6 * NM, 4500.0]), np.array([0.0, -5.0]), 180.0)
    assert Radar(0.0, own, np.empty((0, 2)), 2 * NM, (far, safer)).cpa_line()[1] == CONTACT_COLOR

    size = (1280, 720)
    hud = huds[size]
    x, y, side = hud.radar_rect(size)
    row = slice(y + side - hud.pad - hud.line_height, y + side - hud.pad)
    for contacts, color in (((far, opened, tanker), DANGER_COLOR), ((far, safer), CONTACT_COLOR)):
        image = render(ctx, hud, size, radar=Radar(0.0, own, np.empty((0, 2)), 2 * NM, contacts))
        assert colored(image[row, x:x + side], color, 30).sum() > 100, color
