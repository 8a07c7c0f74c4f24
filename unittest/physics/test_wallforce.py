# SPDX-License-Identifier: GPL-2.0-only (GRANSPH: LICENSE)
"""compute sph/wallforce: a sand layer at rest on a dummy floor pushes on it with its
weight m g (eq. 10), with no tangential force, on 1 and 2 ranks; a tilted normal gives
the projection; fix gravity on the floor adds the floor's weight, with a warning; bad
input stops with an error that names the problem."""

import os
import re
import tempfile

import gransph_run

HERE = os.path.dirname(os.path.abspath(__file__))
DX, G = 0.02, 9.81
FLOOR_MASS = 3 * 6 * 6 * 2450 * DX**3      # three layers of 6 x 6 dummy particles
TILT = (1 / 3, 2 / 3, -2 / 3)               # the input's tilted normal (1, 2, -2), normalised

check = gransph_run.Checks()


def wall_force(tmp, ranks=1, args=(), **variables):
    """weight, (Fx, Fy, Fz, Fn) with n = (0, 0, -1), Fn' with the tilted normal; stdout"""
    out = gransph_run.run(os.path.join(HERE, "in.wallforce"), variables, ranks=ranks, args=args,
                          cwd=tmp)
    words = gransph_run.result_line(out)
    weight = float(words[2])
    floor = [float(w) for w in words[4:8]]
    return weight, floor, float(words[9]), out


with tempfile.TemporaryDirectory() as tmp:
    for ranks in (1, 2):
        weight, (fx, fy, fz, fn), tilted, _ = wall_force(tmp, ranks)
        check(f"normal force = weight, {ranks} rank(s)", abs(fn - weight) < 0.02 * weight,
              f"F_W {fn:.4f} N, m g {weight:.4f} N")
        check(f"no tangential force, {ranks} rank(s)", max(abs(fx), abs(fy)) < 1e-6 * weight,
              f"Fx {fx:.2e} N, Fy {fy:.2e} N")
        check(f"F_W = F . n, {ranks} rank(s)", abs(fn + fz) < 1e-12 * weight,
              f"F_W {fn:.6f} N, -Fz {-fz:.6f} N")
        projection = TILT[0] * fx + TILT[1] * fy + TILT[2] * fz
        check(f"tilted normal gives the projection, {ranks} rank(s)",
              abs(tilted - projection) < 1e-12 * weight, f"{tilted:.6f} N vs F . n' {projection:.6f} N")

    # the Kokkos twins, the compute's device reduction included
    weight, (fx, fy, fz, fn), _, out = wall_force(tmp, args=["-k", "on", "t", "2", "-sf", "kk"])
    check("normal force = weight, Kokkos", abs(fn - weight) < 0.02 * weight,
          f"F_W {fn:.4f} N, m g {weight:.4f} N")
    check("F_W = F . n, Kokkos", abs(fn + fz) < 1e-12 * weight, f"F_W {fn:.6f} N, -Fz {-fz:.6f} N")

    # fix gravity on the floor too: the same grain forces plus the floor's weight
    _, (_, _, _, fn_sand), _, _ = wall_force(tmp, time=0.05, window=0.01)
    _, (_, _, _, fn_all), _, out = wall_force(tmp, time=0.05, window=0.01, gravity="all")
    check("fix gravity on the walls adds m_wall g", abs(fn_all - fn_sand - FLOOR_MASS * G) < 1e-9 * fn_all,
          f"difference {fn_all - fn_sand:.6f} N, m_floor g {FLOOR_MASS * G:.6f} N")
    check("fix gravity on the walls is warned about",
          "WARNING: Compute sph/wallforce: fix gravity gravity acts on atoms of group floor" in out,
          "warning printed" if "WARNING" in out else "no warning")

# --- bad input
BASE = """plugin load gransphplugin.so
units si
atom_style atomic
boundary f f f
comm_modify vel yes
""" + gransph_run.SAND_BLOCK + """mass * 2.45e-3
pair_style sph/granular 0.012
pair_coeff * *
fix gravity sand gravity 9.81 vector 0 0 -1
fix sph sand sph/elastoplastic sand.gransph Chen2019 {walls}
compute w {group} sph/wallforce {normal}
run 0
"""
GOOD = dict(walls="walls floor", group="floor", normal="0 0 -1")
CASES = [
    ("missing normal component", dict(normal="0 0"), "expected nx ny nz"),
    ("zero normal", dict(normal="0 0 0"), "normal nx ny nz must be non-zero"),
    ("group outside the walls", dict(group="all"), "group all has atoms outside the walls group of fix sph"),
    ("integrator without walls", dict(walls=""), "fix sph has no walls group"),
]

# in 2d the wall force has no z component to project
BASE_2D = gransph_run.EMPTY_2D_BOX + "compute w all sph/wallforce 0 1 1\n"


with tempfile.TemporaryDirectory() as tmp:
    code, error = gransph_run.first_error(tmp, BASE.format(**GOOD))
    check("good input runs", code == 0 and not error, error or "no error")
    cases = [(BASE.format(**{**GOOD, **fields}), name, expected) for name, fields, expected in CASES]
    for text, name, expected in cases + [(BASE_2D, "nz != 0 in 2d", "nz = 0 for a 2d simulation")]:
        code, error = gransph_run.first_error(tmp, text)
        check(name, code != 0 and re.search(expected, error), error or "no error")

check.finish()
