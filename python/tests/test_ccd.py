"""tailor.ccd_vertex_face / ccd_edge_edge against the exact ground truth of the reference
queries, their array handling (no copies of float64 C-contiguous input), bad input, and
the GIL."""

import json

import numpy as np
import pytest

import tailor
from conftest import assert_releases_gil, read_queries, reference_query_files

CCD = {"vertex-face": tailor.ccd_vertex_face, "edge-edge": tailor.ccd_edge_edge}


def test_sample_queries_match_the_ground_truth(data_dir):
    total = colliding = 0
    for path, kind in reference_query_files(data_dir):
        points, truth = read_queries(path)
        assert truth is not None and len(truth) == len(points[0]), path
        before = tailor._input_copies()
        hit, toi = CCD[kind](*points)
        assert tailor._input_copies() == before, "float64 C-contiguous input was copied"
        assert hit.dtype == bool and toi.dtype == np.float64
        mismatches = np.flatnonzero(hit != truth)
        assert mismatches.size == 0, f"{path}: queries {mismatches[:10]} disagree with the truth"
        assert np.all((toi >= 0) & (toi <= 1)), path
        assert np.all(toi[~hit] == 1.0), path
        total += len(truth)
        colliding += int(truth.sum())
    # The counts of the data's README: every query was checked.
    assert (total, colliding) == (5029, 329)


@pytest.mark.parametrize("kind,expected", [("vf", 27), ("ee", 107)])
def test_cloth_funnel_queries_match_the_ground_truth(data_dir, kind, expected):
    points, _ = read_queries(data_dir / f"cloth-funnel/queries/227{kind}.csv", truth_column=False)
    truth = np.array(json.loads((data_dir / f"cloth-funnel/mma_bool/227{kind}_mma_bool.json").read_text()))
    assert len(truth) == len(points[0])
    ccd = tailor.ccd_vertex_face if kind == "vf" else tailor.ccd_edge_edge
    hit, _ = ccd(*points)
    assert np.array_equal(hit, truth)
    assert hit.sum() == expected


@pytest.fixture
def unit_queries(data_dir):
    points, truth = read_queries(data_dir / "ccd-queries/unit-tests/vertex-face/data_0_0.csv")
    return points, truth


def test_other_layouts_and_thread_counts_give_the_same_answers(unit_queries):
    points, truth = unit_queries
    expected_hit, expected_toi = tailor.ccd_vertex_face(*points)
    assert np.array_equal(expected_hit, truth)

    before = tailor._input_copies()
    fortran = [np.asfortranarray(p) for p in points]
    hit, toi = tailor.ccd_vertex_face(*fortran)
    assert tailor._input_copies() == before + 8  # each converted once
    assert np.array_equal(hit, expected_hit) and np.array_equal(toi, expected_toi)

    hit, toi = tailor.ccd_vertex_face(*[p.tolist() for p in points])
    assert np.array_equal(hit, expected_hit) and np.array_equal(toi, expected_toi)

    hit, toi = tailor.ccd_vertex_face(*points, threads=1)
    assert np.array_equal(hit, expected_hit) and np.array_equal(toi, expected_toi)


def test_an_empty_batch_gives_empty_results():
    empty = np.zeros((0, 3))
    hit, toi = tailor.ccd_edge_edge(*[empty] * 8)
    assert hit.shape == (0,) and toi.shape == (0,)


def test_a_moving_point_hits_a_triangle_at_the_right_time():
    # The point falls through the triangle z = 0 at t = 0.25.
    p0, p1 = np.array([[0.2, 0.2, 1.0]]), np.array([[0.2, 0.2, -3.0]])
    a, b, c = np.array([[0.0, 0, 0]]), np.array([[1.0, 0, 0]]), np.array([[0.0, 1, 0]])
    hit, toi = tailor.ccd_vertex_face(p0, a, b, c, p1, a, b, c)
    assert hit[0] and 0.25 - 1e-6 <= toi[0] <= 0.25
    # Beside the triangle: no hit.
    hit, toi = tailor.ccd_vertex_face(p0 + 2, a, b, c, p1 + 2, a, b, c)
    assert not hit[0] and toi[0] == 1.0


def test_bad_input_raises_value_error(unit_queries):
    points, _ = unit_queries
    with pytest.raises(ValueError, match=r"c1 has \d+ rows, p0 has \d+"):
        tailor.ccd_vertex_face(*points[:7], points[7][:-1])
    bad = points[3].copy()
    bad[5, 1] = np.nan
    with pytest.raises(ValueError, match="c0 has a non-finite coordinate in row 5"):
        tailor.ccd_vertex_face(*points[:3], bad, *points[4:])
    bad[5, 1] = np.inf
    with pytest.raises(ValueError, match="d0 has a non-finite coordinate in row 5"):
        tailor.ccd_edge_edge(*points[:3], bad, *points[4:])
    with pytest.raises(ValueError, match=r"a1 must be an array of shape \(n, 3\).*got shape \(4, 2\)"):
        tailor.ccd_vertex_face(*points[:5], np.zeros((4, 2)), *points[6:])
    with pytest.raises(ValueError, match="p0 must be an array"):
        tailor.ccd_vertex_face(np.array([["x", "y", "z"]]), *points[1:])
    with pytest.raises(ValueError, match="threads"):
        tailor.ccd_vertex_face(*points, threads=-1)


def test_ccd_batches_release_the_gil(data_dir):
    # Degenerate queries (many reach the exact path), repeated to make one long call.
    points, _ = read_queries(data_dir / "ccd-queries/unit-tests/edge-edge/data_0_0.csv")

    def make_call(scale):
        tiled = [np.ascontiguousarray(np.tile(p, (scale, 1))) for p in points]
        return lambda: tailor.ccd_edge_edge(*tiled, threads=1)

    assert_releases_gil(make_call)
