"""The viewer's HUD on Mesa's software OpenGL: text lands where it is asked, the strip-chart trace where
the data says, the history keeps the last span and survives wrap-around and resets, and drawing leaves
no GL error at two sizes."""

from __future__ import annotations

import numpy as np
import pytest

from conftest import DEFAULT, ROOT, VESSEL_SCENARIO, write

from marinesim.render.hud import AXIS_FLOOR, MARGIN, PAD, TRACE_COLOR, Hud, StripChart, StripHistory, axis_limit


@pytest.fixture(scope="module")
def ctx(gl_context):
    yield gl_context
    _targets.clear()  # the framebuffers go before their context


@pytest.fixture(scope="module")
def hud(ctx):
    made = Hud(ctx)
    yield made
    made.release()


_targets: dict[tuple[int, int], object] = {}


def render(ctx, hud: Hud, size: tuple[int, int], lines=(), charts=(), help_lines=None) -> np.ndarray:
    """The HUD drawn on black, as (h, w, 3) uint8 with row 0 at the top (one framebuffer per size, kept
    for the module: releasing the bound one would leave moderngl rebinding a deleted framebuffer)."""
    if size not in _targets:
        _targets[size] = ctx.simple_framebuffer(size)
    fbo = _targets[size]
    fbo.use()
    fbo.clear(0.0, 0.0, 0.0, 1.0)
    hud.draw(size, lines, charts, help_lines)
    return np.frombuffer(fbo.read(components=3), np.uint8).reshape(size[1], size[0], 3)[::-1]


def bright(image: np.ndarray) -> np.ndarray:
    return image.max(axis=2) > 128


def trace_mask(image: np.ndarray) -> np.ndarray:
    """Pixels of the trace's colour (green, not the white text or the grey zero line)."""
    r, g, b = (image[..., i].astype(int) for i in range(3))
    expected = np.round(np.array(TRACE_COLOR[:3]) * 255)
    return (abs(r - expected[0]) < 30) & (abs(g - expected[1]) < 30) & (abs(b - expected[2]) < 30)


def test_text_lands_in_the_top_left_box_with_a_monospace_advance(ctx, hud):
    short = bright(render(ctx, hud, (640, 360), ["HEAVE 1.23 m"]))
    rows, cols = np.nonzero(short)
    assert rows.size > 50
    x0, y0 = MARGIN + PAD, MARGIN + PAD
    assert cols.min() >= x0 and cols.max() < x0 + 12 * hud.advance
    assert rows.min() >= y0 and rows.max() < y0 + hud.line_height
    assert not short[:, 320:].any() and not short[180:, :].any()

    longer = "HEAVE 1.23 m  ROLL -4.5 deg"
    cols_long = np.nonzero(bright(render(ctx, hud, (640, 360), [longer])))[1]
    assert cols_long.min() == cols.min()  # same first glyph
    assert abs((cols_long.max() - cols.max()) - (len(longer) - 12) * hud.advance) <= hud.advance

    two = bright(render(ctx, hud, (640, 360), ["HEAVE 1.23 m", "HEAVE 1.23 m"]))
    assert np.array_equal(two[y0 + hud.line_height:y0 + 2 * hud.line_height], short[y0:y0 + hud.line_height])


def test_unknown_characters_render_as_question_marks(ctx, hud):
    assert np.array_equal(render(ctx, hud, (320, 180), ["a\u00e9\u2603b"]), render(ctx, hud, (320, 180), ["a??b"]))


def test_axis_limit_rounds_up_to_a_1_2_5_step_above_a_floor():
    assert axis_limit(np.array([0.2, -0.7])) == 1.0
    assert axis_limit(np.array([1.3])) == 2.0
    assert axis_limit(np.array([-2.1, np.nan])) == 5.0
    assert axis_limit(np.array([6.0])) == 10.0
    assert axis_limit(np.array([150.0])) == 200.0
    assert axis_limit(np.array([5.0])) == 5.0
    assert axis_limit(np.array([1e-4, -2e-4])) == AXIS_FLOOR
    assert axis_limit(np.array([])) == AXIS_FLOOR


def test_the_trace_spans_the_amplitude_over_the_rounded_axis_range(ctx, hud):
    size = (640, 360)
    panel_x, _, plot_x, plot_y, half = hud.chart_plot_rect(size, 0, 1)
    right = panel_x + hud.chart_size[0] - PAD
    t = np.linspace(0.0, 120.0, 1201)
    amplitude = 0.7  # axis +-1
    values = np.where(t < 60.0, 5.0, amplitude) * np.sin(2 * np.pi * t / 7.0)  # the early 5 m is out of the window
    image = render(ctx, hud, size, charts=[StripChart("heave", "m", t, values)])
    rows, cols = np.nonzero(trace_mask(image))
    zero = plot_y + half
    assert abs(rows.min() - (zero - amplitude * half)) <= 2
    assert abs(rows.max() - (zero + amplitude * half)) <= 2
    assert abs(cols.min() - plot_x) <= 2 and abs(cols.max() - right) <= 2

    # the grey zero line, seen in the image, is where the layout says
    grey = (np.ptp(image.astype(int), axis=2) < 10) & (image[..., 0] > 60) & (image[..., 0] < 200)
    plot_rows = grey[plot_y:plot_y + 2 * half + 1, plot_x:right].sum(axis=1)
    assert plot_y + int(np.argmax(plot_rows)) == zero

    flat = render(ctx, hud, size, charts=[StripChart("pitch", "deg", t, np.zeros_like(t))])
    rows = np.nonzero(trace_mask(flat))[0]
    assert rows.size > 0.9 * (right - plot_x) and set(rows) == {zero}


def test_charts_stack_at_the_bottom_left_as_many_as_fit(ctx, hud):
    """Three charts stack at the bottom-left of a target tall enough for them; on a 360 px one only the first
    two are drawn (the charts keep to the lower 45 %, clear of the vessel in the middle of the picture)."""
    size = (640, 720)
    t = np.linspace(0.0, 60.0, 601)
    charts = [StripChart(name, "deg", t, 0.3 * np.sin(t)) for name in ("heave", "roll", "pitch")]
    mask = trace_mask(render(ctx, hud, size, charts=charts))
    for index in range(3):
        _, panel_y, _, plot_y, half = hud.chart_plot_rect(size, index, 3)
        band = mask[panel_y:panel_y + hud.chart_size[1]]
        assert band.any() and abs(np.nonzero(band)[0].mean() + panel_y - (plot_y + half)) < 2
    assert hud.chart_plot_rect(size, 2, 3)[1] + hud.chart_size[1] == size[1] - MARGIN
    assert not mask[:, MARGIN + hud.chart_size[0]:].any()
    small = (640, 360)
    assert hud.charts_that_fit(small) == 2
    rows = np.nonzero(trace_mask(render(ctx, hud, small, charts=charts)))[0]
    assert rows.min() >= hud.chart_plot_rect(small, 0, 2)[1] and rows.min() > 0.55 * small[1] - hud.chart_size[1]


def test_history_keeps_the_last_span_wraps_and_resets():
    history = StripHistory(["heave", "roll", "pitch"], span_s=10.0, capacity=8192)
    for t in range(101):
        history.append(float(t), [t, 2 * t, -t])
    roll = history.chart("roll", "deg")
    assert roll.title == "roll" and roll.unit == "deg" and roll.span_s == 10.0
    assert np.array_equal(roll.times, np.arange(90.0, 101.0)) and np.array_equal(roll.values, 2 * roll.times)

    small = StripHistory(["heave"], span_s=1000.0, capacity=50)
    for t in np.arange(1000) * 0.1:
        small.append(t, [np.sin(t)])
    heave = small.chart("heave", "m")
    assert np.allclose(heave.times, np.arange(950, 1000) * 0.1) and np.allclose(heave.values, np.sin(heave.times))

    small.append(3.0, [1.0])  # time went backwards: a reset
    assert np.array_equal(small.chart("heave", "m").times, [3.0])
    small.append(3.0, [2.0])  # equal times are kept
    assert np.array_equal(small.chart("heave", "m").values, [1.0, 2.0])
    small.clear()
    assert small.chart("heave", "m").times.size == 0
    with pytest.raises(KeyError):
        small.chart("sway", "m")
    with pytest.raises(ValueError):
        small.append(4.0, [1.0, 2.0])


def test_draws_at_two_sizes_without_gl_errors_and_releases(ctx):
    hud = Hud(ctx, font_px=16)
    t = np.linspace(0.0, 30.0, 301)
    charts = [StripChart("heave", "m", t, np.sin(t)), StripChart("roll", "deg", t[:1], t[:1]),
              StripChart("pitch", "deg", t[:0], t[:0])]
    help_lines = ["H  toggle this help", "Q  quit"]
    many = [f"line {i:3d} " + "x" * 90 for i in range(60)]  # more glyphs than the first buffer holds
    for size in ((640, 360), (1280, 720)):
        image = render(ctx, hud, size, many, charts, help_lines)
        assert ctx.error == "GL_NO_ERROR"
        assert bright(image)[size[1] // 2 - 20:size[1] // 2 + 20, size[0] // 2 - 60:size[0] // 2 + 60].any()
    # the help block is centred
    image = bright(render(ctx, hud, (1280, 720), help_lines=help_lines))
    rows, cols = np.nonzero(image)
    assert abs((cols.min() + cols.max()) / 2 - 640) < hud.advance and abs((rows.min() + rows.max()) / 2 - 360) < 12
    # the caller's viewport survives, and the HUD covers the whole target whatever it was
    target = _targets[(640, 360)]
    target.use()
    target.clear(0.0, 0.0, 0.0, 1.0)
    ctx.viewport = (300, 10, 100, 50)
    hud.draw((640, 360), ["HEAVE"])
    assert ctx.viewport == (300, 10, 100, 50)
    ctx.viewport = (0, 0, 640, 360)
    assert bright(np.frombuffer(target.read(components=3), np.uint8).reshape(360, 640, 3)[::-1])[:40, :80].any()
    hud.release()
    hud.release()
    assert ctx.error == "GL_NO_ERROR"


def test_the_strip_packs_whole_segments_into_the_frames_width(hud):
    """The compact strip at 640 px, 1280 px and 4K: every segment whole and in order, no line wider than the
    frame holds (it would be cut with ~), and no line that could have taken the next line's first segment."""
    segments = ["t 60.0 s", "Hs 3.8 m  Tp 9.0 s  from 290", "4.0 kn  hdg 260", "x" * 40, "orbit",
                "sun +30  vis 40 km  cloud 0/8  wind 11 m/s", "TAB: panels"]
    counts = []
    for width in (640, 1280, 3840):
        lines, fits = hud.pack(segments, width), hud.columns(width)
        assert "   ".join(lines) == "   ".join(segments)
        assert max(len(line) for line in lines) <= fits
        for line, following in zip(lines, lines[1:]):
            assert len(line) + 3 + len(following.split("   ")[0]) > fits
        counts.append(len(lines))
    assert counts[0] > counts[1] >= counts[2] == 1
    assert hud.pack(["y" * 500, "z"], 640) == ["y" * 500, "z"], "a segment too long for a line is kept whole"


def test_a_vessel_without_a_hull_says_on_screen_that_it_is_not_drawn(tmp_path):
    """The default scenario without its hull and visual mesh: its motions are computed but nothing is drawn of
    her, and both the strip and the panels say so (else a trainee sees empty sea and no reason)."""
    from marinesim.render.offscreen import Offscreen
    from marinesim.render.scene import NOT_DRAWN
    from marinesim.scenario import load_scenario

    lines = [line for line in DEFAULT.read_text().splitlines() if not line.startswith(("hull =", "visual_mesh ="))]
    text = "\n".join(lines).replace('"../rao/', f'"{(ROOT / "rao").as_posix()}/')
    (tmp_path / "bare.toml").write_text(text)
    with Offscreen(load_scenario(tmp_path / "bare.toml"), (640, 360), solver="off") as view:
        assert view.scene.renderer.mesh is None and view.scene.sim.vessel is not None
        assert NOT_DRAWN in view.scene.strip_lines(640) and NOT_DRAWN in view.scene.hud_lines()
    with Offscreen(load_scenario(DEFAULT), (640, 360), solver="off") as view:
        assert NOT_DRAWN not in view.scene.strip_lines(640)


def test_the_font_follows_the_target_within_its_range():
    """14 px on a 1280 x 720 target, in proportion to the smaller ratio, never under 9 px nor over 32 px (a 4K
    screen's: capped at 20 px, its text was 10 px on a 4K display scaled to 200 %)."""
    from marinesim.render.hud import font_px_for

    assert font_px_for((1280, 720)) == 14 and font_px_for((2560, 1440)) == 28 and font_px_for((1920, 1080)) == 21
    assert font_px_for((3840, 2160)) == 32 and font_px_for((7680, 4320)) == 32
    assert font_px_for((640, 360)) == 9 and font_px_for((1280, 360)) == 9 and font_px_for((960, 540)) == 10


@pytest.mark.slow
def test_the_hud_leaves_the_vessel_in_view_with_an_alarm_up():
    """The helideck exercise at 900 s (pitch alarm, red helideck light, two of four criteria past caution): the HUD
    against the same frame without it, the vessel against the frame without the vessel. What was wrong (issue
    22): the banners sat over the hull and at 640 x 360 the HUD covered 77 % of the frame and 98 % of the rig.
    Now the default compact strip leaves the rig free (at most 1 % under it at 1280 x 720, 10 % at 640 x 360, the
    derrick's top) and covers at most 0.6 of what the full panels (TAB) cover; the panels keep the middle free
    (5 % and 40 %); both banners are drawn at the bottom, and no line is cut by the frame's edge."""
    from marinesim.render.offscreen import Offscreen
    from marinesim.render.renderer import RenderOptions
    from marinesim.scenario import load_scenario

    scenario = load_scenario(ROOT / "configs" / "training" / "helideck_landing.toml")
    with Offscreen(scenario, (1280, 720), solver="off", options=RenderOptions(reproducible=True)) as view:
        view.go_to(900.0)
        banners = view.scene.banners()
        assert [level for _, level in view.scene.criteria_strip()] == ["exceeded", "caution"]
        for size, most_strip, most_panels in (((1280, 720), 0.01, 0.05), ((640, 360), 0.10, 0.40)):
            view.resize(size)   # the same moment in a smaller window
            view.scene.panels, view.scene.renderer.vessel.shown = False, True
            strip = view.frame(hud=True).astype(int)
            view.scene.panels = True
            panels = view.frame(hud=True).astype(int)
            bare = view.frame(hud=False).astype(int)
            view.scene.renderer.vessel.shown = False
            no_vessel = view.frame(hud=False).astype(int)
            vessel = np.abs(bare - no_vessel).sum(axis=2) > 30
            assert len(banners) == 2 and vessel.mean() > 0.01
            covered = {}
            for name, with_hud, most in (("strip", strip, most_strip), ("panels", panels, most_panels)):
                hud = np.abs(with_hud - bare).sum(axis=2) > 30
                covered[name] = hud.mean()
                under = hud[vessel].mean()
                assert under <= most, f"{size} {name}: {under:.1%} of the vessel under the HUD"
                red = (with_hud[..., 0] > 150) & (with_hud[..., 1] < 80) & (with_hud[..., 2] < 80)
                assert red[size[1] // 2:].sum() > 20 * red[:size[1] // 2].sum(), "the alarm banner is not at the bottom"
                assert not hud[:, -2:].any(), f"{size} {name}: the HUD runs into the right edge (a line cut off)"
            assert covered["strip"] <= 0.6 * covered["panels"], covered


def test_key_hints_are_shown_in_the_window_only(tmp_path):
    """A headless render (a video, a screenshot) of the tanker with one criterion far above its limit (an alarm up)
    and one far within it: no 'TAB: panels' in the strip, no 'ENTER: acknowledge' on the alarm's banner, no
    'TAB: all' on the criteria's row; the window's scene (``interactive``, as the viewer sets it) shows all
    three. What would be wrong: the keys of a window nobody can press were burnt into every video. The banner
    gives the value and limit as the assessment does."""
    from marinesim.criteria.monitor import value_and_limit
    from marinesim.render.offscreen import Offscreen
    from marinesim.scenario import load_scenario

    criteria = '\n[[criteria]]\nname = "roll"\nquantity = "roll_max_deg"\nlimit = {limit}\nwindow_s = 10.0\n'
    for limit, hints in ((1e-6, ("TAB: panels", "ENTER: acknowledge")), (1e6, ("TAB: panels", "TAB: all"))):
        scenario = load_scenario(write(tmp_path, VESSEL_SCENARIO + criteria.format(limit=limit)))
        with Offscreen(scenario, (640, 360), solver="off") as view:
            view.go_to(5.0)
            scene = view.scene

            def shown() -> str:
                return "\n".join(scene.strip_lines(3840) + [banner.text for banner in scene.banners()]
                                 + [text for text, _ in scene.criteria_strip()])
            assert len(scene.exercise.unacknowledged()) == (limit < 1.0)
            for alarm in scene.exercise.unacknowledged():  # its value and limit in the digits that tell them apart
                assert " > ".join(value_and_limit(alarm.value, alarm.limit)) in shown()
            assert "TAB" not in shown() and "ENTER" not in shown(), shown()
            scene.interactive = True
            assert all(hint in shown() for hint in hints), shown()
