# SPDX-License-Identifier: GPL-2.0-only (GRANSPH: LICENSE)
"""fix sph/move: a sand layer settling on a floor, with everything moving
sideways at 5 m/s, matches the same run at rest (Galilean invariance: the floor
is where the grains are in time when the pair runs, and it, with its ghosts,
has the fix's velocity from the setup on, though the input gives it none); and a
floor accelerated from rest at a covers a t^2 / 2 at the integrator's adaptive
timestep."""

import os
import re
import tempfile

import numpy as np

import gransph_run

HERE = os.path.dirname(os.path.abspath(__file__))
INPUT = os.path.join(HERE, "in.moving_wall")
VW, A = 5.0, 3.0
KOKKOS = ("-k", "on", "t", "2", "-sf", "kk")
check = gransph_run.Checks()


def settle(tmp, vw, args=()):
    gransph_run.run(INPUT, {"vw": vw}, args=args, cwd=tmp)
    d = gransph_run.read_dump(os.path.join(tmp, "moving_wall.dump"))
    d["vx"] = d["vx"] - vw
    return d


with tempfile.TemporaryDirectory() as tmp:
    for name, args in [("plain", ()), ("kk", KOKKOS)]:
        rest, moving = settle(tmp, 0.0, args), settle(tmp, VW, args)
        if name == "plain":
            check("the layer moved", np.max(np.abs(rest["vz"])) > 1e-3,
                  f"max |vz| {np.max(np.abs(rest['vz'])):.2e} m/s")
        # scales: a sideways velocity or a shear stress is zero at rest but for round-off
        speed, stress = np.max(np.abs(rest["vz"])), np.max(np.abs(rest["f_sph[4]"]))
        scales = {"z": np.max(np.abs(rest["z"])), "vx": speed, "vz": speed,
                  "f_sph[1]": np.max(rest["f_sph[1]"]), "f_sph[2]": stress, "f_sph[4]": stress,
                  "f_sph[5]": stress}
        for column, scale in scales.items():
            diff = np.max(np.abs(moving[column] - rest[column])) / scale
            check(f"{name} {column:8s} at {VW} m/s = at rest", diff < 1e-9,
                  f"max difference {diff:.2e} of the scale {scale:.3g}")

    for name, args in [("plain", ()), ("kk", KOKKOS)]:
        gransph_run.run(INPUT, {"a": A, "steps": 0}, args=args, cwd=tmp)
        x0 = gransph_run.read_dump(os.path.join(tmp, "floor.dump"))["xu"]
        out = gransph_run.run(INPUT, {"a": A}, args=args, cwd=tmp)
        t = float(re.search(r"^time (\S+)", out, re.M).group(1))
        floor = gransph_run.read_dump(os.path.join(tmp, "floor.dump"))
        error = np.max(np.abs(floor["xu"] - x0 - 0.5 * A * t * t)) / (0.5 * A * t * t)
        check(f"{name} floor accelerated at {A} m/s^2 covers a t^2/2", error < 1e-9,
              f"t {t:.4g} s, relative error {error:.2e}")
        check(f"{name} floor velocity a t", abs(floor["vx"][0] - A * t) < 1e-9 * A * t,
              f"{floor['vx'][0]:.6g} m/s")
check.finish()
