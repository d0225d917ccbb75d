"""tailor.simulate: a few frames of the arm-sleeve scene, and bad scenes."""

import numpy as np
import pytest

import tailor
from conftest import SOURCE_DIR, assert_releases_gil

SMALL = {"sleeve": {"rings": 9, "segments": 14}}


def test_a_few_frames_of_the_sleeve():
    frames = list(tailor.simulate(SMALL, frames=3))
    assert [f.index for f in frames] == [1, 2, 3]
    assert frames[0].time > 0 and frames[0].time < frames[1].time < frames[2].time
    scene = frames[0].simulation.scene
    for frame in frames:
        assert frame.cloth.shape == (9 * 14, 3) and np.all(np.isfinite(frame.cloth))
        assert frame.arm.shape[1] == 3 and np.all(np.isfinite(frame.arm))
        assert frame.cloth_faces.shape[1] == 3 and frame.cloth_faces.max() < len(frame.cloth)
        assert len(frame.steps) == scene.substeps
        assert all(step["frame"] == frame.index for step in frame.steps)
    # Each frame is its own copy, and the cloth moves.
    assert not np.shares_memory(frames[0].cloth, frames[2].cloth)
    assert not np.array_equal(frames[0].cloth, frames[2].cloth)
    summary = frames[-1].simulation.summary()
    assert summary["frames"] == 3 and summary["steps"] == 3 * scene.substeps
    assert summary["intersections"] == 0 and summary["checked_steps"] >= 3


def test_the_repository_scene_file_and_a_gesture_override():
    path = SOURCE_DIR / "scenes/sleeve.json"
    run = tailor.simulate(path, frames=1, gesture="raise")
    frame = next(run)
    with pytest.raises(StopIteration):
        next(run)
    used, loaded = frame.simulation.scene.to_dict(), tailor.SceneConfig.load(path).to_dict()
    assert used["gesture"]["name"] == "raise" and loaded["gesture"]["name"] != "raise"
    used["gesture"]["name"] = loaded["gesture"]["name"]
    assert used == loaded


def test_zero_frames_yield_nothing():
    assert list(tailor.simulate(SMALL, frames=0)) == []


def test_bad_scenes_raise_before_the_first_frame(tmp_path):
    with pytest.raises(FileNotFoundError, match="nowhere.json"):
        tailor.simulate(tmp_path / "nowhere.json")
    broken = tmp_path / "broken.json"
    broken.write_text("{ not json")
    with pytest.raises(ValueError, match="broken.json"):
        tailor.simulate(broken)
    with pytest.raises(ValueError, match="sleeve.colour"):
        tailor.simulate({"sleeve": {"colour": "red"}})
    with pytest.raises(ValueError, match="sleeve.rings"):
        tailor.simulate({"sleeve": {"rings": "many"}})
    with pytest.raises(ValueError, match="unknown gesture 'wave'"):
        tailor.simulate(SMALL, gesture="wave")
    with pytest.raises(ValueError, match="frames"):
        tailor.simulate(SMALL, frames=-1)
    with pytest.raises(ValueError, match="not JSON data"):
        tailor.simulate({"time_step": float("nan")})
    with pytest.raises(ValueError, match="no-such-method"):
        tailor.simulate(SMALL, method="no-such-method")


def test_scene_settings_round_trip_through_a_dict():
    config = tailor.SceneConfig.from_dict(SMALL)
    settings = config.to_dict()
    assert settings["sleeve"]["rings"] == 9
    again = tailor.SceneConfig.from_dict(settings)
    assert again.to_dict() == settings
    assert (again.frames, again.substeps) == (tailor.SceneConfig().frames, tailor.SceneConfig().substeps)


def test_a_frame_releases_the_gil():
    def make_call(scale):
        simulation = tailor.Simulation(tailor.SceneConfig.from_dict(
            {"sleeve": {"rings": 8 * scale, "segments": 16}, "substeps": 2}), threads=1)
        return simulation.step_frame

    assert_releases_gil(make_call, target_seconds=0.3, max_scale=64)
