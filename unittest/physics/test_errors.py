# SPDX-License-Identifier: GPL-2.0-only (GRANSPH: LICENSE)
"""Bad input stops LAMMPS with an error that names the problem, never a crash,
a hang or silent NaNs; run as a batch job runs, with the screen and the log
redirected to files, which must hold the message."""

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
    ("unknown wall/gradient value", dict(pair_style="sph/granular 0.012 wall/gradient tangent"),
     "unknown value tangent of keyword wall/gradient"),
    ("wall/gradient without a value", dict(pair_style="sph/granular 0.012 wall/gradient"),
     "wall/gradient needs a value"),
    ("unknown precision", dict(pair_style="sph/granular 0.012 precision single"),
     "unknown value single of keyword precision"),
    ("negative prune margin", dict(pair_style="sph/granular 0.012 prune -0.1"),
     "prune must be >= 0, not -0.1"),
    ("prune without a margin", dict(pair_style="sph/granular 0.012 prune"),
     "prune needs a value"),
    ("unknown wall/stress value", dict(pair_style="sph/granular 0.012 wall/stress mean"),
     r"unknown value mean of keyword wall/stress \(it takes paper or ratio\)"),
    ("misspelt pair keyword", dict(pair_style="sph/granular 0.012 wall/fricton floor 20"),
     r"unknown keyword wall/fricton \(the keywords are h, then visc, .*wall/friction,"),
    ("a word for a viscosity", dict(pair_style="sph/granular 0.012 visc high 0"),
     "visc alpha must be a number, not high"),
    ("a word for a wall/friction angle", dict(pair_style="sph/granular 0.012 wall/friction floor steep"),
     r"wall/friction of group floor must be rough, slip, material or an angle in \[0, 90\) degrees, not steep"),
    ("pair_coeff with values", dict(pair_coeff="* * 1.0"), "expected I J only"),
    ("wall/friction of no group", dict(pair_style="sph/granular 0.012 wall/friction nosuch 20"),
     "wall/friction group nosuch does not exist"),
    ("wall/friction/hold stick without such walls",
     dict(pair_style="sph/granular 0.012 wall/friction/hold stick"),
     r"wall/friction/hold stick needs walls with a friction of their own"),
    ("wall/friction/hold of no known value",
     dict(pair_style="sph/granular 0.012 wall/friction floor 20 wall/friction/hold glue"),
     "unknown value glue of keyword wall/friction/hold"),
    ("wall/friction angle of 90", dict(pair_style="sph/granular 0.012 wall/friction floor 90"),
     r"wall/friction of group floor must be rough, slip, material or an angle in \[0, 90\) degrees, not 90"),
    ("wall/friction on a group of no dummies",
     dict(pair_style="sph/granular 0.012 wall/friction sand 20"),
     "wall/friction group sand holds no dummy particle of the walls group of fix sph"),
    ("no grains", dict(run="delete_atoms group sand\nrun 10"),
     "its group sand holds no atom, so there is nothing to integrate"),
    ("a grain that leaves the box", dict(run="set atom 1 vx 100\nrun 300"),
     r"Fix sph/elastoplastic: \d+ atoms left the box by step 300 .*fix sph/outflow over a region"),
    ("wall/friction without a value", dict(pair_style="sph/granular 0.012 wall/friction floor"),
     "wall/friction needs a group and a value"),
    ("sph/visc/atom read before the step's force evaluation",
     dict(run="compute visc sand sph/visc/atom\ncompute pvisc sand reduce max c_visc\n"
              "variable still equal 0*c_pvisc\n"
              "fix hold floor sph/move 0 0 v_still\nrun 10"),
     r"the viscous pressure was not summed on step 0: .* not before it"),
    ("wall/friction without normals", dict(pair_style="sph/granular 0.012 wall/friction floor 20"),
     "of a wall/friction group has no wall normal"),
    ("wall/friction without walls",
     dict(pair_style="sph/granular 0.012 wall/friction floor 20",
          fix="fix sph sand sph/elastoplastic sand.gransph Chen2019"),
     "wall/friction needs dummy walls"),
    ("wall normals of fix property/atom", dict(comm="comm_modify vel yes\n"
                                                   "fix normals all property/atom d2_wall_normal 3 ghost yes"),
     r"wall normals are no longer read from the per-atom property wall_normal .*fix sph/normals"),
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
    ("bad cfl sound speed", dict(fix="fix sph sand sph/elastoplastic sand.gransph Chen2019 cfl/sound bulk"),
     "cfl/sound must be local or reference, not bulk"),
    ("bad predictor", dict(fix="fix sph sand sph/phasechange sand.gransph Chen2019 predictor ab2"),
     "predictor must be midpoint or extrapolated, not ab2"),
    ("bad plastic step", dict(fix="fix sph sand sph/elastoplastic sand.gransph Chen2019 plastic foo"),
     "plastic must be return or paper"),
    ("plastic for the phase-change model",
     dict(fix="fix sph sand sph/phasechange sand.gransph Chen2019 plastic paper"),
     "keyword plastic is for fix sph/elastoplastic only"),
    ("negative density", dict(fix="fix sph sand sph/elastoplastic sand.gransph Chen2019 rho -1"),
     "rho must be > 0"),
    ("keyword without value", dict(fix="fix sph sand sph/elastoplastic sand.gransph Chen2019 walls"),
     "keyword walls needs a value"),
    ("unknown fix keyword", dict(fix="fix sph sand sph/elastoplastic sand.gransph Chen2019 foo 1"),
     "unknown keyword foo"),
    ("two integrators", dict(fix="fix sph sand sph/elastoplastic sand.gransph Chen2019\n"
                                 "fix sph2 floor sph/elastoplastic sand.gransph Chen2019"),
     "only one may be defined"),
    ("sph/move without vz", dict(run="fix move floor sph/move 1 0\nrun 10"), "expected vx vy vz"),
    ("sph/move unknown variable", dict(run="fix move floor sph/move v_nosuch 0 0\nrun 10"),
     "variable nosuch does not exist"),
    ("sph/move atom-style variable", dict(run="variable u atom x\nfix move floor sph/move v_u 0 0\nrun 10"),
     "variable u is not equal-style"),
    ("sph/move on the grains", dict(run="fix move all sph/move 1 0 0\nrun 10"),
     "group all has atoms that fix sph integrates"),
    ("invalid material values", dict(fix="fix sph sand sph/elastoplastic {bad} Bad"),
     "Poisson's ratio must be in"),
    ("a material line with a field too many", dict(fix="fix sph sand sph/elastoplastic {long} Good"),
     r"material file .*long.gransph, material Long: 12 fields instead of 11 on line: Long 2450"),
    ("a material line with a field too few", dict(fix="fix sph sand sph/elastoplastic {short} Good"),
     r"material file .*short.gransph, material Short: 10 fields instead of 11 on line: Short 2450"),
]

# several materials (keyword material GROUP FILE NAME): groups of the sand block's upper
# grains (up: z > 0.02, hi: z > 0.03) and of its lowest grains and the floor (low)
MATERIAL_GROUPS = """region up block INF INF INF INF 0.02 INF units box
group up region up
region hi block INF INF INF INF 0.03 INF units box
group hi region hi
region low block INF INF INF INF INF 0.01 units box
group low region low
"""
SPH = "fix sph sand sph/elastoplastic sand.gransph Chen2019 walls floor "
CASES += [
    ("a grain claimed by two materials",
     dict(fix=MATERIAL_GROUPS + SPH + "material up sand.gransph Chen2019 material hi {sand25} Sand25"),
     r"grain \d+ is claimed by two materials, by the groups up \(Chen2019\) hi \(Sand25\)"),
    ("a material group over the walls",
     dict(fix=MATERIAL_GROUPS + SPH + "material low {sand25} Sand25"),
     r"dummy particle \d+ of the walls group is in the material group low \(Sand25\)"),
    ("materials of other units", dict(fix=MATERIAL_GROUPS + SPH + "material up {nounits} Plain"),
     r"material file .*nounits.gransph declares no units .*, the fix's material file sand.gransph "
     r"units si: the materials of a run must declare the same units"),
    ("an unknown material", dict(fix=MATERIAL_GROUPS + SPH + "material up sand.gransph Nosuch"),
     "material Nosuch not found in file sand.gransph"),
    ("a material of no group", dict(fix=MATERIAL_GROUPS + SPH + "material nosuch sand.gransph Chen2019"),
     "material group nosuch does not exist"),
    ("a material for the fix group", dict(fix=MATERIAL_GROUPS + SPH + "material sand {sand25} Sand25"),
     "material group sand holds every grain"),
    ("a group given two materials",
     dict(fix=MATERIAL_GROUPS + SPH + "material up {sand25} Sand25 material up sand.gransph Chen2019"),
     "group up is given two materials, Sand25 and Chen2019"),
    ("material without a name", dict(fix=MATERIAL_GROUPS + SPH + "material up sand.gransph"),
     "keyword material needs a group, a material file and a name"),
    ("geostatic with several materials",
     dict(fix=MATERIAL_GROUPS + SPH + "material up {sand25} Sand25 geostatic 0.05"),
     "geostatic takes one density and is for one material, not 2"),
    ("compute sph/material/atom with an argument",
     dict(run="compute material sand sph/material/atom 1\nrun 10"),
     "Illegal compute sph/material/atom command: no arguments"),
    ("compute sph/material/atom without an integrator",
     dict(pair_style="zero 0.024", fix="", run="compute material sand sph/material/atom\nrun 10"),
     "Compute sph/material/atom needs a GRANSPH integrator fix"),
]

# fix sph/normals: its keywords and the files it reads ({name} is tmp/name.normals); the
# sand block's grains are atoms 1-125, its floor 126-200
NORMALS_FILES = {"nosection": "Atoms\n\n126 2 0 0 0\n",
                 "nonz": "WallNormals\n\n126 0 0 1\n127 0 0\n",
                 "word": "WallNormals\n\n126 0 zero 1\n",
                 "grain": "WallNormals\n\n1 0 0 1\n",
                 "beyond": "WallNormals\n\n126 0 0 1\n999 0 0 1\n",
                 "floor": "WallNormals\n\n" + "".join(f"{i} 0 0 1\n" for i in range(126, 201))}
for name, fields, expected in (
        ("an unknown keyword", "vector 0 0 1", r"unknown keyword vector \(valid: file, set\)"),
        ("set of no group", "set nosuch 0 0 1", r"group nosuch \(keyword set\) does not exist"),
        ("set of a zero normal", "set floor 0 0 0", "the normal of group floor must not be zero"),
        ("set without nz", "set floor 0 0", "keyword set needs a group ID and nx ny nz"),
        ("a file that is not there", "file nosuch.normals", "cannot open file nosuch.normals"),
        ("a file without the section", "file {nosection}", "nosection.normals has no WallNormals section"),
        ("a row without nz", "file {nonz}", r"nonz.normals:4: 127 0 0 \(expected ID nx ny nz\)"),
        ("a word for a number", "file {word}", r"word.normals:3: 126 0 zero 1 \(expected ID nx ny nz\)"),
        ("an ID of another group", "file {grain}",
         r"atom 1 of file .*grain.normals is not in group floor \(was the file read with an ID offset\?\)"),
        ("an ID of no atom", "file {beyond}", r"beyond.normals:4: no atom has ID 999")):
    CASES.append(("fix sph/normals: " + name,
                  dict(fix=GOOD["fix"] + "\nfix normals floor sph/normals " + fields), expected))
CASES.append(("two fixes sph/normals",
              dict(fix=GOOD["fix"] + "\nfix n1 floor sph/normals set floor 0 0 1\n"
                                     "fix n2 floor sph/normals set floor 0 0 1"),
              "fixes n1 and n2 are both wall-normal fixes \\(sph/normals\\); only one may be defined"))

# expansion faster than dt can follow: rho < 0, caught with the atom's ID
# the block at rest with a timestep 75 times its CFL limit (2.7e-5 s): the elastic
# waves grow until a density turns negative a few steps in
BLOW_UP = dict(fix="fix sph sand sph/elastoplastic sand.gransph Chen2019 walls floor cfl none",
               run="timestep 2e-3\nrun 10")
BAD_STATE = r"atom \d+ has a non-finite state or non-positive density"
CASES.append(("a blow-up is caught with the atom ID", BLOW_UP, BAD_STATE))
KOKKOS = ["-k", "on", "t", "1", "-sf", "kk"]

# a grain created on a dummy particle's lattice site: no kernel gradient keeps them apart
ON_A_DUMMY = dict(run="create_atoms 1 single 0.025 0.025 -0.005 units box\ngroup sand type 1\nrun 10")
COINCIDENT = r"atoms \d+ and \d+ are both at \(0\.025\d*, 0\.025\d*, -0\.005\d*\); did two create_atoms"
CASES.append(("a grain on a dummy particle", ON_A_DUMMY, COINCIDENT))

# sand finer than its floor (a terrain made at another spacing): the 1 cm floor under grains
# of 5 mm, and under grains of 3.3 mm whose support 2h does not reach a second dummy
FINER_SAND = dict(mass="mass 1 3.0625e-4\nmass 2 2.45e-3")
WALL_SPACING = r"the dummy particles lie 0\.01 apart \(the mean distance to the nearest dummy\), the grains 0\.005 "
CASES.append(("a floor at twice the grains' spacing", FINER_SAND, WALL_SPACING))
CASES.append(("a floor farther apart than the support",
              dict(mass="mass 1 9.07e-5\nmass 2 2.45e-3", pair_style="sph/granular 0.004"),
              r"no dummy particle has another within 2h = 0\.008 of it while the grains lie 0\.0033"))

# a bad initial state stops the run at setup, before the step-0 thermo output
BAD_START = BAD_STATE + r" \(rho 2450, v {} 0 0\) at step 0"
NAN_START = dict(run="variable vx atom exp(1000)-exp(1000)\nvelocity sand set v_vx 0 0 units box\nrun 10")
INF_START = dict(run="variable vx atom exp(1000)\nvelocity sand set v_vx 0 0 units box\nrun 10")
CASES.append(("a NaN initial velocity is caught at setup", NAN_START, BAD_START.format("-?nan")))
CASES.append(("an infinite initial velocity is caught at setup", INF_START, BAD_START.format("inf")))

# a 2d layer of sand on a dummy floor, with `{change}` before the run
PLANE_2D = """plugin load gransphplugin.so
units si
dimension 2
atom_style atomic
atom_modify map array
boundary f f p
comm_modify vel yes
region box block 0 0.1 -0.03 0.1 -0.005 0.005 units box
create_box 2 box
lattice sq 0.01 origin 0.5 0.5 0
region sand block 0 0.05 0 0.05 INF INF units box
region floor block 0 0.05 -0.03 0 INF INF units box
create_atoms 1 region sand
create_atoms 2 region floor
group sand type 1
group floor type 2
mass * 0.245
pair_style sph/granular 0.012
pair_coeff * *
fix gravity sand gravity 9.81 vector 0 -1 0
fix sph sand sph/elastoplastic sand.gransph Chen2019 walls floor
{change}
run 10
"""
OFF_PLANE = r"atom {} is off the z = 0 plane of the 2d run \(z {}, vz {}\)"
CASES_2D = [
    ("2d: good input runs", "", None),
    ("2d: a grain off the plane", "set atom 3 z 0.001", OFF_PLANE.format(3, 0.001, 0)),
    ("2d: a wall particle off the plane", "set atom 30 z -0.002", OFF_PLANE.format(30, -0.002, 0)),
    ("2d: a grain with a z velocity", "set atom 7 vz 0.5", OFF_PLANE.format(7, 0, 0.5)),
]

MOVE_2D = gransph_run.EMPTY_2D_BOX + "fix move all sph/move 0 1 1\n"


def run_case(tmp, fields, args=()):
    text = BASE.format(**{**GOOD, **fields})
    for name in ("bad", "long", "short", "nounits"):
        text = text.replace("{" + name + "}", os.path.join(tmp, name + ".gransph"))
    text = text.replace("{sand25}", os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                                 "sand25.gransph"))
    for name in NORMALS_FILES:
        text = text.replace("{" + name + "}", os.path.join(tmp, name + ".normals"))
    return gransph_run.first_error(tmp, text, args)


check = gransph_run.Checks()
with tempfile.TemporaryDirectory() as tmp:
    good = "Good 2450 20e6 0.3 37 0 0 1500 1.1 0.6 0.8\n"
    for name, text in NORMALS_FILES.items():
        with open(os.path.join(tmp, name + ".normals"), "w") as f:
            f.write(text)
    with open(os.path.join(tmp, "bad.gransph"), "w") as f:
        f.write("# UNITS: si\nBad 2450 20e6 0.6 37 0 0 1500 1.1 0.6 0.8\n")
    with open(os.path.join(tmp, "long.gransph"), "w") as f:
        f.write("# UNITS: si\n" + good + "Long 2450 20e6 0.3 37 0 0 1500 1.1 0.6 0.8 9\n")
    with open(os.path.join(tmp, "short.gransph"), "w") as f:
        f.write("# UNITS: si\n" + good + "Short 2450 20e6 0.3 37 0 0 1500 1.1 0.6\n" + good)
    with open(os.path.join(tmp, "nounits.gransph"), "w") as f:
        f.write("# a material file that declares no units\nPlain 2450 20e6 0.3 37 0 0 1500 1.1 0.6 0.8\n")
    code, error = run_case(tmp, {})
    check("good input runs", code == 0 and not error, error or "no error")
    # the viscous pressure is summed on the steps its output asks for, and only there
    for args in ([], KOKKOS):
        code, error = run_case(tmp, dict(run="compute visc sand sph/visc/atom\n"
                                             "dump d sand custom 5 visc.dump id c_visc\nrun 10"), args)
        dumped = open(os.path.join(tmp, "visc.dump")).read().split("ITEM: TIMESTEP\n")[1:] \
            if code == 0 else []
        check("sph/visc/atom in a dump every 5 steps" + (" (/kk)" if args else ""),
              code == 0 and not error and [d.split()[0] for d in dumped] == ["0", "5", "10"],
              error or f"steps dumped: {[d.split()[0] for d in dumped]}")
    code, error = run_case(tmp, FINER_SAND, KOKKOS)
    check("a floor at twice the grains' spacing (/kk)", code != 0 and re.search(WALL_SPACING, error),
          error or "no error")
    # a terrain's normals in a box periodic across it: a warning that names the direction
    # (a periodic terrain is legitimate), none in the box of fixed boundaries
    terrain = GOOD["fix"] + "\nfix normals floor sph/normals file " + os.path.join(tmp, "floor.normals")
    for boundary, expected in (("p f f", "WARNING: Fix sph/normals: the box is periodic in x: the terrain of "),
                               ("f f f", None)):
        code, out = gransph_run.output_of(
            tmp, BASE.format(**{**GOOD, "fix": terrain}).replace("boundary f f f", "boundary " + boundary))
        warned = expected in out if expected else "WARNING: Fix sph/normals" not in out
        check(f"a terrain in a box of boundary {boundary}: {'a' if expected else 'no'} warning",
              code == 0 and warned and "75 wall normals from" in out,
              next((l for l in out.splitlines() if "WARNING" in l or "ERROR" in l), "no warning"))
    # a batch job's log file holds the message too, from a one-rank error (error->one) of
    # GRANSPH's and of LAMMPS' own
    for name, text, expected in (
            ("a material line of 5 fields", BASE.format(**{**GOOD, "fix": "fix sph sand sph/elastoplastic {short5} Good"}),
             r"material Good: 5 fields instead of 11"),
            ("an illegal variable", "variable a equal 1\nprint ${b}\n", r"Substitution for illegal variable b")):
        with open(os.path.join(tmp, "short5.gransph"), "w") as f:
            f.write("# UNITS: si\nGood 2450 20e6 0.3 37\n")
        code, error = gransph_run.first_error(tmp, text.replace("{short5}", os.path.join(tmp, "short5.gransph")))
        with open(os.path.join(tmp, "log.txt")) as f:
            logged = re.search(expected, f.read())
        check(f"{name}: the message in the redirected screen and the log file",
              code != 0 and re.search(expected, error) and logged,
              f"screen: {error or 'no error'}; log: {'has it' if logged else 'lacks it'}")
    for name, fields, expected in CASES:
        code, error = run_case(tmp, fields)
        check(name, code != 0 and re.search(expected, error), error or "no error")
    # single-precision positions far from their origin: a warning that says how far
    for name, box, warned in (("precision mixed in a small box", "", False),
                              ("precision mixed in a box 30 m long",
                               "\nchange_box all x final 0 30 units box", True)):
        code, out = gransph_run.output_of(tmp, BASE.format(**{
            **GOOD, "pair_style": "sph/granular 0.012 precision mixed",
            "mass": GOOD["mass"] + box}))
        warning = re.search(r"WARNING: Pair style sph/granular precision mixed: particles lie "
                            r"up to (\S+) h from the origin", out)
        check(name + (": warns" if warned else ": no warning"),
              code == 0 and bool(warning) == warned and (not warned or 1000 < float(warning[1])),
              warning[0] if warning else f"exit {code}, no warning")
    code, error = gransph_run.first_error(tmp, MOVE_2D)
    check("sph/move with vz in 2d", code != 0 and "vz must be 0" in error, error or "no error")
    code, error = run_case(tmp, BLOW_UP, KOKKOS)
    check("the /kk integrator catches a blow-up too", code != 0 and re.search(BAD_STATE, error),
          error or "no error")
    code, error = run_case(tmp, ON_A_DUMMY, KOKKOS)
    check("the /kk pair style finds a grain on a dummy particle too",
          code != 0 and re.search(COINCIDENT, error), error or "no error")
    code, error = run_case(tmp, NAN_START, KOKKOS)
    check("the /kk integrator catches a NaN initial velocity at setup",
          code != 0 and re.search(BAD_START.format("-?nan"), error), error or "no error")
    for name, change, expected in CASES_2D:
        for args in ([], KOKKOS):
            code, error = gransph_run.first_error(tmp, PLANE_2D.format(change=change), args)
            ok = code == 0 and not error if expected is None else code != 0 and re.search(expected, error)
            check(name + (" (/kk)" if args else ""), ok, error or "no error")
check.finish()
