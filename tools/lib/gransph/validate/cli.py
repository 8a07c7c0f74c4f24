# SPDX-License-Identifier: GPL-2.0-only (GRANSPH: LICENSE)
"""tools/research/validate: the paper's validation cases and the convergence studies, each a
subcommand writing its report (Markdown) and plots into its folder of validation/.

  tools/research/validate [report]        the paper's four cases at reduced resolution
                                          (each case minutes on 2 cores): validation/report.md,
                                          its plots in validation/paper/
      --paper                   the paper's resolutions (far beyond a 2-core machine)
      --quick                   one short case, to check that the command works (CI)
  tools/research/validate convergence     the column collapse at 8 to 20 particles per radius:
                                          validation/convergence/convergence.md and .png
      --aspect A [A ...]        aspect ratios (default 0.5 2)
      --ppr N [N ...]           particles per radius (default 8 12 16 20)
      --plane                   the collapse in plane strain (in.column_collapse_plane):
                                validation/convergence/convergence_plane.md
      --material FILE NAME      (with --label) the material NAME of the material file FILE
                                instead of Chen2019
      --var NAME=VALUE          (with --label; repeatable) an input variable of the column,
                                e.g. --var normals=1
  tools/research/validate basal-friction  a layer of 1 to 8 particles set sliding on a level
                                          dummy floor at 0.5 to 2 m/s, dx 0.02 to 0.005: its
                                          deceleration against mu g, and whether it hops over
                                          the floor (validation/basal_friction/basal_friction.md,
                                          1 rank)
  tools/research/validate flume-convergence  the flume impact at several spacings, both models:
                                          the wall force's peak, its time and the impulse
                                          (validation/flume/flume_convergence.md and .png)
      --dx D [D ...]            spacings in m (default 0.03 0.025 0.02 0.0167)
      --tend T                  simulated time in s (default 1)
      --deltas D [D ...]        the bed and side walls' interface friction angles in degrees,
                                or rough, slip or material (default rough, the input's); each
                                at every spacing
  tools/research/validate cfl [C ...]     the CFL constant C of the integrators' timestep
                                          (default 0.1 0.2 0.3 0.4 0.5): an elastic wave's error
                                          against a small C, the column collapse (a = 0.5, both
                                          models) and the flume impact (dx 0.025,
                                          Drucker-Prager, to 1 s) against the smallest C, and
                                          which C stay stable (validation/cfl/)
      --cfl-parts P [P ...]     wave column flume (default all three)
      --ppr N                   the column's particles per radius (default 16)
      --dx D                    the flume's spacing (default 0.025)
      --tend T                  the flume's simulated time in s (default 1)
      --replicas N              run the flume N times at each C, all but the first with the
                                grains displaced at random (default 1)
      --perturb P               (with --replicas) by up to P spacings along each axis
                                (default 1e-12: round-off in the positions)
      --cfl-sound S             the integrators' cfl/sound: reference (the default;
                                validation/cfl/cfl_reference.md, .png) or local
                                (validation/cfl/cfl.md, .png)
  tools/research/validate sphere-impact   a steel ball dropped into a sand bed
                                          (examples/sphere_impact) from several heights at
                                          several resolutions: its deepest penetration against
                                          Uehara et al.'s law, the exponent and convergence
                                          (validation/sphere_impact/sphere_impact.md and .png)
      --heights H [H ...]       drop heights in m (default 0.025 0.05 0.1 0.2)
      --per-diameter N [N ...]  ball diameters per spacing (default 10 12)
      --alphas A [A ...]        linear coefficients of the artificial viscosity (default the
                                example's)
      --width W                 the bed's width in D, its depth W/2 (default 4)
  tools/research/validate erodible-bed    a column released on a slope onto an erodible layer of
                                          the same sand (examples/erodible_bed): its runout
                                          against the layer's thickness on several slopes at
                                          two resolutions, beside Mangeney et al. (2010)
                                          (validation/erodible_bed/erodible_bed.md and .png)
      --slopes S [S ...]        slopes in degrees (default 0 10 16 22)
      --thickness F [F ...]     the layer's thickness e/h0, 0 the bare bed first (default
                                0 0.0667 0.1333 0.2: 0 to 3 rows of grains at h0/dx = 15)
      --per-height N [N ...]    particles across the column's height h0 (default 15 30)
      --tmax T                  stop a run not at rest by T s (default 3)
      --floor F                 rough (the default walls) or contact (the floor holds the grains
                                as contacts do, at their own friction: wall/friction/hold
                                stick): validation/erodible_bed/erodible_bed_contact.md

Options of the studies (each where it applies):
      --models M [M ...]        (convergence, flume-convergence, cfl's column) default
                                elastoplastic phasechange
      --label NAME              write the study's report with _NAME, e.g.
                                validation/convergence/convergence_NAME.md
      --pair-options "..."      (with --label; convergence, basal-friction, flume-convergence)
                                a variant of the numerics, e.g. "visc 1 1 visc/sound paper
                                visc/walls yes wall/stress paper"
      --fix-options "..."       (with --label; convergence, basal-friction, flume-convergence,
                                cfl) keywords added to the integrator, e.g. "cfl/sound local"
Options of every subcommand:
      --ranks N                 run LAMMPS on N MPI ranks (default 2)
      --kokkos                  run the /kk styles on N OpenMP threads instead (N of --ranks)
      --resume                  keep the runs in validation/runs/ that a study with the same
                                options finished before it was stopped (each run's folder
                                records its command; older folders count if they finished)
      --out DIR                 write the reports, plots and runs under DIR instead of
                                validation/ (each study into its folder there)

The command lines of before the subcommands (tools/research/validate --convergence ...,
--quick, --cfl 0.2 0.3 ...) still work: the mode flag is read as its subcommand.
Every number in a report comes from the runs of that invocation (with --resume, also
from those of the stopped invocation it resumes).
"""

import argparse
import datetime
import os
import sys

from .. import TOP
from ..lammps import Runner
from .basal_friction import basal_friction
from .cfl import cfl_study
from .convergence import convergence
from .erodible_bed import erodible_bed
from .flume import flume_convergence
from .paper import column_collapse, flume_impact
from .jets import jet_collision, jet_film
from .report import Report, generated, machine
from .sphere_impact import SPHERE_ALPHA, sphere_impact

NAME = "tools/research/validate"
STUDIES = ["report", "convergence", "basal-friction", "flume-convergence", "cfl", "sphere-impact",
           "erodible-bed"]
# the mode flags of the command line before the subcommands, and their subcommands
LEGACY = {"--quick": ["report", "--quick"], "--paper": ["report", "--paper"],
          "--convergence": ["convergence"], "--basal-friction": ["basal-friction"],
          "--flume-convergence": ["flume-convergence"], "--sphere-impact": ["sphere-impact"],
          "--cfl": ["cfl"]}
# every study's options, with their values where a subcommand does not take them
DEFAULTS = dict(paper=False, quick=False, aspect=[0.5, 2.0], ppr=None, plane=False,
                models=["elastoplastic", "phasechange"], pair_options="", fix_options="",
                label="", material=None, var=[], heights=[0.025, 0.05, 0.1, 0.2],
                per_diameter=[10, 12], alphas=[SPHERE_ALPHA], width=4.0, dx=None, tend=1.0,
                deltas=["rough"], constants=None, cfl_parts=["wave", "column", "flume"],
                replicas=1, perturb=1e-12, cfl_sound="reference", slopes=[0.0, 10.0, 16.0, 22.0],
                thickness=[0.0, 0.0667, 0.1333, 0.2], per_height=[15, 30], tmax=3.0, floor="rough")


def subcommand_first(argv):
    """argv with its subcommand first: the report where it names none, and a mode flag of
    the older command line (--convergence, --cfl 0.2 0.3, ...) read as its subcommand"""
    argv = list(argv)
    if argv[:1] in ([s] for s in STUDIES) or argv[:1] in (["-h"], ["--help"]):
        return argv
    modes = [k for k, a in enumerate(argv) if a in LEGACY]
    if len(modes) > 1:
        sys.exit(f"{NAME}: one study at a time ({', '.join(argv[k] for k in modes)})")
    if modes:
        k = modes[0]
        flag = argv.pop(k)
        values = []
        while flag == "--cfl" and k < len(argv) and not argv[k].startswith("-"):
            values.append(argv.pop(k))
        return LEGACY[flag] + values + argv
    if not argv or argv[0].startswith("-"):
        return ["report"] + argv
    return argv


def parser():
    """the command line: a subcommand per study, each with its options"""
    top = argparse.ArgumentParser(prog=NAME, description=__doc__,
                                  formatter_class=argparse.RawDescriptionHelpFormatter)
    common = argparse.ArgumentParser(add_help=False)
    common.add_argument("--ranks", type=int, default=2, help="MPI ranks (default 2), or threads with --kokkos")
    common.add_argument("--kokkos", action="store_true", help="the /kk styles on --ranks OpenMP threads")
    common.add_argument("--resume", action="store_true", help="keep the runs a stopped study finished")
    common.add_argument("--out", default=os.path.join(TOP, "validation"),
                        help="the reports', plots' and runs' root (default validation/)")
    label = argparse.ArgumentParser(add_help=False)
    label.add_argument("--label", default="", help="the report's name gets _LABEL")
    models = argparse.ArgumentParser(add_help=False)
    models.add_argument("--models", nargs="+", default=DEFAULTS["models"])
    pair = argparse.ArgumentParser(add_help=False)
    pair.add_argument("--pair-options", default="", help="(with --label) pair style keywords of a variant")
    fix = argparse.ArgumentParser(add_help=False)
    fix.add_argument("--fix-options", default="", help="(with --label) integrator keywords of a variant")
    subs = top.add_subparsers(dest="study", metavar="STUDY")
    sub = subs.add_parser("report", parents=[common], help="the paper's four cases: validation/report.md")
    sub.add_argument("--paper", action="store_true", help="at the paper's resolutions")
    sub.add_argument("--quick", action="store_true", help="one short case (CI)")
    sub = subs.add_parser("convergence", parents=[common, label, models, pair, fix],
                          help="the column collapse in resolution: validation/convergence/")
    sub.add_argument("--aspect", type=float, nargs="+", default=DEFAULTS["aspect"])
    sub.add_argument("--ppr", type=int, nargs="+", help="particles per radius (default 8 12 16 20)")
    sub.add_argument("--plane", action="store_true", help="in plane strain")
    sub.add_argument("--material", nargs=2, metavar=("FILE", "NAME"))
    sub.add_argument("--var", action="append", default=[], metavar="NAME=VALUE")
    subs.add_parser("basal-friction", parents=[common, label, pair, fix],
                    help="thin layers sliding to rest: validation/basal_friction/")
    sub = subs.add_parser("flume-convergence", parents=[common, label, models, pair, fix],
                          help="the flume impact in resolution: validation/flume/")
    sub.add_argument("--dx", type=float, nargs="+", help="spacings in m (default 0.03 0.025 0.02 0.0167)")
    sub.add_argument("--tend", type=float, default=1.0)
    sub.add_argument("--deltas", nargs="+", default=["rough"])
    sub = subs.add_parser("cfl", parents=[common, label, models, fix],
                          help="the CFL constant of the timestep: validation/cfl/")
    sub.add_argument("constants", type=float, nargs="*", metavar="C",
                     help="the CFL constants (default 0.1 0.2 0.3 0.4 0.5)")
    sub.add_argument("--cfl-parts", nargs="+", choices=["wave", "column", "flume"],
                     default=DEFAULTS["cfl_parts"])
    sub.add_argument("--ppr", type=int, nargs="+", help="the column's particles per radius (default 16)")
    sub.add_argument("--dx", type=float, nargs="+", help="the flume's spacing (default 0.025)")
    sub.add_argument("--tend", type=float, default=1.0)
    sub.add_argument("--replicas", type=int, default=1)
    sub.add_argument("--perturb", type=float, default=1e-12)
    sub.add_argument("--cfl-sound", choices=["local", "reference"], default="reference")
    sub = subs.add_parser("sphere-impact", parents=[common, label],
                          help="a ball dropped into a sand bed: validation/sphere_impact/")
    sub.add_argument("--heights", type=float, nargs="+", default=DEFAULTS["heights"])
    sub.add_argument("--per-diameter", type=int, nargs="+", default=DEFAULTS["per_diameter"])
    sub.add_argument("--alphas", type=float, nargs="+", default=DEFAULTS["alphas"])
    sub.add_argument("--width", type=float, default=4.0)
    sub = subs.add_parser("erodible-bed", parents=[common, label],
                          help="a column onto an erodible layer on slopes: validation/erodible_bed/")
    sub.add_argument("--slopes", type=float, nargs="+", default=DEFAULTS["slopes"])
    sub.add_argument("--thickness", type=float, nargs="+", default=DEFAULTS["thickness"])
    sub.add_argument("--per-height", type=int, nargs="+", default=DEFAULTS["per_height"])
    sub.add_argument("--tmax", type=float, default=3.0)
    sub.add_argument("--floor", choices=["rough", "contact"], default="rough")
    return top


def options(argv=None):
    """the parsed command line, every study's options filled in"""
    args = parser().parse_args(subcommand_first(sys.argv[1:] if argv is None else argv))
    for name, value in DEFAULTS.items():
        if not hasattr(args, name):
            setattr(args, name, value)
    for study in STUDIES[1:]:
        setattr(args, study.replace("-", "_"), args.study == study)
    args.cfl = (args.constants or []) if args.study == "cfl" else None
    return args


def main(argv=None):
    args = options(argv)
    args.runner = Runner(args.out, kokkos=args.kokkos, resume=args.resume)
    root = args.runner.root
    os.makedirs(root, exist_ok=True)
    started = args.started = datetime.datetime.now()
    cfl = args.cfl is not None
    args.ppr = args.ppr or ([16] if cfl else [8, 12, 16, 20])
    args.dx = args.dx or ([0.025] if cfl else [0.03, 0.025, 0.02, 0.0167])
    if (args.pair_options or args.fix_options or args.material or args.var) and not args.label:
        sys.exit(f"{NAME}: --pair-options, --fix-options, --material and --var need a "
                 "--label for the report")
    if args.var and not args.convergence:
        sys.exit(f"{NAME}: --var goes with --convergence")
    if not all("=" in v for v in args.var):
        sys.exit(f"{NAME}: --var takes NAME=VALUE, e.g. --var normals=1")
    args.input_vars = dict(v.split("=", 1) for v in args.var)
    if args.pair_options and not (args.convergence or args.basal_friction or args.flume_convergence):
        sys.exit(f"{NAME}: --pair-options goes with --convergence, --basal-friction or "
                 "--flume-convergence")
    if args.fix_options and not (args.convergence or args.basal_friction or args.flume_convergence
                                 or cfl):
        sys.exit(f"{NAME}: --fix-options goes with --convergence, --basal-friction, "
                 "--flume-convergence or --cfl")
    if args.material and not args.convergence:
        sys.exit(f"{NAME}: --material goes with --convergence")
    if args.deltas != ["rough"] and not args.flume_convergence:
        sys.exit(f"{NAME}: --deltas goes with --flume-convergence")
    if args.replicas != 1 and not cfl:
        sys.exit(f"{NAME}: --replicas goes with --cfl")
    if args.replicas < 1:
        sys.exit(f"{NAME}: --replicas takes a number of runs, 1 or more")
    if args.perturb != 1e-12 and args.replicas == 1:
        sys.exit(f"{NAME}: --perturb goes with --replicas N, N > 1")
    if args.plane and not args.convergence:
        sys.exit(f"{NAME}: --plane goes with --convergence")
    args.suffix = (("_plane" if args.plane else "") + ("_contact" if args.floor == "contact" else "") +
                   (f"_{args.label}" if args.label else ""))
    variant = ((" --plane" if args.plane else "") +
               (f" --pair-options \"{args.pair_options}\"" if args.pair_options else "") +
               (f" --fix-options \"{args.fix_options}\"" if args.fix_options else "") +
               (f" --tend {args.tend:g}" if args.tend != 1.0 else "") +
               (f" --deltas {' '.join(args.deltas)}" if args.deltas != ["rough"] else "") +
               (" --kokkos" if args.kokkos else "") +
               (" --resume" if args.resume else "") +
               (f" --material {' '.join(args.material)}" if args.material else "") +
               "".join(f" --var {v}" for v in args.var) +
               (f" --label {args.label}" if args.label else ""))
    variant_lines = (([f"Pair style keywords of this variant: `{args.pair_options}`.\n"]
                      if args.pair_options else []) +
                     ([f"Integrator keywords of this variant: `{args.fix_options}`.\n"]
                      if args.fix_options else []) +
                     ([f"Material of this variant: {args.material[1]} of {args.material[0]}.\n"]
                      if args.material else []) +
                     ([f"Input variables of this variant: `{' '.join(args.var)}`.\n"]
                      if args.var else []))
    label = f": {args.label}" if args.label else ""
    if args.convergence:
        study, name = convergence, f"convergence/convergence{args.suffix}.md"
        lines = ["# GRANSPH convergence study" + (" in plane strain" if args.plane else "") + label + "\n",
                 generated(f"{NAME} convergence --aspect {' '.join(map(str, args.aspect))} "
                           f"--ppr {' '.join(map(str, args.ppr))} --models {' '.join(args.models)}{variant}",
                           started, machine(args))]
    elif args.basal_friction:
        study, name = basal_friction, f"basal_friction/basal_friction{args.suffix}.md"
        lines = ["# GRANSPH: dynamic basal friction of thin layers" + label + "\n",
                 generated(f"{NAME} basal-friction{variant}", started, "1 MPI rank")]
    elif cfl:
        args.cfl = sorted(args.cfl or [0.1, 0.2, 0.3, 0.4, 0.5])
        args.cfl_report = ("cfl" if args.cfl_sound == "local" else "cfl_reference") + args.suffix
        if len(args.ppr) != 1 or len(args.dx) != 1:
            sys.exit(f"{NAME}: --cfl takes one --ppr and one --dx")
        study, name = cfl_study, "cfl/" + args.cfl_report + ".md"
        lines = ["# GRANSPH: the CFL constant of the timestep\n",
                 generated(f"{NAME} cfl {' '.join(map(str, args.cfl))} --cfl-parts "
                           f"{' '.join(args.cfl_parts)} --ppr {args.ppr[0]} --dx {args.dx[0]}"
                           + (f" --replicas {args.replicas} --perturb {args.perturb:g}" if args.replicas > 1 else "")
                           + f" --models {' '.join(args.models)} --cfl-sound {args.cfl_sound}{variant}",
                           started, f"{machine(args)} (the wave on 1)"),
                 "The integrators (fix sph/elastoplastic, fix sph/phasechange) take the timestep "
                 "dt = C min(sqrt(h / max|a|), h / max c), c = sqrt(E/rho) (eq. 19 of the paper; "
                 "`cfl C`, default 0.2, the paper's), rho "
                 + ("each grain's density (`cfl/sound local`)" if args.cfl_sound == "local" else
                    "the initial density rho0 (`cfl/sound reference`: a dilated grain does not "
                    "shorten the step)") + ". A larger C takes fewer steps; this study "
                 "asks up to which C the runs stay stable and how far their results move from "
                 "those of a small C.\n"]
    elif args.sphere_impact:
        args.alphas = sorted(args.alphas, reverse=True)
        study, name = sphere_impact, f"sphere_impact/sphere_impact{args.suffix}.md"
        lines = ["# GRANSPH: a sphere dropped into a sand bed\n",
                 generated(f"{NAME} sphere-impact --heights {' '.join(map(str, args.heights))} "
                           f"--per-diameter {' '.join(map(str, args.per_diameter))} --alphas "
                           f"{' '.join(f'{a:g}' for a in args.alphas)} --width {args.width:g}{variant}",
                           started, machine(args))]
    elif args.flume_convergence:
        study, name = flume_convergence, f"flume/flume_convergence{args.suffix}.md"
        lines = ["# GRANSPH: the flume impact in resolution\n",
                 generated(f"{NAME} flume-convergence --dx {' '.join(map(str, args.dx))} "
                           f"--models {' '.join(args.models)}{variant}", started, machine(args))]
    elif args.erodible_bed:
        study, name = erodible_bed, f"erodible_bed/erodible_bed{args.suffix}.md"
        lines = ["# GRANSPH: a granular column onto an erodible bed" + label + "\n",
                 generated(f"{NAME} erodible-bed --slopes {' '.join(f'{s:g}' for s in args.slopes)} "
                           f"--thickness {' '.join(f'{e:g}' for e in args.thickness)} --per-height "
                           f"{' '.join(map(str, args.per_height))}"
                           + (f" --tmax {args.tmax:g}" if args.tmax != 3.0 else "")
                           + (f" --floor {args.floor}" if args.floor != "rough" else "") + variant,
                           started, machine(args))]
    else:    # the paper's cases: a report after every case, complete at the end
        report = Report(root, started, [
            "# GRANSPH validation report\n",
            generated(f"{NAME} report{' --paper' if args.paper else ''}{' --quick' if args.quick else ''}",
                      started, machine(args))])
        for case in [column_collapse] if args.quick else [column_collapse, flume_impact,
                                                          jet_collision, jet_film]:
            case(args, report)
            report.write()
        return
    # a study's report: its first lines, the variant's (sphere-impact takes none), the study's
    report = Report(root, started, lines + variant_lines)
    study(args, report)
    report.write(name)
