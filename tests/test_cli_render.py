"""`marinesim render`: a screenshot or a video of a scenario through EGL; bad arguments refused before anything is written."""

from __future__ import annotations

import pytest

from conftest import DEFAULT
from marinesim.cli import main
from marinesim.gl import GraphicsError


def test_render_command_refuses_bad_sizes_and_writes_a_screenshot(tmp_path, capsys):
    assert main(["render", str(DEFAULT), "--screenshot", str(tmp_path / "a.png"), "--size", "321x180"]) == 2
    assert "--size" in capsys.readouterr().err
    assert main(["render", str(DEFAULT), "--out", str(tmp_path / "a.avi")]) == 2
    assert main(["render", str(DEFAULT), "--screenshot", str(tmp_path / "a.png"), "--time", "-1"]) == 2
    assert main(["render", str(DEFAULT), "--out", str(tmp_path / "a.mp4"), "--seconds", "0"]) == 2
    assert "--seconds" in capsys.readouterr().err
    assert main(["render", str(DEFAULT), "--out", str(tmp_path / "a.mp4"), "--fps", "0"]) == 2
    assert "--fps" in capsys.readouterr().err
    both = ["--out", str(tmp_path / "a.mp4"), "--screenshot", str(tmp_path / "a.png")]
    assert main(["render", str(DEFAULT), *both]) == 2
    assert not list(tmp_path.iterdir()), "a refused command wrote something"
    try:
        code = main(["render", str(DEFAULT), "--screenshot", str(tmp_path / "shot.png"), "--size", "160x90",
                     "--time", "5", "--camera", "bridge"])
    except GraphicsError as error:
        pytest.skip(str(error))
    from PIL import Image

    assert code == 0
    assert Image.open(tmp_path / "shot.png").size == (160, 90)


def test_the_hud_option_draws_the_strip_the_panels_or_nothing(tmp_path):
    """``--hud``: off draws the picture alone, strip (the default) only a band at the top, panels also the strip
    charts at the bottom-left. If this fails, the option does not reach the scene or the strip draws charts."""
    import numpy as np
    from PIL import Image

    shots = {}
    for hud in ("off", "strip", "panels"):
        out = tmp_path / f"{hud}.png"
        args = ["render", str(DEFAULT), "--screenshot", str(out), "--size", "320x180", "--time", "2", "--quiet"]
        try:
            assert main(args + ([] if hud == "strip" else ["--hud", hud])) == 0
        except GraphicsError as error:
            pytest.skip(str(error))
        shots[hud] = np.asarray(Image.open(out), dtype=int)
    top, bottom_left = (slice(0, 20), slice(None)), (slice(130, 175), slice(5, 80))
    changed = {hud: np.abs(shots[hud] - shots["off"]).sum(axis=2) > 30 for hud in ("strip", "panels")}
    assert changed["strip"][top].mean() > 0.3 and changed["panels"][top].mean() > 0.3
    assert not changed["strip"][bottom_left].any() and changed["panels"][bottom_left].mean() > 0.3
    with pytest.raises(SystemExit) as refused:
        main(["render", str(DEFAULT), "--screenshot", str(tmp_path / "x.png"), "--hud", "full"])
    assert refused.value.code == 2 and not (tmp_path / "x.png").exists()
