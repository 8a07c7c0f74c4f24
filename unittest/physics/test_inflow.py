# SPDX-License-Identifier: GPL-2.0-only (GRANSPH: LICENSE)
"""fix sph/inflow: a jet into empty space (in.inflow).

Layer k leaves the nozzle plane at t_k = k dx / v (the first at t = 0, the setup
of the run) and enters on the first step whose midpoint reaches t_k, so after a
run that ends at time t with step dt, floor(v (t - dt/2) / dx) + 1 layers of
the same lattice are in. Checked: the counts; every layer is v (t - t_k) in
front of the nozzle (so consecutive layers are dx apart) within 1e-6 dx, also
across a change of timestep; a restarted run ends as the uninterrupted one; the jet moves at v along n; with
`wave`, the centre of layer k is A0 sin(2 pi f0 t_k) off the nozzle axis; with
`until`, no layer leaves after that time; a jet of a material of its own is of that
material and starts at its density; bad input stops with an error that
names the problem."""

import math
import os
import re
import subprocess
import tempfile

import numpy as np

import gransph_run

HERE = os.path.dirname(os.path.abspath(__file__))
INPUT = os.path.join(HERE, "in.inflow")
DX, R, V = 0.004, 0.01, 10.0

check = gransph_run.Checks()


def run(tmp, variables, ranks=1):
    """Run in.inflow; return (time, dt, layers, particles) and the dump."""
    out = gransph_run.run(INPUT, variables, ranks=ranks, cwd=tmp)
    words = next(l for l in out.splitlines() if l.startswith("inflow:")).split()
    counts = float(words[2]), float(words[4]), int(float(words[6])), int(float(words[8]))
    return counts, gransph_run.read_dump(os.path.join(tmp, "inflow.dump"))


def per_layer():
    """Lattice points (i, j) dx within R of the nozzle centre."""
    n = int(R / DX) + 1
    return sum(1 for i in range(-n, n + 1) for j in range(-n, n + 1) if (i * i + j * j) * DX**2 <= R**2 * (1 + 1e-10))


def check_jet(name, counts, d, center, normal, wave=None):
    t, dt, layers, particles = counts
    n = np.array(normal, float) / np.linalg.norm(normal)
    x = np.column_stack([d["x"], d["y"], d["z"]]) - np.array(center)
    s = x @ n                                        # distance in front of the nozzle plane
    k = np.rint((V * t - s) / DX).astype(int)        # layer index, s_k = v (t - k dx / v)
    expected_layers = math.floor(V * (t - 0.5 * dt) / DX) + 1
    check(f"{name}: layers", layers == expected_layers and k.max() == layers - 1 and k.min() == 0,
          f"{layers} inserted by t = {t:.6g} s, floor(v (t - dt/2) / dx) + 1 = {expected_layers}")
    sizes = np.bincount(k, minlength=layers)
    check(f"{name}: particles", particles == len(s) == layers * per_layer() and np.all(sizes == per_layer()),
          f"{particles} = {layers} layers x {per_layer()} per layer")
    position_error = np.max(np.abs(s - (V * t - k * DX))) / DX
    gaps = np.diff([s[k == i].mean() for i in range(layers)])
    spacing_error = np.max(np.abs(-gaps - DX)) / DX
    check(f"{name}: spacing", position_error < 1e-6 and spacing_error < 1e-6,
          f"layer position error {position_error:.1e} dx, spacing dx within {spacing_error:.1e}")
    vel = np.column_stack([d["vx"], d["vy"], d["vz"]])
    along = vel @ n
    lateral = np.linalg.norm(vel - np.outer(along, n), axis=1)
    check(f"{name}: velocity", abs(along.mean() / V - 1) < 0.01 and lateral.max() < 0.01 * V,
          f"mean speed along n {along.mean():.6g} m/s (v = {V}), max lateral {lateral.max():.1e} m/s")
    if wave:
        a0, f0, e = wave
        e = np.array(e, float) / np.linalg.norm(e)
        offset = np.array([(x[k == i] @ e).mean() for i in range(layers)])
        expected = a0 * np.sin(2 * np.pi * f0 * np.arange(layers) * DX / V)
        error = np.max(np.abs(offset - expected)) / DX
        check(f"{name}: wave", error < 1e-6,
              f"layer centres follow A0 sin(2 pi f0 t_k) within {error:.1e} dx over {layers * DX * f0 / V:.2f} periods")


def expect_error(tmp, name, variables, message):
    cmd = ["stdbuf", "-oL", gransph_run.LMP, "-in", INPUT, "-log", "none", "-echo", "none"]
    for key, value in {"steps": 10, **variables}.items():
        cmd += ["-var", key, str(value)]
    proc = subprocess.run(cmd, cwd=tmp, capture_output=True, text=True, timeout=120)
    errors = [l for l in (proc.stdout + proc.stderr).splitlines() if "ERROR" in l]
    check(f"error, {name}", proc.returncode != 0 and errors and re.search(message, errors[0]),
          errors[0] if errors else "no error")


with tempfile.TemporaryDirectory() as tmp:
    # oblique jet, CFL timestep
    counts, d = run(tmp, {"steps": 600})
    check_jet("oblique", counts, d, (-0.05, -0.05, -0.05), (1, 1, 1))
    # a jet of a material of its own: the inflow's group is the material's
    light = os.path.join(HERE, "light.gransph")
    counts, d = run(tmp, {"steps": 600, "group": "sand", "jet_group": "bed",
                          "fix_options": f"material bed {light} Light1500"})
    check_jet("of a second material", counts, d, (-0.05, -0.05, -0.05), (1, 1, 1))
    check("of a second material: its grains", np.all(d["c_material"] == 2)
          and abs(np.mean(d["f_sph[1]"]) / 1500 - 1) < 0.01,
          f"materials {sorted(set(d['c_material']))}, mean density {np.mean(d['f_sph[1]']):.1f} kg/m3 (1500)")

    # a fixed timestep changed between two runs, then the second run again from
    # the restart file written between them
    fixed = {"cfl": "none", "dt": 1e-5, "steps": 500, "steps2": 300, "dt2": 2.5e-5}
    counts, d = run(tmp, fixed)
    check_jet("timestep change", counts, d, (-0.05, -0.05, -0.05), (1, 1, 1))
    counts_b, d_b = run(tmp, {**fixed, "restart": 1})
    same = counts_b[2:] == counts[2:] and np.array_equal(d_b["id"], d["id"])
    diff = max(np.max(np.abs(d_b[c] - d[c])) for c in ("x", "y", "z", "vx", "vy", "vz")) if same else np.inf
    check("restart", same and diff < 1e-12,
          f"restarted run: {counts_b[2]} layers, {counts_b[3]} particles; max difference {diff:.1e}")

    # wavy vertical jet on 2 ranks; the nozzle is above the shrink-wrapped box,
    # which grows to take in each new layer
    wave = (0.002, 160.0, (1, 0, 0))
    counts, d = run(tmp, {"steps": 1200, "bnd": "m", "top": 0.0, "center": "0 0 0.08",
                          "normal": "0 0 -1", "extra": "wave 0.002 160 1 0 0"}, ranks=2)
    check_jet("wave, 2 ranks, shrink-wrapped", counts, d, (0, 0, 0.08), (0, 0, -1), wave)

    # until: layers leave at t_k = 0, 0.4, 0.8 ms only
    counts, _ = run(tmp, {"steps": 300, "extra": "until 0.001"})
    check("until", counts[2] == 3 and counts[3] == 3 * per_layer(),
          f"{counts[2]} layers, {counts[3]} particles by t = {counts[0]:.3g} s with until 0.001")

    expect_error(tmp, "zero normal", {"normal": "0 0 0"}, "normal must not be zero")
    expect_error(tmp, "wave not perpendicular", {"extra": "wave 0.002 160 1 0 0"},
                 "wave direction must be perpendicular to the normal")
    expect_error(tmp, "wave without values", {"extra": "wave 0.002"}, "keyword wave needs 5 value")
    expect_error(tmp, "radius", {"R": 0}, "radius must be > 0")
    expect_error(tmp, "type", {"extra": "type 2"}, "type 2 is out of range 1-1")
    expect_error(tmp, "mass with per-type masses", {"extra": "mass 1"}, "keyword mass needs an atom style")
    expect_error(tmp, "unknown keyword", {"extra": "foo 1"}, "unknown keyword foo")
    expect_error(tmp, "group not integrated", {"group": "sand"},
                 "group all is not integrated: the integrator fix sph acts on group sand")
    expect_error(tmp, "nozzle outside the box", {"center": "0 0 0.2"}, "new particles lie outside the box")

check.finish()
