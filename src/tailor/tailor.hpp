#pragma once
/// @file
/// The front door: everything a program needs to find the self-collisions of a cloth.
///
///     #include "tailor/tailor.hpp"
///
///     tailor::MeshData t0 = tailor::read_mesh("t0.ply"), t1 = tailor::read_mesh("t1.ply");
///     tailor::TriangleMesh mesh(static_cast<tailor::Index>(t0.vertices.rows()), t0.faces);
///     // One step:
///     tailor::DetectionResult step = tailor::detect_self_collisions(mesh, t0.vertices,
///                                                                   t1.vertices);
///     // Many steps of one mesh: build once, detect per step.
///     tailor::SelfCollisionDetector detector(mesh, t0.vertices,
///                                            tailor::DetectionConfig::preset("paper"));
///     step = detector.detect(t0.vertices, t1.vertices);
///
/// Brings in: the mesh (TriangleMesh, MeshData, Positions), reading and writing meshes, frame
/// sequences and the SequenceChecker, radial-view observer files, the detector
/// (SelfCollisionDetector, detect_self_collisions), its DetectionConfig, DetectionResult,
/// DetectionStats, the static intersection check, brute force (the oracle) and InputError.
/// Only for programs using the library: no file under src/tailor/ includes it (the ctest
/// `layering` checks that it includes only the core library's modules and that no module
/// includes it). The simulation (tailor::sim) has its own headers under tailor/scene,
/// tailor/sim and tailor/render.

#include "tailor/geometry/error.hpp"
#include "tailor/geometry/types.hpp"
#include "tailor/mesh/mesh_data.hpp"
#include "tailor/mesh/triangle_mesh.hpp"
#include "tailor/io/frame_sequence.hpp"
#include "tailor/io/mesh_io.hpp"
#include "tailor/io/observer_loops.hpp"
#include "tailor/detection/brute_force.hpp"
#include "tailor/detection/collision_free_step.hpp"
#include "tailor/detection/collision.hpp"
#include "tailor/detection/detect_self_collisions.hpp"
#include "tailor/detection/detection_config.hpp"
#include "tailor/detection/detection_stats.hpp"
#include "tailor/detection/intersection_check.hpp"
#include "tailor/detection/proximity_pairs.hpp"
#include "tailor/detection/self_collision_detector.hpp"
#include "tailor/detection/sequence_check.hpp"
