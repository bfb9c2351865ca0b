"""The time-domain check of a study (marinesim/study/timedomain.py) run serially and on a real Dask
LocalCluster (marinesim/study/distributed.py): the same bits either way, a study interrupted mid-way resumes
with only what is missing, and a store that belongs to another study is refused."""

from __future__ import annotations

import math

import numpy as np
import pytest

from conftest import ROOT
from marinesim.criteria.monitor import Criterion
from marinesim.errors import MarinesimError, ParameterError
from marinesim.sea.build import wave_system
from marinesim.study.distributed import run_tasks
from marinesim.study.timedomain import Task, TimeDomainStudy, run_task
from marinesim.vessel import read_rao

CRITERIA = (Criterion("heave_rms_m", 1.0), Criterion("pitch_rms_deg", 1.0), Criterion("roll_max_deg", 5.0),
            Criterion("vertical_acc_rms_m_s2", 1.0, point="bow"))


def small_study(duration_s: float = 1200.0, seeds: tuple[int, ...] = (1, 2)) -> TimeDomainStudy:
    """The tanker in two sea states at two headings: 2 x 2 x len(seeds) tasks."""
    system = wave_system("jonswap", from_deg=0.0, hs=1.0, tp=10.0, gamma=3.3, spreading_s=10.0)
    return TimeDomainStudy(read_rao(ROOT / "rao" / "tanker" / "tanker.4"), {"bow": (120.0, 0.0, 10.0)}, 0.0,
                           CRITERIA, system, math.inf, np.array([2.0, 4.0]), np.array([9.0, 12.0]),
                           np.array([180.0, 120.0]), seeds, duration_s)


def test_the_same_tasks_give_the_same_bits_serially_and_on_a_local_cluster(tmp_path):
    study = small_study()
    serial = run_tasks(Task(study), study.tasks, len(CRITERIA), tmp_path / "serial.zarr", "small", serial=True)
    cluster = run_tasks(Task(study), study.tasks, len(CRITERIA), tmp_path / "cluster.zarr", "small", workers=2)
    assert np.isfinite(serial).all()
    assert serial.tobytes() == cluster.tobytes(), "a worker process must compute what this process computes"
    heave = serial[:, 0].reshape(study.shape)
    assert (heave[1] > heave[0]).all(), "the 4 m, 12 s sea must heave the tanker more than the 2 m, 9 s one"


def test_an_interrupted_study_resumes_with_only_the_missing_tasks(tmp_path):
    study = small_study(duration_s=600.0)
    calls: list[int] = []

    def interrupted(index: int) -> np.ndarray:
        if len(calls) == 5:
            raise KeyboardInterrupt
        calls.append(index)
        return run_task(study, index)

    store = tmp_path / "study.zarr"
    with pytest.raises(KeyboardInterrupt):
        run_tasks(interrupted, study.tasks, len(CRITERIA), store, "resume", serial=True)
    assert calls == [0, 1, 2, 3, 4]
    calls.clear()

    def counted(index: int) -> np.ndarray:
        calls.append(index)
        return run_task(study, index)

    resumed = run_tasks(counted, study.tasks, len(CRITERIA), store, "resume", serial=True)
    assert calls == [5, 6, 7], "the five finished tasks are kept, not computed again"
    fresh = run_tasks(Task(study), study.tasks, len(CRITERIA), tmp_path / "fresh.zarr", "resume", serial=True)
    assert resumed.tobytes() == fresh.tobytes()


def test_a_store_of_another_study_is_refused(tmp_path):
    study = small_study(duration_s=600.0, seeds=(1,))
    store = tmp_path / "study.zarr"
    run_tasks(Task(study), study.tasks, len(CRITERIA), store, "first", serial=True)
    with pytest.raises(MarinesimError, match="another study"):
        run_tasks(Task(study), study.tasks, len(CRITERIA), store, "second", serial=True)
    with pytest.raises(MarinesimError, match="another study"):
        run_tasks(Task(study), study.tasks + 1, len(CRITERIA), store, "first", serial=True)
    (tmp_path / "junk.zarr").write_text("not a store")
    with pytest.raises(MarinesimError, match="not a marinesim study store"):
        run_tasks(Task(study), study.tasks, len(CRITERIA), tmp_path / "junk.zarr", "first", serial=True)


def test_a_record_shorter_than_a_window_is_refused():
    with pytest.raises(ParameterError, match="window is longer"):
        small_study(duration_s=300.0)
