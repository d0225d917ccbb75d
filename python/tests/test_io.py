"""tailor.read_mesh / write_mesh / Mesh: the arrays (no copies), round trips, and bad
input with the CLI's messages and error types."""

import numpy as np
import pytest

import tailor
from conftest import cli_error


def test_read_mesh_gives_the_reader_storage_without_a_copy(data_dir):
    vertices, faces = tailor.read_mesh(data_dir / "cloth-funnel/frames/227.ply")
    assert vertices.shape == (9450, 3) and vertices.dtype == np.float64
    assert faces.shape == (18484, 3) and faces.dtype == np.int32
    # The arrays adopt the C++ storage: they own nothing, a capsule does.
    assert not vertices.flags.owndata and not faces.flags.owndata
    assert type(vertices.base).__name__ == "PyCapsule"
    assert vertices.flags.c_contiguous and vertices.flags.writeable
    assert faces.min() >= 0 and faces.max() < len(vertices)


def test_mesh_arrays_are_read_only_views_of_the_mesh(data_dir):
    _, faces = tailor.read_mesh(data_dir / "cloth-funnel/frames/227.ply")
    mesh = tailor.Mesh(faces)
    assert (mesh.num_vertices, mesh.num_faces) == (9450, 18484)
    assert np.array_equal(mesh.faces, faces)
    first, second = mesh.faces, mesh.faces
    assert first.ctypes.data == second.ctypes.data  # the same storage, not a copy per access
    with pytest.raises(ValueError):
        first[0, 0] = 1
    edges = mesh.edges
    assert edges.shape == (mesh.num_edges, 2) and np.all(edges[:, 0] < edges[:, 1])
    # Sorted by (b, a), the order of the reference data.
    keys = edges[:, 1].astype(np.int64) * mesh.num_vertices + edges[:, 0]
    assert np.all(np.diff(keys) > 0)
    a, b = edges[17]
    assert mesh.find_edge(b, a) == 17 and mesh.find_edge(0, 0) == -1
    assert mesh.num_components >= 1 and len(mesh.face_components) == mesh.num_faces
    loops = [mesh.boundary_loop(i) for i in range(mesh.num_boundary_loops)]
    assert sum(len(loop) for loop in loops) > 0
    with pytest.raises(IndexError):
        mesh.boundary_loop(mesh.num_boundary_loops)


def test_a_mesh_outlives_the_python_reference_its_arrays_came_from():
    faces = tailor.Mesh(np.array([[0, 1, 2], [0, 2, 3]])).faces  # the Mesh object is gone
    assert faces.tolist() == [[0, 1, 2], [0, 2, 3]]


@pytest.mark.parametrize("extension", ["ply", "obj"])
def test_write_then_read_round_trip(tmp_path, data_dir, extension):
    vertices, faces = tailor.read_mesh(data_dir / "thick-cloth/t0.ply")
    path = tmp_path / f"copy.{extension}"
    tailor.write_mesh(path, vertices, faces)
    again, again_faces = tailor.read_mesh(str(path))
    assert np.array_equal(again_faces, faces)
    assert np.array_equal(again, vertices)  # both formats keep every bit of a double


def test_a_missing_file_is_file_not_found_with_the_cli_message(tmp_path):
    path = tmp_path / "absent.ply"
    with pytest.raises(FileNotFoundError) as error:
        tailor.read_mesh(path)
    assert str(error.value) == cli_error("info", path)
    assert "absent.ply" in str(error.value)


def test_a_folder_is_an_os_error(tmp_path):
    folder = tmp_path / "folder.ply"
    folder.mkdir()
    with pytest.raises(OSError) as error:
        tailor.read_mesh(folder)
    assert "folder.ply" in str(error.value)


def test_a_truncated_file_is_an_input_error_with_the_cli_message(tmp_path, data_dir):
    data = (data_dir / "thick-cloth/t0.ply").read_bytes()
    path = tmp_path / "cut.ply"
    path.write_bytes(data[: len(data) // 2])
    with pytest.raises(tailor.InputError) as error:
        tailor.read_mesh(path)
    assert isinstance(error.value, ValueError)
    assert str(error.value) == cli_error("info", path)
    assert "cut.ply" in str(error.value) and "truncated" in str(error.value)


def test_bad_content_and_names_are_value_errors(tmp_path):
    nan = tmp_path / "nan.obj"
    nan.write_text("v 0 0 0\nv 1 0 nan\nv 0 1 0\nf 1 2 3\n")
    with pytest.raises(ValueError) as error:
        tailor.read_mesh(nan)
    assert str(error.value) == cli_error("info", nan)
    unknown = tmp_path / "mesh.stl"
    unknown.write_text("solid x\n")
    with pytest.raises(ValueError, match="mesh.stl"):
        tailor.read_mesh(unknown)
    with pytest.raises(ValueError, match="out of range"):
        tailor.write_mesh(tmp_path / "bad.ply", np.zeros((3, 3)), [[0, 1, 5]])


def test_bad_faces_are_value_errors():
    with pytest.raises(ValueError, match="face 1 repeats a vertex"):
        tailor.Mesh([[0, 1, 2], [2, 2, 3]])
    with pytest.raises(ValueError, match="face 0 has vertex index -1 out of range"):
        tailor.Mesh([[-1, 1, 2]], num_vertices=3)
    with pytest.raises(ValueError, match=r"faces must be an array of shape \(n, 3\)"):
        tailor.Mesh([[0, 1]])
    with pytest.raises(ValueError, match="faces must be"):
        tailor.Mesh([[0.0, 1.5, 2.0]])
    with pytest.raises(ValueError, match="outside the int32 range"):
        tailor.Mesh([[0, 1, 2**40]])
