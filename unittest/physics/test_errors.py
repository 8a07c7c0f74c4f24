"""Bad input stops LAMMPS with an error that names the problem, never a crash,
a hang or silent NaNs."""

import os
import re
import tempfile

import gransph_run

BASE = """plugin load gransphplugin.so
units si
atom_style atomic
atom_modify map array
boundary f f f
{comm}
""" + gransph_run.SAND_BLOCK + """{mass}
pair_style {pair_style}
pair_coeff {pair_coeff}
fix gravity sand gravity 9.81 vector 0 0 -1
{fix}
{run}
"""

GOOD = dict(comm="comm_modify vel yes", mass="mass * 2.45e-3", pair_style="sph/granular 0.012",
            pair_coeff="* *", run="run 10",
            fix="fix sph sand sph/elastoplastic sand.gransph Chen2019 walls floor")

CASES = [
    ("smoothing length <= 0", dict(pair_style="sph/granular 0"), "smoothing length h must be > 0"),
    ("unknown pair keyword", dict(pair_style="sph/granular 0.012 foo 1"), "unknown keyword foo"),
    ("negative viscosity", dict(pair_style="sph/granular 0.012 visc -1 0"), "must be >= 0"),
    ("pair_coeff with values", dict(pair_coeff="* * 1.0"), "expected I J only"),
    ("no ghost velocities", dict(comm=""), "comm_modify vel yes"),
    ("no integrator fix", dict(fix=""), "needs a GRANSPH integrator"),
    ("missing material", dict(fix="fix sph sand sph/elastoplastic sand.gransph Nosuch"),
     "material Nosuch not found"),
    ("missing material file", dict(fix="fix sph sand sph/elastoplastic nosuch.gransph Chen2019"),
     "cannot open"),
    ("unknown walls group", dict(fix="fix sph sand sph/elastoplastic sand.gransph Chen2019 walls nosuch"),
     "walls group nosuch does not exist"),
    ("atoms in both groups", dict(fix="group both union sand floor\n"
                                      "fix sph both sph/elastoplastic sand.gransph Chen2019 walls floor"),
     "in both the fix group and the walls group"),
    ("walls = fix group", dict(fix="fix sph sand sph/elastoplastic sand.gransph Chen2019 walls sand"),
     "walls group must differ"),
    ("bad cfl", dict(fix="fix sph sand sph/elastoplastic sand.gransph Chen2019 cfl 2"), "cfl must be in"),
    ("negative density", dict(fix="fix sph sand sph/elastoplastic sand.gransph Chen2019 rho -1"),
     "rho must be > 0"),
    ("keyword without value", dict(fix="fix sph sand sph/elastoplastic sand.gransph Chen2019 walls"),
     "keyword walls needs a value"),
    ("unknown fix keyword", dict(fix="fix sph sand sph/elastoplastic sand.gransph Chen2019 foo 1"),
     "unknown keyword foo"),
    ("two integrators", dict(fix="fix sph sand sph/elastoplastic sand.gransph Chen2019\n"
                                 "fix sph2 floor sph/elastoplastic sand.gransph Chen2019"),
     "Only one GRANSPH integrator"),
    ("sph/move without vz", dict(run="fix move floor sph/move 1 0\nrun 10"), "expected vx vy vz"),
    ("sph/move unknown variable", dict(run="fix move floor sph/move v_nosuch 0 0\nrun 10"),
     "variable nosuch does not exist"),
    ("sph/move atom-style variable", dict(run="variable u atom x\nfix move floor sph/move v_u 0 0\nrun 10"),
     "variable u is not equal-style"),
    ("sph/move on the grains", dict(run="fix move all sph/move 1 0 0\nrun 10"),
     "group all has atoms that fix sph integrates"),
    ("invalid material values", dict(fix="fix sph sand sph/elastoplastic {bad} Bad"),
     "Poisson's ratio must be in"),
]

# expansion faster than dt can follow: rho < 0, caught with the atom's ID
# the block at rest with a timestep 75 times its CFL limit (2.7e-5 s): the elastic
# waves grow until a density turns negative a few steps in
BLOW_UP = dict(fix="fix sph sand sph/elastoplastic sand.gransph Chen2019 walls floor cfl none",
               run="timestep 2e-3\nrun 10")
BAD_STATE = r"atom \d+ has a non-finite state or non-positive density"
CASES.append(("a blow-up is caught with the atom ID", BLOW_UP, BAD_STATE))
KOKKOS = ["-k", "on", "t", "1", "-sf", "kk"]

MOVE_2D = gransph_run.EMPTY_2D_BOX + "fix move all sph/move 0 1 1\n"


def run_case(tmp, fields, args=()):
    text = BASE.format(**{**GOOD, **fields}).replace("{bad}", os.path.join(tmp, "bad.gransph"))
    return gransph_run.first_error(tmp, text, args)


check = gransph_run.Checks()
with tempfile.TemporaryDirectory() as tmp:
    with open(os.path.join(tmp, "bad.gransph"), "w") as f:
        f.write("# UNITS: si\nBad 2450 20e6 0.6 37 0 0 1500 1.1 0.6 0.8\n")
    code, error = run_case(tmp, {})
    check("good input runs", code == 0 and not error, error or "no error")
    for name, fields, expected in CASES:
        code, error = run_case(tmp, fields)
        check(name, code != 0 and re.search(expected, error), error or "no error")
    code, error = gransph_run.first_error(tmp, MOVE_2D)
    check("sph/move with vz in 2d", code != 0 and "vz must be 0" in error, error or "no error")
    code, error = run_case(tmp, BLOW_UP, KOKKOS)
    check("the /kk integrator catches a blow-up too", code != 0 and re.search(BAD_STATE, error),
          error or "no error")
check.finish()
