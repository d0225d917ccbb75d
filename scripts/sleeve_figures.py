#!/usr/bin/env python3
"""The sleeve's figures for docs/simulation.md: for the default sleeve (21 x 33) and the
10x sleeve (66 x 104), each gesture, frames per second and milliseconds per stage on 1
and 2 threads, then a run with --check-frames on 2 threads for the credibility columns
(max / p99 edge strain and end extent from the written OBJs, self-collisions per frame,
intersections, reverted, unresolved). Prints the Markdown table.

    python3 scripts/sleeve_figures.py [--tailor build/release/tailor] [--out DIR]

Needs NumPy (Debian python3-numpy). About 3 minutes on 2 cores."""

import argparse
import glob
import json
import os
import subprocess
import tempfile

import numpy as np

SLEEVES = {"1×": [], "10×": ["--rings", "66", "--segments", "104"]}
GESTURES = ["elbow", "raise", "twist"]


def simulate(tailor, folder, args):
    subprocess.run([tailor, "simulate", "--out", folder, "--no-contacts"] + args, check=True,
                   stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    with open(os.path.join(folder, "summary.json")) as f:
        return json.load(f)


def read_obj(path):
    vertices, faces = [], []
    with open(path) as f:
        for line in f:
            if line.startswith("v "):
                vertices.append([float(t) for t in line.split()[1:4]])
            elif line.startswith("f "):
                faces.append([int(t.split("/")[0]) - 1 for t in line.split()[1:4]])
    return np.array(vertices), np.array(faces)


def strain_and_extent(folder):
    """Largest and 99th-percentile edge strain over the frames, and the end extent."""
    files = sorted(glob.glob(os.path.join(folder, "cloth_*.obj")))
    x0, faces = read_obj(files[0])
    edges = np.unique(np.sort(np.concatenate([faces[:, [0, 1]], faces[:, [1, 2]],
                                              faces[:, [2, 0]]]), axis=1), axis=0)
    rest = np.linalg.norm(x0[edges[:, 0]] - x0[edges[:, 1]], axis=1)
    largest = p99 = 0.0
    for path in files[1:]:
        x, _ = read_obj(path)
        strain = np.linalg.norm(x[edges[:, 0]] - x[edges[:, 1]], axis=1) / rest - 1
        largest, p99 = max(largest, strain.max()), max(p99, np.percentile(strain, 99))
    x_end, _ = read_obj(files[-1])
    extent = np.ptp(x_end[:, 0]) / np.ptp(x0[:, 0])
    return largest, p99, extent


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--tailor", default="build/release/tailor")
    parser.add_argument("--out", default=None, help="where the runs go (default: a temp dir)")
    options = parser.parse_args()
    out = options.out or tempfile.mkdtemp(prefix="sleeve_figures_")
    print("| sleeve | gesture | fps, 1 thread | fps, 2 threads | ms per step, 2 threads: "
          "assembly / factor + solve / strain limit + arm / detection / response | "
          "max / p99 strain | end extent | self-collisions / frame | intersections |")
    print("|---|---|---:|---:|---|---|---:|---:|---|")
    for sleeve, extra in SLEEVES.items():
        for gesture in GESTURES:
            base = ["--gesture", gesture] + extra
            fps = {}
            for threads in ("1", "2"):
                run = simulate(options.tailor, os.path.join(out, f"{sleeve}_{gesture}_{threads}"),
                               base + ["--threads", threads])
                fps[threads] = run["frames_per_second"]
                ms = run["ms_per_step"]
            folder = os.path.join(out, f"{sleeve}_{gesture}_check")
            check = simulate(options.tailor, folder, base + ["--threads", "2", "--check-frames"])
            largest, p99, extent = strain_and_extent(folder)
            stages = " / ".join(f"{ms[k]:.2f}" for k in
                                ("assemble", "solve", "strain_limit", "detection", "response"))
            print(f"| {sleeve} | {gesture} | {fps['1']:.1f} | {fps['2']:.1f} | {stages} | "
                  f"{100 * largest:.2f} / {100 * p99:.2f} % | {100 * extent:.1f} % | "
                  f"{check['self_collisions'] / check['frames']:.1f} | "
                  f"{check['intersections']} in {check['checked_steps']} steps "
                  f"(reverted {check['reverted_vertices']}, unresolved {check['unresolved']}) |",
                  flush=True)


if __name__ == "__main__":
    main()
