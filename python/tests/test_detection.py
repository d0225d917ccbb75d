"""tailor.detect / SelfCollisionDetector: exactly the ground truth on the cloth-funnel
step, exactly brute force on small meshes (every preset and stage switch), the detector's
buffers (no copies, aliasing), bad input, and the GIL."""

import json

import numpy as np
import pytest

import tailor
from conftest import DATA_DIR, assert_releases_gil, sanitized

PRESETS = tailor.DetectionConfig.preset_names()
# Under the sanitizers (slow), the funnel step with two presets only; tests/detection runs
# every preset on it in C++.
FUNNEL_PRESETS = ["tang", "paper"] if sanitized() else PRESETS


def collision_sets(result):
    vertex_face = {tuple(row) for row in result.vertex_face.tolist()}
    edge_edge = {tuple(row) for row in result.edge_edge.tolist()}
    assert len(vertex_face) == len(result.vertex_face) and len(edge_edge) == len(result.edge_edge)
    return vertex_face, edge_edge


def grid_cloth(n, seed, amplitude, planar=False):
    """An n x n grid cloth, crumpled (or flat, `planar`) at the start, and a random end
    position with vertices moved by up to `amplitude` edge lengths, a few of them onto
    other vertices' start positions: a step with many collisions. A flat start makes every
    pair coplanar at t = 0, so the exact arithmetic decides most queries (slow: keep n small)."""
    rng = np.random.default_rng(seed)
    i, j = np.meshgrid(np.arange(n), np.arange(n), indexing="ij")
    height = np.zeros(n * n) if planar else rng.uniform(-0.3, 0.3, n * n)
    x0 = np.stack([i.ravel(), j.ravel(), height], axis=1) / (n - 1)
    ids = np.arange(n * n).reshape(n, n)
    a, b, c, d = ids[:-1, :-1].ravel(), ids[1:, :-1].ravel(), ids[1:, 1:].ravel(), ids[:-1, 1:].ravel()
    faces = np.concatenate([np.stack([a, b, c], 1), np.stack([a, c, d], 1)])
    x1 = x0 + rng.uniform(-amplitude, amplitude, x0.shape) / (n - 1)
    snap = rng.choice(n * n, size=n // 2, replace=False)
    x1[snap] = x0[rng.choice(n * n, size=n // 2, replace=False)]
    return faces, x0, x1


@pytest.fixture(scope="module")
def funnel():
    data = DATA_DIR / "cloth-funnel"
    x0, faces = tailor.read_mesh(data / "frames/227.ply")
    x1, faces1 = tailor.read_mesh(data / "frames/228.ply")
    assert np.array_equal(faces, faces1)
    mesh = tailor.Mesh(faces)
    nv, ne = mesh.num_vertices, mesh.num_edges
    truth = {}
    for kind in ("vf", "ee"):
        pairs = json.loads((data / f"boxes/227{kind}.json").read_text())
        flags = json.loads((data / f"mma_bool/227{kind}_mma_bool.json").read_text())
        assert len(pairs) == len(flags)
        truth[kind] = {tuple(p) for p, flag in zip(pairs, flags) if flag}
    vertex_face = {(v, f - nv - ne) for v, f in truth["vf"]}
    edge_edge = {tuple(sorted((a - nv, b - nv))) for a, b in truth["ee"]}
    return mesh, x0, x1, vertex_face, edge_edge


def edge_id_pairs(result):
    return {tuple(sorted(row)) for row in result.edge_ids.tolist()}


@pytest.mark.parametrize("method", FUNNEL_PRESETS)
def test_cloth_funnel_every_preset_reports_exactly_the_true_pairs(funnel, method):
    mesh, x0, x1, vertex_face, edge_edge = funnel
    assert (len(vertex_face), len(edge_edge)) == (27, 107)
    result = tailor.detect(mesh, x0, x1, method=method)
    found_vf, _ = collision_sets(result)
    assert found_vf == vertex_face
    assert edge_id_pairs(result) == edge_edge
    # The edge ids name the same edges as the vertex pairs.
    edges = mesh.edges
    for (a0, a1, b0, b1), (ea, eb) in zip(result.edge_edge.tolist(), result.edge_ids.tolist()):
        assert tuple(edges[ea]) == (a0, a1) and tuple(edges[eb]) == (b0, b1)
    assert result.stats["vf_colliding"] == 27 and result.stats["ee_colliding"] == 107
    assert len(result) == 27 + 107


def assert_same_collisions(result, oracle):
    assert collision_sets(result) == collision_sets(oracle)
    # Same pairs in the same (sorted) order, so the times line up too.
    assert np.array_equal(result.vertex_face, oracle.vertex_face)
    assert np.array_equal(result.edge_edge, oracle.edge_edge)
    assert np.all((result.toi >= 0) & (result.toi <= 1))


@pytest.mark.parametrize("seed,n,planar",
                         [(0, 10, False), (2, 5, True)] + ([] if sanitized() else [(1, 10, False)]))
def test_every_preset_equals_brute_force_on_random_steps(seed, n, planar):
    faces, x0, x1 = grid_cloth(n, seed, amplitude=3.0, planar=planar)
    oracle = tailor.brute_force(faces, x0, x1)
    assert len(oracle.vertex_face) > 0 and len(oracle.edge_edge) > 0, "a step without collisions"
    for method in PRESETS:
        assert_same_collisions(tailor.detect(faces, x0, x1, method=method), oracle)


@pytest.mark.parametrize(
    "switch",
    ["normal_cones", "diagonal_bounds", "adjacency_culling", "triangle_filter",
     "direction_filter", "feature_assignment", "primitive_boxes", "coplanarity_filter",
     "projection_filter"])
def test_each_stage_switched_off_alone_still_equals_brute_force(switch):
    faces, x0, x1 = grid_cloth(10, 7, amplitude=2.0)
    config = tailor.DetectionConfig.preset("paper")
    setattr(config, switch, False)
    assert getattr(config, switch) is False
    assert_same_collisions(tailor.detect(faces, x0, x1, method=config),
                           tailor.brute_force(faces, x0, x1))


def test_thick_cloth_step_equals_brute_force(data_dir):
    x0, faces = tailor.read_mesh(data_dir / "thick-cloth/t0.ply")
    x1, _ = tailor.read_mesh(data_dir / "thick-cloth/t1.ply")
    oracle = tailor.brute_force(faces, x0, x1)
    assert oracle.stats is None
    for method in PRESETS:
        assert_same_collisions(tailor.detect(faces, x0, x1, method=method), oracle)


def test_radial_view_with_the_sleeve_observers_equals_brute_force():
    simulation = tailor.Simulation(tailor.SceneConfig.from_dict({"sleeve": {"rings": 10, "segments": 16}}))
    x0 = simulation.cloth_positions
    simulation.step_frame()
    x1 = simulation.cloth_positions
    # Exaggerate the motion so that the step has collisions.
    x1 = x0 + 6.0 * (x1 - x0)
    mesh = simulation.cloth_mesh
    oracle = tailor.brute_force(mesh, x0, x1)
    assert_same_collisions(tailor.detect(mesh, x0, x1, observers=simulation.observer_loops), oracle)
    # On this small sleeve the diagonal bounds leave radial view nothing to cull: without
    # them it must cull, and still report exactly the oracle's pairs.
    config = tailor.DetectionConfig.preset("paper")
    config.diagonal_bounds = False
    result = tailor.detect(mesh, x0, x1, method=config, observers=simulation.observer_loops)
    assert_same_collisions(result, oracle)
    assert result.stats["radial_pairs_culled"] > 0, "radial view culled nothing"
    # Classifying every cluster culls the same pairs and fills the classification counts.
    config.classify_every_cluster = True
    every = tailor.detect(mesh, x0, x1, method=config, observers=simulation.observer_loops)
    assert_same_collisions(every, oracle)
    assert every.stats["radial_pairs_culled"] == result.stats["radial_pairs_culled"]
    assert every.stats["radial_positive"] + every.stats["radial_negative"] + \
        every.stats["radial_undetermined"] > 0, "no cluster classified"


def test_detector_buffers_are_used_in_place_and_copies_are_counted():
    faces, x0, x1 = grid_cloth(10, 3, amplitude=2.0)
    oracle = tailor.brute_force(faces, x0, x1)
    detector = tailor.SelfCollisionDetector(tailor.Mesh(faces), x0)
    assert np.array_equal(detector.x0, x0) and np.array_equal(detector.x1, x0)

    before = tailor._input_copies()
    assert_same_collisions(detector.detect(x0, x1), oracle)
    assert tailor._input_copies() == before + 2  # the C++ API takes its own Positions

    detector.x1[:] = x1  # fill the buffer in place
    before = tailor._input_copies()
    assert_same_collisions(detector.detect(), oracle)
    assert_same_collisions(detector.detect(detector.x0, detector.x1), oracle)
    assert tailor._input_copies() == before  # no copy at all

    # Other dtypes and byte orders are converted once, then copied into the buffers.
    before = tailor._input_copies()
    assert_same_collisions(tailor.detect(faces, x0.astype(">f8"), x1.astype(">f8")), oracle)
    assert tailor._input_copies() == before + 4

    # The reverse step through the swapped buffers (each input aliases the other buffer).
    reverse = tailor.brute_force(faces, x1, x0)
    assert_same_collisions(detector.detect(detector.x1, detector.x0), reverse)
    assert np.array_equal(detector.x0, x1) and np.array_equal(detector.x1, x0)


def test_repeated_steps_match_one_off_detection():
    faces, x0, _ = grid_cloth(9, 11, amplitude=0.0)
    detector = tailor.SelfCollisionDetector(tailor.Mesh(faces), x0, method="tang")
    current = x0
    for step in range(4):
        _, _, target = grid_cloth(9, 100 + step, amplitude=1.5)
        result = detector.detect(current, target)
        assert_same_collisions(result, tailor.brute_force(faces, current, target))
        current = target


def test_results_are_arrays_of_the_documented_shapes():
    faces, x0, x1 = grid_cloth(8, 5, amplitude=2.0)
    result = tailor.detect(faces, x0, x1)
    n, m = len(result.vertex_face), len(result.edge_edge)
    assert result.vertex_face.shape == (n, 2) and result.vertex_face.dtype == np.int32
    assert result.edge_edge.shape == (m, 4) and result.edge_ids.shape == (m, 2)
    assert result.toi.shape == (n + m,)
    assert np.shares_memory(result.vertex_face_toi, result.toi)
    assert np.array_equal(np.concatenate([result.vertex_face_toi, result.edge_edge_toi]), result.toi)
    assert np.all(result.edge_edge[:, 0] < result.edge_edge[:, 1])
    assert np.all(result.edge_edge[:, 2] < result.edge_edge[:, 3])
    assert {"candidate_triangle_pairs", "vf_tested", "ee_tested", "total_ms"} <= set(result.stats)
    assert result.stats["vf_colliding"] == n and result.stats["ee_colliding"] == m


def test_bad_input_raises_value_error_with_the_library_message():
    faces, x0, x1 = grid_cloth(5, 1, amplitude=1.0)
    nan = x1.copy()
    nan[3, 2] = np.nan
    with pytest.raises(tailor.InputError, match="^x1 has a non-finite coordinate at vertex 3$"):
        tailor.detect(faces, x0, nan)
    with pytest.raises(ValueError, match="^x1 has 24 vertices, the mesh has 25$"):
        tailor.detect(faces, x0, x1[:-1])
    detector = tailor.SelfCollisionDetector(tailor.Mesh(faces), x0)
    with pytest.raises(ValueError, match="^x0 has 26 vertices, the mesh has 25$"):
        detector.detect(np.vstack([x0, x0[:1]]), x1)
    with pytest.raises(ValueError, match="the build frame has 24 vertices, the mesh has 25"):
        tailor.SelfCollisionDetector(tailor.Mesh(faces), x0[:-1])
    with pytest.raises(ValueError, match="no-such-method"):
        tailor.detect(faces, x0, x1, method="no-such-method")
    with pytest.raises(ValueError, match=r"shape \(n, 3\)"):
        tailor.detect(faces, x0[:, :2], x1)
    with pytest.raises(ValueError, match="faces must be"):
        tailor.detect(np.zeros((3, 4), dtype=int), x0, x1)
    with pytest.raises(ValueError, match="out of range"):
        tailor.detect(tailor.Mesh(faces, num_vertices=3), x0, x1)
    with pytest.raises(ValueError, match="section loop 0 has vertex 99"):
        tailor.detect(faces, x0, x1, observers=[[0, 1, 99]])
    with pytest.raises(ValueError, match="observers must be a list of lists"):
        tailor.detect(faces, x0, x1, observers="ring")
    with pytest.raises(ValueError, match="threads"):
        tailor.detect(faces, x0, x1, threads=-2)
    # Nothing was changed by the failed calls.
    assert np.array_equal(detector.x0, x0)


def test_detection_releases_the_gil():
    def make_call(scale):
        n = int(16 * scale ** 0.5)
        faces, x0, x1 = grid_cloth(n, 0, amplitude=3.0)
        detector = tailor.SelfCollisionDetector(tailor.Mesh(faces), x0, method="basic", threads=1)
        return lambda: detector.detect(x0, x1)

    assert_releases_gil(make_call, max_scale=4096)


def two_sheets(gap):
    """Two flat 6 x 6 grids of unit size, the second `gap` above the first (z)."""
    n = 7
    xs, ys = np.meshgrid(np.linspace(0, 1, n), np.linspace(0, 1, n), indexing="ij")
    sheet = np.stack([xs.ravel(), ys.ravel(), np.zeros(n * n)], axis=1)
    quads = [(i * n + j, (i + 1) * n + j, (i + 1) * n + j + 1, i * n + j + 1)
             for i in range(n - 1) for j in range(n - 1)]
    faces = np.array([f for a, b, c, d in quads for f in ((a, b, c), (a, c, d))])
    x = np.vstack([sheet, sheet + [0, 0, gap]])
    return np.vstack([faces, faces + n * n]), x


def test_proximity_pairs_are_exact_at_the_gap_sorted_and_thread_independent():
    # In one sheet, non-incident features are at least spacing / sqrt(2) = 0.118 apart.
    faces, x = two_sheets(0.0625)
    vf, ee = tailor.proximity_pairs(faces, x, 0.0625)
    assert vf.shape[1] == 2 and ee.shape[1] == 2 and len(vf) > 0 and len(ee) > 0
    # Every vertex of one sheet is exactly the gap from the other sheet.
    assert set(vf[:, 0].tolist()) == set(range(len(x)))
    assert vf.tolist() == sorted(vf.tolist()) and ee.tolist() == sorted(ee.tolist())
    below_vf, below_ee = tailor.proximity_pairs(faces, x, np.nextafter(0.0625, 0))
    assert len(below_vf) == 0 and len(below_ee) == 0
    one_vf, one_ee = tailor.proximity_pairs(tailor.Mesh(faces), x, 0.0625, threads=1)
    assert np.array_equal(one_vf, vf) and np.array_equal(one_ee, ee)
    with pytest.raises(tailor.InputError):
        tailor.proximity_pairs(faces, x, -1.0)
    with pytest.raises(tailor.InputError):
        tailor.proximity_pairs(faces, x[:5], 0.1)


def test_thickness_detection_and_collision_free_step():
    # Two unit squares 1 apart, the upper one falling by 1: within 0.25 from t = 0.75.
    faces = np.array([[0, 1, 2], [0, 2, 3], [4, 5, 6], [4, 6, 7]])
    x0 = np.array([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0],
                   [0, 0, 1], [1, 0, 1], [1, 1, 1], [0, 1, 1]], dtype=float)
    x1 = x0.copy()
    x1[4:, 2] -= 1.0
    within = tailor.detect(faces, x0, x1, thickness=0.25)
    assert 0.75 - 1e-6 <= within.toi.min() <= 0.75
    short = x0.copy()
    short[4:, 2] -= 0.9  # ends 0.1 apart: never touching, within 0.25 from t = 0.75 / 0.9
    assert len(tailor.detect(faces, x0, short)) == 0
    assert len(tailor.detect(faces, x0, short, thickness=0.25)) > 0
    step = tailor.collision_free_step(faces, x0, x1, 0.25)
    assert 0.75 - 1e-6 <= step["alpha"] <= 0.75
    assert step["vertex_face"] is not None or step["edge_edge"] is not None
    free = tailor.collision_free_step(faces, x0, x0 + [0, 0, 0.1], 0.25)
    assert free == {"alpha": 1.0, "vertex_face": None, "edge_edge": None}
    config = tailor.DetectionConfig()
    config.thickness = 0.25
    assert np.array_equal(tailor.detect(faces, x0, short, method=config).vertex_face,
                          tailor.detect(faces, x0, short, thickness=0.25).vertex_face)
    with pytest.raises(tailor.InputError):
        tailor.detect(faces, x0, x1, thickness=-1.0)


def test_a_proximity_search_reused_over_moving_configurations_finds_the_one_off_pairs():
    faces, x = two_sheets(0.0625)
    mesh = tailor.Mesh(faces)
    search = tailor.ProximitySearch(mesh, threads=2)
    rng = np.random.default_rng(7)
    found = 0
    # The trees are built on the first configuration and refitted on the others, the last
    # squashed along y (pairs appear whose boxes were apart at first).
    for x_now in (x, x + 0.01 * rng.standard_normal(x.shape), x * np.array([1.0, 0.2, 1.0])):
        vf, ee = search.pairs(x_now, 0.0625)
        one_vf, one_ee = tailor.proximity_pairs(mesh, x_now, 0.0625)
        assert np.array_equal(vf, one_vf) and np.array_equal(ee, one_ee)
        found += len(vf) + len(ee)
    assert found > 0
    with pytest.raises(tailor.InputError):
        search.pairs(x, -1.0)
