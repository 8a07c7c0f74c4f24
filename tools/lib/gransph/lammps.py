# SPDX-License-Identifier: GPL-2.0-only (GRANSPH: LICENSE)
"""Running LAMMPS through tools/lmp: the command line of a run (variables, MPI ranks or
the /kk styles on threads), its folder, log, wall time and result line."""

import os
import re
import subprocess
import sys
import time

from . import TOP

LMP = os.path.join(TOP, "tools", "lmp")
EXAMPLES = os.path.join(TOP, "examples")
# LAMMPS' "Loop time of T on P procs for N steps with A atoms" and the grains a GRANSPH
# input reports (the bench and the GPU check time runs by them)
LOOP = re.compile(r"Loop time of (\S+) on \d+ procs for (\d+) steps with (\d+) atoms")
GRAINS = re.compile(r"^\s*(\d+) atoms in group sand\s*$", re.M)    # the jet: all are grains


def environment():
    """the environment of an MPI run (as root where the machine runs everything as root)"""
    return dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")


def finished(workdir, command):
    """Whether workdir holds a finished run (its wall time and a result line) of this
    command; runs from before the command was recorded count if they finished."""
    log = os.path.join(workdir, "log.lammps")
    if not (os.path.exists(os.path.join(workdir, "wall_time")) and os.path.exists(log)):
        return False
    recorded = os.path.join(workdir, "command")
    if os.path.exists(recorded) and open(recorded).read().strip() != command:
        return False
    return any(l.startswith("result:") for l in open(log).read().splitlines())


class Runner:
    """Runs examples and inputs into out/runs/<tag>/ and writes reports and plots under
    out: `kokkos` runs the /kk styles on `ranks` OpenMP threads instead of MPI ranks,
    `resume` keeps a run that the same command finished before."""

    def __init__(self, out, kokkos=False, resume=False, say="[validate]"):
        self.root = os.path.abspath(out)
        self.kokkos = kokkos
        self.resume = resume
        self.say = say
        self.env = environment()

    def out(self, *parts):
        """a path under the output folder, its folder made"""
        path = os.path.join(self.root, *parts)
        os.makedirs(os.path.dirname(path), exist_ok=True)
        return path

    def workdir(self, tag):
        """the run folder of tag, made"""
        workdir = os.path.join(self.root, "runs", tag)
        os.makedirs(workdir, exist_ok=True)
        return workdir

    def command(self, input_file, variables, ranks, may_fail=False):
        cmd = [LMP, "-in", input_file, "-log", "log.lammps", "-echo", "none", "-screen", "none"]
        if may_fail:    # LAMMPS' error message on the screen, line-buffered: its log loses it
            cmd = ["stdbuf", "-oL"] + cmd[:-2]    # when the error aborts (LAMMPS_EXCEPTIONS)
        for name, value in variables.items():
            cmd += ["-var", name, str(value)]
        if self.kokkos:
            cmd += ["-k", "on", "t", str(ranks), "-sf", "kk"]
        elif ranks > 1:
            cmd = ["mpirun", "-np", str(ranks)] + cmd
        return cmd

    def run(self, case, variables, ranks, tag, input_file=None, may_fail=False):
        """Run examples/<case>/in.<case> (or input_file); return the words of its 'result:'
        line (None for an input without one) and the run's folder. With may_fail a run that
        stops with an error returns None, its reason in the folder's file 'failed'."""
        say = self.say
        workdir = self.workdir(tag)
        input_file = input_file or os.path.join(EXAMPLES, case, f"in.{case}")
        example = os.path.dirname(input_file) == os.path.join(EXAMPLES, case)
        cmd = self.command(input_file, variables, ranks, may_fail)
        command = " ".join(cmd)
        if self.resume and finished(workdir, command):
            print(f"{say} {tag}: kept from an earlier run (--resume)", flush=True)
            log = open(os.path.join(workdir, "log.lammps")).read()
            return [l for l in log.splitlines() if l.startswith("result:")][-1].split(), workdir
        print(f"{say} {tag}: {variables}", flush=True)
        start = time.monotonic()
        for name in ("wall_time", "command"):    # a run stopped midway is not finished
            if os.path.exists(os.path.join(workdir, name)):
                os.remove(os.path.join(workdir, name))
        proc = subprocess.run(cmd, cwd=workdir, env=self.env, capture_output=True, text=True)
        with open(os.path.join(workdir, "wall_time"), "w") as f:
            f.write(f"{time.monotonic() - start:.1f}\n")
        with open(os.path.join(workdir, "command"), "w") as f:
            f.write(command + "\n")
        log = open(os.path.join(workdir, "log.lammps")).read() if os.path.exists(
            os.path.join(workdir, "log.lammps")) else proc.stdout
        results = [l for l in log.splitlines() if l.startswith("result:")]
        if proc.returncode != 0 and may_fail:
            lines = (log + proc.stdout + proc.stderr).splitlines()
            errors = ([l.strip() for l in lines if l.startswith("ERROR")] +    # LAMMPS' own first
                      [l.strip() for l in lines if "ERROR" in l])
            with open(os.path.join(workdir, "failed"), "w") as f:
                f.write((errors[0] if errors else f"exit status {proc.returncode}") + "\n")
            print(f"{say} {tag} stopped: {errors[0] if errors else proc.returncode}", flush=True)
            return None, workdir
        if proc.returncode != 0 or (example and not results):
            sys.exit(f"{say} {tag} failed:\n{log[-3000:]}{proc.stderr[-2000:]}")
        return (results[-1].split() if results else None), workdir
