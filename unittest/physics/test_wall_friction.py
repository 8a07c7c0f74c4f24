# SPDX-License-Identifier: GPL-2.0-only (GRANSPH: LICENSE)
"""Walls with a friction of their own (pair_style sph/granular wall/friction): a sand
layer on a floor of interface friction angle delta (in.wall_friction)

- on a slope, holds at delta - 1.5 degrees and slides at delta + 1.5 degrees, for layers
  of 1 and 4 particles, both models, strips 4 to 16 columns wide, dx 0.02 and 0.01 m;
- set sliding at 1 m/s on the level floor, is pushed back with the floor's tangential
  force at tan(delta) times its normal force (within 3% for a single layer) and
  decelerates at g tan(delta) (within 5%); down a slope of 10 degrees at
  g (tan(delta) cos(theta) - sin(theta)) (within 5%); pushed at 5 cm/s 1.5 degrees below
  delta, stops and holds;
- on a slip floor keeps its speed within 1% over 0.5 s;
- on a floor of two halves of different delta, each half gives its own friction;
- gives the same history, and the same virial, on 1 and 2 MPI ranks (how the grains
  slide reaches the ghosts; the dummies tally the whole virial of their pairs, ghosts'
  pairs included), and with the /kk styles on 2 threads (LAMMPS 29Sep2021 under Kokkos cannot
  pass the floor's normals to the periodic images: there the pair style refuses).
The rough floor (no wall/friction) is tested unchanged by test_slope.py and test_slide.py."""

import math
import os
import tempfile

import numpy as np

import gransph_run

HERE = os.path.dirname(os.path.abspath(__file__))
G = 9.81
KOKKOS = ["-k", "on", "t", "2", "-sf", "kk"]


def run(tmp, ranks=1, args=(), **variables):
    """the columns of wall_friction.txt: t, vx, fx1, fz1, fx2, fz2"""
    gransph_run.run(os.path.join(HERE, "in.wall_friction"), variables, ranks=ranks, args=args,
                    cwd=tmp)
    return np.loadtxt(os.path.join(tmp, "wall_friction.txt"), unpack=True)


def virial(tmp):
    """the last run's virial record: t, xx, yy, zz, xy, xz, yz"""
    return np.loadtxt(os.path.join(tmp, "wall_friction_virial.txt"), unpack=True)


def slope(t, v):
    """the mean rate of change of v over the second half of the record"""
    late = t >= 0.5 * t[-1]
    return np.polyfit(t[late], v[late], 1)[0]


def sliding(t, v, v0):
    """the record's part while the layer slides between 0.9 and 0.3 of v0"""
    return (v < 0.9 * v0) & (v > 0.3 * v0)


check = gransph_run.Checks()
with tempfile.TemporaryDirectory() as tmp:
    # hold and slide on a slope
    cases = [("elastoplastic", 15, 1, 0.02, 6), ("elastoplastic", 25, 1, 0.02, 6),
             ("elastoplastic", 15, 4, 0.02, 6), ("elastoplastic", 25, 4, 0.02, 6),
             ("elastoplastic", 25, 1, 0.02, 4), ("elastoplastic", 25, 1, 0.02, 16),
             ("elastoplastic", 15, 1, 0.01, 6), ("phasechange", 15, 1, 0.02, 6),
             ("phasechange", 25, 4, 0.02, 6), ("phasechange", 15, 1, 0.02, 4),
             ("phasechange", 25, 1, 0.02, 16), ("elastoplastic", 25, 4, 0.01, 6),
             ("elastoplastic", 25, 1, 0.01, 16), ("phasechange", 25, 1, 0.01, 6),
             ("phasechange", 15, 4, 0.01, 16)]
    for model, delta, layers, dx, width in cases:
        case = f"{model}, delta {delta}, {layers} layer(s), dx {dx}, {width} columns"
        below, above = delta - 1.5, delta + 1.5
        t, v, *_ = run(tmp, model=model, delta1=delta, layers=layers, dx=dx, width=width,
                       theta=below)
        a = slope(t, v)
        check(f"{case}: holds at {below} deg", abs(v[-1]) < 0.01 and abs(a) < 0.02,
              f"v {v[-1]:.2e} m/s, a {a:.2e} m/s^2")
        t, v, *_ = run(tmp, model=model, delta1=delta, layers=layers, dx=dx, width=width,
                       theta=above)
        a = slope(t, v)
        a_free = G * (math.sin(math.radians(above)) -
                      math.tan(math.radians(delta)) * math.cos(math.radians(above)))
        check(f"{case}: slides at {above} deg", a > 0.5 * a_free,
              f"a {a:.3f} m/s^2 (sliding at the wall's friction {a_free:.3f})")

    # a layer set sliding on the level floor
    for delta, layers, tolerance in ((15, 1, 0.03), (25, 1, 0.03), (15, 4, 0.05), (25, 4, 0.05)):
        t, v, fx1, fz1, fx2, fz2 = run(tmp, delta1=delta, layers=layers, v0=1.0, tmeas=0.5)
        window = sliding(t, v, 1.0)
        assert window.sum() > 10, "the layer did not slow down through the window"
        mu = math.tan(math.radians(delta))
        # the grains push the floor down (fz < 0) and drag it along (fx > 0)
        ratio = (fx1[window] + fx2[window]).sum() / -(fz1[window] + fz2[window]).sum()
        decel = -np.polyfit(t[window], v[window], 1)[0] / G
        case = f"delta {delta}, {layers} layer(s) sliding"
        check(f"{case}: floor's friction tan(delta) = {mu:.4f} within {100 * tolerance:.0f}%",
              abs(ratio / mu - 1.0) < tolerance, f"{ratio:.4f}")
        check(f"{case}: decelerates at g tan(delta) within 5%", abs(decel / mu - 1.0) < 0.05,
              f"{decel:.4f} g")

    # a block sliding down a slope, and a push below the slide angle
    theta = 10.0
    for layers in (1, 4):
        t, v, *_ = run(tmp, delta1=25, layers=layers, theta=theta, v0=1.0, tmeas=0.5)
        window = sliding(t, v, 1.0)
        assert window.sum() > 10, "the layer did not slow down through the window"
        expected = G * (math.tan(math.radians(25)) * math.cos(math.radians(theta)) -
                        math.sin(math.radians(theta)))
        decel = -np.polyfit(t[window], v[window], 1)[0]
        check(f"delta 25, {layers} layer(s) sliding down {theta:.0f} deg: decelerates at "
              f"g (tan(delta) cos(theta) - sin(theta)) = {expected:.3f} m/s^2 within 5%",
              abs(decel / expected - 1.0) < 0.05, f"{decel:.3f} m/s^2")
    t, v, *_ = run(tmp, delta1=25, theta=23.5, v0=0.05, tmeas=0.3)
    a = slope(t, v)
    check("delta 25, pushed at 5 cm/s at 23.5 deg: stops and holds",
          abs(v[-1]) < 0.01 and abs(a) < 0.02, f"v {v[-1]:.2e} m/s, a {a:.2e} m/s^2")

    # a slip floor
    for layers in (1, 4):
        t, v, *_ = run(tmp, delta1="slip", layers=layers, v0=1.0, tmeas=0.5)
        check(f"slip floor, {layers} layer(s): keeps its speed over {t[-1]:.2f} s within 1%",
              t[-1] >= 0.5 and np.max(np.abs(v - 1.0)) < 0.01,
              f"speed between {v.min():.4f} and {v.max():.4f} m/s")

    # two halves of the floor, delta 15 and 25
    t, v, fx1, fz1, fx2, fz2 = run(tmp, delta1=15, delta2=25, v0=1.0, tmeas=0.2)
    window = sliding(t, v, 1.0)
    for half, fx, fz, delta in ((1, fx1, fz1, 15), (2, fx2, fz2, 25)):
        mu, ratio = math.tan(math.radians(delta)), fx[window].sum() / -fz[window].sum()
        check(f"two floors: half {half} gives its own friction tan({delta}) = {mu:.4f} within 3%",
              abs(ratio / mu - 1.0) < 0.03, f"{ratio:.4f}")
    # 1 against 2 ranks, a short run (round-off grows over a long one), sliding at once
    records, virials = [], []
    for ranks in (1, 2):
        records.append(run(tmp, ranks, delta1=15, delta2=25, v0=1.0, load=300, tmeas=0.01))
        virials.append(virial(tmp))
    def difference(a, b):
        return max(np.max(np.abs(x - y)) / max(np.max(np.abs(x)), 1e-300) for x, y in zip(a, b))
    assert np.min(records[0][1]) < 0.99, "the layer did not slow down: nothing was compared"
    # the friction's shear on the floor: xz, against the weight's zz
    assert np.min(virials[0][5]) < -0.1 * np.max(virials[0][3]), "no shear in the virial"
    diff = difference(records[0], records[1])
    check("1 and 2 ranks: the same history", diff < 1e-9, f"largest relative difference {diff:.1e}")
    diff = difference(virials[0], virials[1])
    check("1 and 2 ranks: the same virial", diff < 1e-9, f"largest relative difference {diff:.1e}")
    try:
        kk = run(tmp, delta1=15, delta2=25, v0=1.0, load=300, tmeas=0.01, args=KOKKOS)
        diff = difference(records[0], kk)
        check("plain and /kk: the same history", diff < 1e-9,
              f"largest relative difference {diff:.1e}")
        diff = difference(virials[0], virial(tmp))
        check("plain and /kk: the same virial", diff < 1e-9,
              f"largest relative difference {diff:.1e}")
    except RuntimeError as error:
        output = gransph_run.LAST_OUTPUT
        check("/kk refused by LAMMPS 29Sep2021 + Kokkos (the normals cannot reach ghosts)",
              "LAMMPS (29 Sep 2021" in output and
              "per-atom wall normals need LAMMPS newer than 29 Sep 2021" in output, str(error))
check.finish()
