"""The Python surface of the field lists (TAILOR_DETECTION_SETTINGS, TAILOR_DETECTION_STATS):
every setting is a documented property of DetectionConfig, in its repr and to_dict();
every statistic is a key of DetectionResult.stats. Fails when the binding misses a field."""

import numpy as np

import tailor

SETTINGS = tailor.DetectionConfig.settings()
STAT_FIELDS = tailor.DetectionResult.stat_fields()


def properties(cls):
    return {name for name in dir(cls) if isinstance(getattr(cls, name), property)}


def changed(setting):
    """A value other than the default, within the range."""
    if isinstance(setting["default"], bool):
        return not setting["default"]
    return setting["default"] + 1


def test_every_setting_is_a_documented_property():
    names = [s["name"] for s in SETTINGS]
    # to_dict() comes from the C++ JSON output (the keys `tailor detect --json` writes).
    assert len(set(names)) == len(names)
    as_dict = set(tailor.DetectionConfig().to_dict())
    assert set(names) == as_dict, f"settings() and to_dict() differ: {set(names) ^ as_dict}"
    bound = properties(tailor.DetectionConfig)
    assert not set(names) - bound, f"DetectionConfig misses the properties {set(names) - bound}"
    extra = bound - set(names)
    assert not extra, f"DetectionConfig has properties not in the list: {extra}"
    for s in SETTINGS:
        doc = getattr(tailor.DetectionConfig, s["name"]).__doc__
        assert doc and s["help"][1:] in doc and s["effect"] in doc, (s["name"], doc)
        assert s["effect"] in ("work only", "output only", "unsound when off",
                               "defines the result"), s


def test_every_setting_reaches_repr_and_to_dict():
    config = tailor.DetectionConfig()
    for s in SETTINGS:
        assert getattr(config, s["name"]) == s["default"], s["name"]
        assert f"{s['name']}={s['default']!r}" in repr(config), (s["name"], repr(config))
    for s in SETTINGS:
        setattr(config, s["name"], changed(s))
    as_dict = config.to_dict()
    for s in SETTINGS:
        assert getattr(config, s["name"]) == changed(s), s["name"]
        assert as_dict[s["name"]] == changed(s), s["name"]
        assert f"{s['name']}={changed(s)!r}" in repr(config), (s["name"], repr(config))


def test_numbers_are_checked_against_their_range():
    for s in SETTINGS:
        if isinstance(s["default"], bool):
            continue
        config = tailor.DetectionConfig()
        below = type(s["default"])(s["min"]) - 1
        try:
            setattr(config, s["name"], below)
        except ValueError as error:
            assert s["name"] in str(error)
        else:
            raise AssertionError(f"{s['name']} = {below} was accepted")


def test_every_statistic_is_a_key_of_stats():
    n = 6
    i, j = np.meshgrid(np.arange(n), np.arange(n), indexing="ij")
    x0 = np.stack([i.ravel(), j.ravel(), np.zeros(n * n)], axis=1) / (n - 1)
    ids = np.arange(n * n).reshape(n, n)
    a, b, c, d = ids[:-1, :-1].ravel(), ids[1:, :-1].ravel(), ids[1:, 1:].ravel(), ids[:-1, 1:].ravel()
    faces = np.concatenate([np.stack([a, b, c], 1), np.stack([a, c, d], 1)])
    stats = tailor.detect(faces, x0, x0 + [0, 0, 0.1]).stats
    names = {f["name"] for f in STAT_FIELDS}
    assert not names - set(stats), f"DetectionResult.stats misses {names - set(stats)}"
    assert not set(stats) - names, f"stats has keys not in the list: {set(stats) - names}"
    for f in STAT_FIELDS:
        assert f["unit"] in ("count", "ms") and f["stage"] and f["help"], f
        assert isinstance(stats[f["name"]], int if f["unit"] == "count" else float), f
