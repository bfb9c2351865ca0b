"""The cache and configuration folders: ``$MARINESIM_CACHE_DIR`` / ``$MARINESIM_CONFIG_DIR`` first, else the user's
folders as platformdirs finds them (``$XDG_CACHE_HOME`` / ``$XDG_CONFIG_HOME`` where set, then the platform's own).
Each is checked by writing into it: a cache entry, the session-log key."""

from __future__ import annotations

import sys
from pathlib import Path

import platformdirs
import pytest

from marinesim.cache import cache_root, store
from marinesim.session.signing import KEY_FILE, config_root, installation_key

LINUX = sys.platform.startswith("linux")


@pytest.fixture
def home(tmp_path, monkeypatch) -> Path:
    """A home folder under ``tmp_path``, with neither marinesim's overrides nor the XDG variables set."""
    for name in ("MARINESIM_CACHE_DIR", "MARINESIM_CONFIG_DIR", "XDG_CACHE_HOME", "XDG_CONFIG_HOME"):
        monkeypatch.delenv(name, raising=False)
    monkeypatch.setenv("HOME", str(tmp_path / "home"))
    return tmp_path / "home"


def _cache_entry() -> Path:
    """A cache entry written through :func:`store`, as the wake and the FFT plans are."""
    path = cache_root() / "probe"
    store(path, lambda p: p.write_text("cached\n"))
    return path


def test_the_cache_is_under_xdg_cache_home_where_that_is_set(home, tmp_path, monkeypatch):
    monkeypatch.setenv("XDG_CACHE_HOME", str(tmp_path / "xdg-cache"))
    assert _cache_entry() == tmp_path / "xdg-cache" / "marinesim" / "probe"
    assert (tmp_path / "xdg-cache" / "marinesim" / "probe").read_text() == "cached\n"


def test_the_cache_is_the_platforms_user_cache_folder_otherwise(home):
    folder = platformdirs.user_cache_path("marinesim", appauthor=False)
    assert cache_root() == folder
    if LINUX:
        assert folder == home / ".cache" / "marinesim"
    assert _cache_entry().read_text() == "cached\n" and (folder / "probe").is_file()


@pytest.mark.parametrize("xdg", [False, True], ids=["alone", "over XDG_CACHE_HOME"])
def test_marinesim_cache_dir_wins(home, tmp_path, monkeypatch, xdg):
    monkeypatch.setenv("MARINESIM_CACHE_DIR", str(tmp_path / "own-cache"))
    if xdg:
        monkeypatch.setenv("XDG_CACHE_HOME", str(tmp_path / "xdg-cache"))
    assert _cache_entry() == tmp_path / "own-cache" / "probe"
    assert not (tmp_path / "xdg-cache").exists() and not home.exists()


def test_the_key_is_under_xdg_config_home_where_that_is_set(home, tmp_path, monkeypatch):
    monkeypatch.setenv("XDG_CONFIG_HOME", str(tmp_path / "xdg-config"))
    assert config_root() == tmp_path / "xdg-config" / "marinesim"
    key = installation_key(create=True)
    assert (tmp_path / "xdg-config" / "marinesim" / KEY_FILE).read_text().strip() == key.hex()


def test_the_key_is_in_the_platforms_user_config_folder_otherwise(home):
    folder = platformdirs.user_config_path("marinesim", appauthor=False)
    assert config_root() == folder
    if LINUX:
        assert folder == home / ".config" / "marinesim"
    key = installation_key(create=True)
    assert (folder / KEY_FILE).read_text().strip() == key.hex()


@pytest.mark.parametrize("xdg", [False, True], ids=["alone", "over XDG_CONFIG_HOME"])
def test_marinesim_config_dir_wins(home, tmp_path, monkeypatch, xdg):
    monkeypatch.setenv("MARINESIM_CONFIG_DIR", str(tmp_path / "own-config"))
    if xdg:
        monkeypatch.setenv("XDG_CONFIG_HOME", str(tmp_path / "xdg-config"))
    key = installation_key(create=True)
    assert (tmp_path / "own-config" / KEY_FILE).read_text().strip() == key.hex()
    assert not (tmp_path / "xdg-config").exists() and not home.exists()

