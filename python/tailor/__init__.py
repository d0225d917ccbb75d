"""tailor: exact continuous self-collision detection for cloth.

Every vertex-face and edge-edge pair of a deforming triangle mesh that touches during a
linear time step, found by the two-level culling pipeline of *Self-collision Detection
Optimization Method in the Arm Clothes Simulation* and decided by an exact CCD; plus the
arm-sleeve cloth simulation it was designed for. See docs/design.md in the repository.

One step: ``tailor.detect(mesh, x0, x1, method="paper")``, the one-off form (C++
``tailor::detect_self_collisions``); many steps of one mesh: build a
``SelfCollisionDetector(mesh, x0)`` once and call ``detect(x0, x1)`` per step (the BVH is
built once). ``method`` is a preset name (basic, curtis, tang, paper) or a DetectionConfig;
``DetectionConfig.settings()`` lists every setting with its default, range and whether it
keeps the result exact, ``DetectionResult.stat_fields()`` every key of ``result.stats``
(docs/settings.md in the repository). One configuration: ``proximity_pairs(mesh, x,
thickness)``, every pair within a thickness (for repulsion and barrier methods), and
``ProximitySearch(mesh).pairs(x, thickness)`` for the same step after step. With a
thickness: ``detect(..., thickness=h)`` (every pair that comes within h, at the earliest
time) and ``collision_free_step(mesh, x0, x1, h)`` (the fraction of a step that keeps
every pair farther than h apart).

Arrays: positions are (n, 3) float64, faces (m, 3) integer vertex ids. float64
C-contiguous arrays are read in place where the C++ API allows (CCD batches; the
`x0`/`x1` buffers of a SelfCollisionDetector); the GIL is released while C++ works. Bad
input raises InputError (a ValueError) with the message the `tailor` CLI prints, and a
file that cannot be opened raises OSError (FileNotFoundError when it does not exist).
"""

from dataclasses import dataclass
import os

import numpy as np

from ._tailor import (
    DetectionConfig,
    DetectionResult,
    InputError,
    Mesh,
    ProximitySearch,
    SceneConfig,
    SelfCollisionDetector,
    Simulation,
    brute_force,
    collision_free_step,
    proximity_pairs,
    ccd_edge_edge,
    ccd_vertex_face,
    check_sequence,
    detect,
    read_mesh,
    write_mesh,
)
from ._tailor import _input_copies  # noqa: F401  (for tests: copies of input arrays so far)

__all__ = [
    "DetectionConfig",
    "DetectionResult",
    "Frame",
    "InputError",
    "Mesh",
    "ProximitySearch",
    "SceneConfig",
    "SelfCollisionDetector",
    "Simulation",
    "brute_force",
    "collision_free_step",
    "proximity_pairs",
    "ccd_edge_edge",
    "ccd_vertex_face",
    "check_sequence",
    "detect",
    "read_mesh",
    "simulate",
    "write_mesh",
]


@dataclass
class Frame:
    """One simulated frame of the arm-sleeve scene."""

    index: int  #: 1 for the first frame simulated
    time: float  #: simulated time at its end (s)
    cloth: np.ndarray  #: (n, 3) cloth positions
    arm: np.ndarray  #: (m, 3) skinned arm positions
    cloth_faces: np.ndarray  #: (f, 3) sleeve faces (the same array every frame)
    arm_faces: np.ndarray  #: (g, 3) arm faces
    steps: list  #: the frame's substeps as dicts (as in steps.jsonl)
    simulation: Simulation  #: the run (summary(), observer_loops, cloth_mesh, ...)


def _scene_config(scene):
    if scene is None:
        return SceneConfig()
    if isinstance(scene, SceneConfig):
        return scene
    if isinstance(scene, dict):
        return SceneConfig.from_dict(scene)
    if isinstance(scene, (str, os.PathLike)):
        return SceneConfig.load(scene)
    raise ValueError("scene must be None, a SceneConfig, a dict or the path of a scene file")


def simulate(scene=None, frames=None, *, gesture=None, method="paper", threads=0,
             check_intersections=False):
    """Runs the arm-sleeve simulation: an iterator over the frames (Frame), each computed
    when it is asked for.

    `scene`: None (the built-in scene), a SceneConfig, a dict shaped like the scene file,
    or the path of a scene file. `frames`: how many to simulate (default: the scene's).
    `gesture`: elbow, raise or twist (default: the scene's). `method`: detection preset or
    DetectionConfig. `check_intersections`: run the static intersection check after every
    substep (it always runs after every frame; Simulation.summary() has the counts).
    """
    config = _scene_config(scene)
    count = config.frames if frames is None else frames
    if not isinstance(count, int) or isinstance(count, bool) or count < 0:
        raise ValueError(f"frames must be an integer ≥ 0, got {frames!r}")
    # Built now, so that bad settings raise here rather than at the first frame.
    simulation = Simulation(config, gesture=gesture, method=method, threads=threads,
                            check_intersections=check_intersections)
    return _frames(simulation, count)


def _frames(simulation, count):
    cloth_faces = simulation.cloth_mesh.faces
    arm_faces = simulation.arm_mesh.faces
    for _ in range(count):
        steps = simulation.step_frame()
        yield Frame(simulation.frame, simulation.time, simulation.cloth_positions,
                    simulation.arm_positions, cloth_faces, arm_faces, steps, simulation)
