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
