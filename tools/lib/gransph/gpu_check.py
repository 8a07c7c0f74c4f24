# SPDX-License-Identifier: GPL-2.0-only (GRANSPH: LICENSE)
"""GRANSPH on a GPU: check and time the CUDA bundle that tools/gpu/gpu-bundle builds.

  tools/gpu/gpu-check             # on the GPU machine with gpu-bundle/ carried: under 8 minutes
  tools/gpu/gpu-check --dry-run   # anywhere: is the bundle complete, does it resolve, does it fit?

On the GPU machine (the device tool: run(command="tools/gpu/gpu-check", carry=["gpu-bundle"])):
  1. the GPU and its driver (nvidia-smi); no GPU: a clear message and exit status 2;
  2. the first launch of `lmp -k on g 1 -sf kk` (a tiny run), timed apart from a second one:
     the difference is the one-time cost of loading (and, for code without SASS for the
     GPU, JIT-compiling) the device code;
  3. a short GPU run under compute-sanitizer memcheck (reported);
  4. every case of ctest Kokkos:equal_to_plain (the column collapse at dx 0.02 with each
     wall treatment and option, the jet's phase change), the flume (3 cm, 200 steps),
     the landslide (a terrain with its own normals, the site from the bundle's site/)
     and the erodible bed (examples/erodible_bed: two materials, the column's and the
     bed's, in one run; 300 steps) with `-k on g 1 -sf kk` and with the plain styles on
     one CPU core, compared per atom
     (positions, velocities, density, stress, compute sph/stress/atom) to TOLERANCE;
  5. `-k on g 1 -sf kk` timed on the column at about 1e5, 1e6 and 4e6 particles at rest, at
     4e6 flowing from its first step (-var v0 1: the sand thrown at the floor at 1 m/s,
     its lists built every 30 steps or so, as in the collapse's fastest phase), and on the
     bench's flume and jet: particle-steps per second from LAMMPS' loop time, and its
     timing breakdown (Pair, Neigh, Comm, Modify, ...) from second runs with
     CUDA_LAUNCH_BLOCKING=1, since asynchronous kernel launches put device time into
     whichever section next waits for the device; the device memory each run peaks at
     (nvidia-smi, sampled), hence bytes per particle and the largest column the GPU holds;
  6. two MPI ranks on the one GPU (the bundle's Open MPI, bin/mpirun): the column at dx 0.02
     against one rank, per atom to TOLERANCE, and its throughput at about 1e6 particles
     beside one rank's;
  7. the paper's flume (dx = 10 mm, to 3 s; --flume-dx, --flume-tend for another),
     Drucker-Prager then phase change, as far as the budget allows: simulated time
     reached, steps, wall time, force history and its largest sample, largest 20 ms mean
     and first impact (as tools/research/validate takes them).
Each stage runs whether or not the ones before it failed. Writes gpu-check.json,
gpu-check.log and lammps-logs.tar.gz (every run's log, screen output and stderr) to $OUT (default
./gpu-check-out). A stage that would run past the budget (--budget, 8 minutes) is skipped
and listed as such. Exit status: 0 all ran and agreed, 1 a run failed or the comparison did not agree,
2 no GPU, 3 no usable bundle (77 for --dry-run without a bundle: "not built").
"""

import argparse
import datetime
import json
import os
import re
import shutil
import struct
import subprocess
import sys
import tarfile
import tempfile
import threading
import time

from . import TOP
from . import bench    # the bench's inputs and sizes
from .lammps import GRAINS, LOOP
from .measures import windowed_peak

COLLAPSE = os.path.join(TOP, bench.INPUTS["column"])
POTENTIALS = os.path.join(TOP, "potentials")
BUDGET_S = 480            # default --budget: the 8 minutes, for the whole script
RESERVE_S = 25            # kept back for writing the results
KOKKOS_GPU = ["-k", "on", "g", "1", "-sf", "kk"]

# GPU against plain CPU after 300 steps (0.016 s of the collapse at dx 0.02). Both runs do
# the same arithmetic in another order: the GPU sums each particle's full neighbour list in
# the order of Kokkos' device binning, the plain styles a half list, and nvcc contracts
# a*b+c into FMAs (g++ here builds generic x86-64, no FMA). Each is a perturbation of about
# 1e-16 per operation, which the flow amplifies: the CPU /kk styles (reordering only) stay
# within 1e-10 of the plain ones over these 300 steps (ctest Kokkos:equal_to_plain; measured
# 2026-12-01: 2.4e-12 at worst in the state, 1.9e-11 in compute sph/stress/atom), and
# reach 1e-5 only after a second of settling at the yield surface. FMA perturbs every
# multiply-add rather than every sum: allow ten times the CPU bound. A device-code bug (a
# missed or doubled neighbour among ~75, a race on a sum) moves a particle's rates by
# about 1%, and its state by far more than 1e-6 within 300 steps: three orders above.
TOLERANCE = 1e-9
FIRST = {"dx": 0.04, "steps": 20}
STAGES = ("launch", "memcheck", "compare", "timings", "ranks", "flume")

# the timing runs: (case, label, variables, steps). The column at the bench's 1e5 and, solved
# for grains ~ dx^-3 plus floor ~ dx^-2 from its counts (42,300 + 60,900), 1e6 and 4e6; the
# flume and the jet at the bench's sizes (the flume at the paper's 10 mm).
SIZES = [("column", "1e5", bench.SIZES["column"]["1e5"][0], 200),
         ("column", "1e6", {"dx": 0.00271}, 100),
         ("column", "4e6", {"dx": 0.00163}, 100),
         ("column", "4e6-flow", {"dx": 0.00163, "v0": 1.0}, 200),
         ("flume", "1.2e5", bench.SIZES["flume"]["1.2e5"][0], 200),
         ("jet", "1.1e5", bench.SIZES["jet"]["1.1e5"][0], 200)]
BLOCKING_STEPS = {"1e5": 100, "1e6": 50, "4e6-flow": 100, "1.2e5": 100}
# the flume stage: the paper's spacing and duration unless --flume-dx / --flume-tend say
# otherwise; the Drucker-Prager run leaves the phase change half of the time that is left
# (and whatever it does not use) where that is at least FLUME_RESERVE_S
FLUME = {"dx": 0.01, "tend": 3.0}
FLUME_RESERVE_S = 150
MEMCHECK_S = 90
RUN_S = 60                # a short run that takes longer hangs (each timing run: twice)
# the flume in the comparison: walls on three sides and the outflow, 200 steps at 3 cm
FLUME_COMPARE = {"dx": 0.03, "model": "elastoplastic", "steps": 200}
# and the landslide: a terrain with its dummies' own normals (fix sph/normals), at the
# example's 2 cm. Its site comes made in the bundle (site/: tools/gpu/gpu-bundle runs the
# example's make_site.sh, which needs GDAL, where it builds), so the input's own site
# script is replaced by `true`
LANDSLIDE_COMPARE = {"steps": 200, "site": "true"}
# and the erodible bed: a column of one material onto a layer of a second (the fix's
# keyword material), at the example's defaults (22 degrees, e/h0 = 0.1, dx 7 mm)
ERODIBLE_COMPARE = {"steps": 300}
SITE_FILES = ["site/landslide_site.data", "site/landslide_site.normals"]
# the ranks stage: 2 ranks on the one GPU against 1, compared as the compare stage compares
# (the column's 300 steps at dx 0.02), then timed at the timing stage's 1e6
RANKS_COMPARE = {"dx": 0.02, "steps": 300}
RANKS_TIMING = ("column", "1e6", {"dx": 0.00271}, 100)

# what a bundle holds, and what it may take from the machine it runs on: glibc's parts
# and the C++ runtime (every Linux image has them; the bundle's own code needs glibc 2.34
# and GLIBCXX_3.4.29, g++ 11's, which the dry run checks) and the driver's libcuda, which
# must match the kernel module and so can never travel. The CUDA runtime travels; so does
# g++ 12's C++ runtime, in lib/cxx, used only where lmp does not load without it (it
# needs glibc 2.36 itself, so it is no default).
REQUIRED = ["bin/lmp", "lib/liblammps.so.0", "lib/gransphplugin.so", "lib/libcudart.so.13",
            "lib/libkokkoscore.so.3.4", "lib/libkokkoscontainers.so.3.4",
            "bin/mpirun", "ompi/mpi.env", "lib/libmpi.so.40",
            "lib/cxx/libstdc++.so.6", "lib/cxx/libgcc_s.so.1", "MANIFEST"] + SITE_FILES
SYSTEM_LIBS = {"linux-vdso.so.1", "ld-linux-x86-64.so.2", "libc.so.6", "libm.so.6",
               "libdl.so.2", "libpthread.so.0", "librt.so.1", "libstdc++.so.6", "libgcc_s.so.1"}
NEWEST_GLIBC, NEWEST_GLIBCXX = (2, 34), (3, 4, 29)
DRIVER_LIBS = {"libcuda.so.1"}
CARRY_LIMIT = 64 * 1024 * 1024

LOG_LINES = []


def say(text=""):
    print(text, flush=True)
    LOG_LINES.append(text)


# ---------------------------------------------------------------- the bundle
def elf_files(bundle):
    """every program and library of the bundle, Open MPI's components among them"""
    out = []
    for sub in ("bin", "lib", "ompi", "pmix"):
        for folder, _, names in os.walk(os.path.join(bundle, sub)):
            if folder == os.path.join(bundle, "lib", "cxx"):
                continue                  # the fallback C++ runtime: checked on its own
            for name in sorted(names):
                path = os.path.join(folder, name)
                with open(path, "rb") as f:
                    if f.read(4) == b"\x7fELF":
                        out.append(path)
    return out


def mpi_environment(bundle):
    """what a rank of the bundle's Open MPI needs in its environment, also one run without
    mpirun (ompi/mpi.env, written by tools/gpu/pack-openmpi; $BUNDLE is the bundle's folder)"""
    with open(os.path.join(bundle, "ompi", "mpi.env")) as f:
        pairs = [line.strip().split("=", 1) for line in f if "=" in line]
    return {name: value.replace("$BUNDLE", bundle) for name, value in pairs}


def fatbin_images(path):
    """(kind, arch, bytes) of every image in the ELF's .nv_fatbin section: kind 'sass' or
    'ptx', arch as in sm_90 -> 90. The fatbin container is not documented; its layout is the one
    nvcc 13 writes (header: magic 0xBA55ED50, u16 version, u16 header size, u64 payload
    size; each entry: u16 kind (1 PTX, 2 ELF), u16, u32 header size, u64 payload size,
    ..., u32 arch at offset 28)."""
    with open(path, "rb") as f:
        data = f.read()
    # ELF64 little-endian section headers
    shoff, = struct.unpack_from("<Q", data, 0x28)
    shentsize, shnum, shstrndx = struct.unpack_from("<HHH", data, 0x3A)
    sections = [struct.unpack_from("<IIQQQQIIQQ", data, shoff + i * shentsize) for i in range(shnum)]
    strtab = sections[shstrndx]
    images = []
    for sh in sections:
        end = data.index(b"\0", strtab[4] + sh[0])
        if data[strtab[4] + sh[0]:end] != b".nv_fatbin":
            continue
        pos, stop = sh[4], sh[4] + sh[5]
        while pos + 16 <= stop:
            magic, _, hsize, fsize = struct.unpack_from("<IHHQ", data, pos)
            if magic != 0xBA55ED50:
                pos += 8                      # containers are 8-byte aligned
                continue
            entry, cend = pos + hsize, pos + hsize + fsize
            while entry + 32 <= cend:
                kind, _, ehsize, esize = struct.unpack_from("<HHIQ", data, entry)
                arch, = struct.unpack_from("<I", data, entry + 28)
                images.append(({1: "ptx", 2: "sass"}.get(kind, f"kind{kind}"), arch, esize))
                entry += ehsize + esize
            pos = cend
    return images


def ldd(path, libdir):
    env = dict(os.environ, LD_LIBRARY_PATH=libdir)
    out = subprocess.run(["ldd", path], capture_output=True, text=True, env=env).stdout
    deps = []
    for line in out.splitlines():
        line = line.strip()
        m = re.match(r"(\S+) => (not found|\S+)", line)
        if m:
            deps.append((m.group(1), m.group(2)))
        elif line.startswith("/"):
            deps.append((os.path.basename(line.split()[0]), line.split()[0]))
        elif line.startswith("linux-vdso"):
            deps.append(("linux-vdso.so.1", "vdso"))
    return deps


def versions_needed(path, prefix):
    """the newest symbol version of GLIBC_ or GLIBCXX_ that the ELF file needs"""
    out = subprocess.run(["objdump", "-T", path], capture_output=True, text=True).stdout
    found = {tuple(int(x) for x in v.split("."))
             for v in re.findall(r"\*UND\*.*\(" + prefix + r"_(\d+(?:\.\d+)+)\)", out)}
    return max(found) if found else (0,)


def tree_bytes():
    """bytes of what the device tool carries besides the bundle: tracked files and
    untracked ones that git does not ignore"""
    try:
        names = subprocess.run(["git", "-C", TOP, "ls-files", "-co", "--exclude-standard", "-z"],
                               capture_output=True, check=True).stdout.split(b"\0")
    except (OSError, subprocess.CalledProcessError):
        return None
    return sum(os.path.getsize(os.path.join(TOP, n.decode())) for n in names
               if n and os.path.isfile(os.path.join(TOP, n.decode())))


def dir_bytes(path):
    return sum(os.path.getsize(os.path.join(d, f)) for d, _, fs in os.walk(path) for f in fs)


def open_bundle(bundle, scratch):
    """The folder holding bin/ and lib/: the bundle itself, or, where tools/gpu/gpu-bundle had
    to compress it to fit the carry limit, its bundle.tar.xz unpacked into scratch."""
    packed = os.path.join(bundle, "bundle.tar.xz")
    if os.path.isdir(os.path.join(bundle, "bin")) or not os.path.isfile(packed):
        return bundle
    start = time.monotonic()
    os.makedirs(scratch, exist_ok=True)
    try:
        with tarfile.open(packed) as tar:
            # the "data" filter where this Python has it (3.12 warns without one)
            tar.extractall(scratch, **({"filter": "data"} if hasattr(tarfile, "data_filter") else {}))
    except (ImportError, tarfile.CompressionError):      # a Python without lzma
        subprocess.run(["tar", "-xJf", packed, "-C", scratch], check=True)
    say(f"  unpacked {packed} in {time.monotonic() - start:.1f} s")
    shutil.copy(os.path.join(bundle, "MANIFEST"), os.path.join(scratch, "gpu-bundle", "MANIFEST"))
    shutil.copytree(os.path.join(bundle, "site"), os.path.join(scratch, "gpu-bundle", "site"))
    return os.path.join(scratch, "gpu-bundle")


def check_bundle(bundle, full, carried=None):
    """Problems with the bundle (empty list: usable); prints what it finds. full: also
    the device code, the glibc it needs and the carry limit (the dry run)."""
    problems = []
    missing = [r for r in REQUIRED if not os.path.exists(os.path.join(bundle, r))]
    if missing:
        return [f"missing from {bundle}: {', '.join(missing)}"]
    with open(os.path.join(bundle, "MANIFEST")) as f:
        for line in f:
            say("  " + line.rstrip())
    libdir = os.path.join(bundle, "lib")
    newest_glibc = newest_glibcxx = (0,)
    for path in elf_files(bundle):
        rel = os.path.relpath(path, bundle)
        for name, where in ldd(path, libdir):
            inside = where.startswith(os.path.realpath(bundle) + "/") or where.startswith(bundle + "/")
            # the driver's libcuda: found on a GPU machine, "not found" on one without
            if inside or name in SYSTEM_LIBS or name in DRIVER_LIBS:
                continue
            problems.append(f"{rel} needs {name} from {where}: neither in the bundle nor a system library")
        if full:
            newest_glibc = max(newest_glibc, versions_needed(path, "GLIBC"))
            newest_glibcxx = max(newest_glibcxx, versions_needed(path, "GLIBCXX"))
    if not full:
        return problems
    say(f"  every library resolves inside the bundle or to the system C and C++ runtimes ({', '.join(sorted(SYSTEM_LIBS - {'linux-vdso.so.1'}))})"
        f" or the driver's {', '.join(sorted(DRIVER_LIBS))}" if not problems else "  library problems:")
    version = lambda v: ".".join(map(str, v))
    cxx_glibc = max(versions_needed(os.path.join(libdir, "cxx", f), "GLIBC")
                    for f in ("libstdc++.so.6", "libgcc_s.so.1"))
    say(f"  the bundle needs glibc >= {version(newest_glibc)} and GLIBCXX >= {version(newest_glibcxx)}"
        f" on the GPU machine (with its lib/cxx fallback: glibc >= {version(cxx_glibc)})")
    if newest_glibc > NEWEST_GLIBC or newest_glibcxx > NEWEST_GLIBCXX:
        problems.append(f"the bundle needs newer system libraries than glibc {version(NEWEST_GLIBC)}"
                        f" and GLIBCXX {version(NEWEST_GLIBCXX)}")
    for lib in ("lib/liblammps.so.0", "lib/gransphplugin.so", "lib/libkokkoscore.so.3.4"):
        images = fatbin_images(os.path.join(bundle, lib))
        kinds = sorted({(k, a) for k, a, _ in images})
        say(f"  device code in {lib}: " + ", ".join(
            f"{'sm' if k == 'sass' else 'compute'}_{a} {k} {sum(n for kk, aa, n in images if (kk, aa) == (k, a)) / 2**20:.1f} MiB"
            for k, a in kinds))
        if ("sass", 90) not in kinds:
            problems.append(f"{lib}: no sm_90 machine code (the H200 would JIT-compile it all)")
        if not any(k == "ptx" for k, _ in kinds):
            problems.append(f"{lib}: no PTX (no fallback for a GPU newer than sm_90)")
    bundle_size, tree = dir_bytes(carried or bundle), tree_bytes()
    if tree is None:
        problems.append("cannot list the working tree (git): carry size unknown")
    else:
        total = bundle_size + tree
        say(f"  carry: bundle {bundle_size / 2**20:.1f} MiB + working tree {tree / 2**20:.1f} MiB"
            f" = {total / 2**20:.1f} MiB of {CARRY_LIMIT / 2**20:.0f} MiB")
        if total > CARRY_LIMIT:
            problems.append(f"bundle + tree = {total} bytes, over the {CARRY_LIMIT}-byte carry limit")
    return problems


def smoke_run(bundle):
    """Here, without a GPU: load the bundle's lmp against CUDA's stub libcuda (it links
    and resolves; the stub answers every call with an error) and run the column collapse
    for a few steps with the plain styles, the plugin loaded. Problems (empty: ran)."""
    stubs = [os.path.join(d, "stubs", "libcuda.so") for d in
             ("/usr/local/cuda/lib64", "/usr/local/cuda/lib", "/usr/local/cuda/targets/x86_64-linux/lib")]
    stub = next((p for p in stubs if os.path.isfile(p)), None)
    if not stub:
        say("  smoke run skipped: no stub libcuda (CUDA toolkit) on this machine")
        return []
    with tempfile.TemporaryDirectory() as tmp:
        os.symlink(stub, os.path.join(tmp, "libcuda.so.1"))
        env = dict(os.environ, LD_LIBRARY_PATH=os.path.join(bundle, "lib") + ":" + tmp,
                   LAMMPS_POTENTIALS=POTENTIALS, OMP_NUM_THREADS="1", **mpi_environment(bundle))
        lmp = os.path.join(bundle, "bin", "lmp")
        help_text = subprocess.run([lmp, "-h"], capture_output=True, text=True, env=env, cwd=tmp).stdout
        api = re.search(r"KOKKOS package API: (.*)", help_text)
        say(f"  lmp -h (stub libcuda): {help_text.splitlines()[1].strip() if help_text.count(chr(10)) > 1 else 'no output'};"
            f" KOKKOS package API: {api.group(1).strip() if api else '?'}")
        if not api or "CUDA" not in api.group(1):
            return ["lmp -h does not report a CUDA KOKKOS package"]
        cmd = [lmp, "-in", COLLAPSE, "-var", "dx", "0.04", "-var", "steps", "10", "-log", "none",
               "-echo", "none"]
        proc = subprocess.run(cmd, capture_output=True, text=True, env=env, cwd=tmp, timeout=120)
        result = [l for l in proc.stdout.splitlines() if l.startswith("result:")]
        if proc.returncode != 0 or not result:
            return ["plain styles with the bundle's lmp and plugin failed:\n"
                    + "\n".join((proc.stdout + proc.stderr).splitlines()[-10:])]
        say(f"  plain styles, 10 steps of the column collapse at dx 0.04 with the bundle: ran"
            f" ({' '.join(result[0].split()[:6])} ...)")
        # the compare stage's landslide on the bundle's site
        for site in SITE_FILES:
            shutil.copy(os.path.join(bundle, site), tmp)
        cmd = [lmp, "-in", example("landslide"), "-var", "steps", "5", "-var", "site", "true",
               "-log", "none", "-echo", "none"]
        proc = subprocess.run(cmd, capture_output=True, text=True, env=env, cwd=tmp, timeout=120)
        normals = re.search(r"^Fix sph/normals: (\d+) wall normals from", proc.stdout, re.M)
        if proc.returncode != 0 or not normals:
            return ["the landslide on the bundle's site failed:\n"
                    + "\n".join((proc.stdout + proc.stderr).splitlines()[-10:])]
        say(f"  plain styles, 5 steps of the landslide on the bundle's site: ran ({normals.group(1)}"
            " terrain normals read)")
        # the compare stage's erodible bed: two materials (the integrator's keyword material,
        # which a bundle built before commit 8464c16 does not know)
        cmd = [lmp, "-in", example("erodible_bed"), "-var", "steps", "5", "-log", "none", "-echo", "none"]
        proc = subprocess.run(cmd, capture_output=True, text=True, env=env, cwd=tmp, timeout=120)
        result = [l for l in proc.stdout.splitlines() if l.startswith("result:")]
        if proc.returncode != 0 or not result:
            return ["the erodible bed (two materials) failed with the bundle (built before the"
                    " materials of commit 8464c16? rerun tools/gpu/gpu-bundle):\n"
                    + "\n".join((proc.stdout + proc.stderr).splitlines()[-10:])]
        say("  plain styles, 5 steps of the erodible bed (two materials) with the bundle: ran")
        return ranks_smoke_run(bundle, env, tmp)


def dump_comparison(a, b):
    """two dumps of the same atoms: each column's largest relative difference
    (gransph_run.dump_differences), the worst column, and a phrase that says it"""
    import gransph_run
    diffs = {c: float(v) for c, v in gransph_run.dump_differences(a, b).items()}
    worst = max(diffs, key=diffs.get)
    return diffs, worst, (f"worst {worst} {diffs[worst]:.2e}" if diffs[worst] else "the same to the bit")


def ranks_smoke_run(bundle, env, tmp):
    """The ranks stage's comparison with the plain styles: the column at dx 0.04 on 1 and
    on 2 ranks of the bundle's Open MPI, per atom to TOLERANCE. Problems (empty: agree)."""
    import gransph_run
    states = {}
    for ranks in (1, 2):
        cwd = os.path.join(tmp, f"ranks{ranks}")
        os.makedirs(cwd)
        cmd = [os.path.join(bundle, "bin", "mpirun"), "-np", str(ranks), os.path.join(bundle, "bin", "lmp"),
               "-in", COLLAPSE, "-var", "dx", "0.04", "-var", "steps", "100", "-var", "dump", "1",
               "-log", "none", "-echo", "none"]
        proc = subprocess.run(cmd, capture_output=True, text=True, env=env, cwd=cwd, timeout=120)
        if proc.returncode != 0 or not os.path.isfile(os.path.join(cwd, "column_collapse.dump")):
            return [f"plain styles on {ranks} rank(s) with the bundle's Open MPI failed:\n"
                    + "\n".join((proc.stdout + proc.stderr).splitlines()[-10:])]
        states[ranks] = gransph_run.read_dump(os.path.join(cwd, "column_collapse.dump"))
    moved = float(max(abs(states[1]["vx"]).max(), abs(states[1]["vz"]).max()))
    if moved == 0.0:
        return ["the column did not move in 100 steps: nothing was compared"]
    diffs, worst, phrase = dump_comparison(states[1], states[2])
    say(f"  plain styles, 100 steps of the column at dx 0.04 (largest speed {moved:.2g} m/s) on 2"
        f" ranks of the bundle's mpirun against 1: {phrase} (tolerance {TOLERANCE:g})")
    return [] if diffs[worst] <= TOLERANCE else [f"2 ranks differ from 1 by {diffs[worst]:.1e} in {worst}"]


def stale_note(bundle):
    """a warning if the plugin's sources changed since the bundle was built"""
    with open(os.path.join(bundle, "MANIFEST")) as f:
        m = re.search(r"^commit: (\w+)", f.read(), re.M)
    if not m:
        return None
    r = subprocess.run(["git", "-C", TOP, "diff", "--quiet", m.group(1), "--", "src", "CMakeLists.txt"],
                       capture_output=True)
    if r.returncode == 1:
        return f"warning: src/ or CMakeLists.txt changed since the bundle's commit {m.group(1)[:10]}: rerun tools/gpu/gpu-bundle"
    return None


# ---------------------------------------------------------------- running LAMMPS
class Runner:
    def __init__(self, bundle, work, deadline):
        self.lmp = os.path.join(bundle, "bin", "lmp")
        self.bundle = bundle
        self.work = work
        self.deadline = deadline
        self.logs = os.path.join(work, "logs")
        os.makedirs(self.logs, exist_ok=True)
        libdir = os.path.join(bundle, "lib")
        for path in (libdir, libdir + ":" + os.path.join(libdir, "cxx")):
            env = dict(os.environ, LD_LIBRARY_PATH=path + (":" + os.environ["LD_LIBRARY_PATH"]
                                                           if os.environ.get("LD_LIBRARY_PATH") else ""))
            probe = subprocess.run([self.lmp, "-h"], capture_output=True, text=True, env=env)
            if probe.returncode == 0:
                break
            say(f"  lmp does not load with LD_LIBRARY_PATH={path}: {probe.stderr.strip()[-300:]}")
        else:
            raise RuntimeError("the bundle's lmp does not load here, with or without lib/cxx")
        self.libpath = path
        say(f"  lmp loads with the bundle's {os.path.relpath(path.split(':')[-1], bundle)}"
            f"{' (the C++ runtime of the image was too old)' if 'cxx' in path else ' and the image C++ runtime'}")
        self.env = dict(env, **mpi_environment(bundle),
                        LAMMPS_POTENTIALS=POTENTIALS, OMP_NUM_THREADS="1",
                        # JIT results (only for code without sm_90 SASS) kept for the whole call
                        CUDA_CACHE_PATH=os.path.join(work, "cuda-cache"),
                        CUDA_CACHE_MAXSIZE=str(4 * 2**30))

    def keep(self, name, stdout, stderr):
        """a run's screen output and stderr beside its log (CUDA's and the sanitizer's
        messages are in no LAMMPS log)"""
        with open(os.path.join(self.logs, f"out.{name}"), "w") as f:
            for text in (stdout, stderr):
                f.write(text.decode(errors="replace") if isinstance(text, bytes) else text or "")

    def left(self):
        return self.deadline - time.monotonic()

    def run(self, name, variables, args=(), env=None, timeout=None, script=COLLAPSE,
            partial=False, wrapper=()):
        """Run `script` (the column collapse unless said) in its own folder; (stdout, wall
        seconds, finished). Raises on failure, and on timeout unless `partial` (then what
        it printed so far, and finished False). `wrapper`: a command that runs lmp."""
        cwd = os.path.join(self.work, name)
        os.makedirs(cwd, exist_ok=True)
        cmd = list(wrapper) + [self.lmp, "-in", script, "-log", os.path.join(self.logs, f"log.{name}"),
               "-echo", "none"]
        for key, value in variables.items():
            cmd += ["-var", key, str(value)]
        cmd += list(args)
        limit = min(self.left(), timeout or 1e9)
        if limit < 5:
            raise TimeoutError(f"{name}: no time left in the budget")
        start = time.monotonic()
        try:
            proc = subprocess.run(cmd, cwd=cwd, capture_output=True, text=True,
                                  env=dict(self.env, **(env or {})), timeout=limit)
        except subprocess.TimeoutExpired as stopped:
            self.keep(name, stopped.stdout, stopped.stderr)
            if not partial:
                raise TimeoutError(f"{name}: stopped after {limit:.0f} s (the budget)")
            out = stopped.stdout or ""
            return (out.decode(errors="replace") if isinstance(out, bytes) else out,
                    time.monotonic() - start, False)
        wall = time.monotonic() - start
        self.keep(name, proc.stdout, proc.stderr)
        # LAMMPS' errors start a line; compute-sanitizer's "ERROR SUMMARY" follows its "====="
        if proc.returncode != 0 or re.search(r"^ERROR", proc.stdout, re.M):
            tail = "\n".join((proc.stdout + proc.stderr).splitlines()[-15:])
            raise RuntimeError(f"{name}: LAMMPS failed (exit {proc.returncode}):\n{tail}")
        if args and "will use up to 1 GPU(s) per node" not in proc.stdout:
            raise RuntimeError(f"{name}: LAMMPS did not report the GPU (Kokkos not on CUDA?)")
        return proc.stdout, wall, True


BINS = re.compile(r"binsize = \S+, bins = +(\d+) +(\d+) +(\d+)")    # the neighbour bins
BUILDS = re.compile(r"Neighbor list builds = (\d+)")
SECTIONS = ("Pair", "Bond", "Kspace", "Neigh", "Comm", "Output", "Modify", "Other")


def breakdown(stdout):
    """{section: {s, percent}} from the last 'MPI task timing breakdown' table: rows of
    'name | min | avg | max | %varavg | %total' (Other has only avg and %total)"""
    phases = {}
    for line in stdout.split("MPI task timing breakdown")[-1].splitlines():
        cols = [c.strip() for c in line.split("|")]
        if len(cols) == 6 and cols[0] in SECTIONS:
            phases[cols[0]] = {"s": float(cols[2]), "percent": float(cols[5])}
    return phases


def timing(stdout):
    loops = LOOP.findall(stdout)
    seconds, steps, atoms = loops[-1]
    grains = GRAINS.findall(stdout) or [atoms]    # the jet: all are grains
    phases = breakdown(stdout)
    bins = [int(n) for n in BINS.findall(stdout)[-1]] if BINS.search(stdout) else None
    builds = BUILDS.findall(stdout)
    return {"bins": bins, "list_builds": int(builds[-1]) if builds else None, "atoms": int(atoms), "grains": int(grains[0]), "steps": int(steps),
            "loop_s": float(seconds), "particle_steps_per_s": int(steps) * int(atoms) / float(seconds),
            "phases": phases}


# ---------------------------------------------------------------- stages
def gpu_info():
    smi = shutil.which("nvidia-smi")
    if not smi:
        return None, "nvidia-smi not found: no NVIDIA driver on this machine"
    query = "name,driver_version,memory.total,compute_cap"
    proc = subprocess.run([smi, f"--query-gpu={query}", "--format=csv,noheader"],
                          capture_output=True, text=True)
    lines = [l for l in proc.stdout.splitlines() if l.strip()]
    if proc.returncode != 0 or not lines:
        return None, f"nvidia-smi found no GPU: {(proc.stdout + proc.stderr).strip()[-300:]}"
    gpus = [dict(zip(query.split(","), (w.strip() for w in l.split(",")))) for l in lines]
    cuda = re.search(r"CUDA Version: (\S+)", subprocess.run([smi], capture_output=True, text=True).stdout)
    for g in gpus:
        g["cuda_driver_api"] = cuda.group(1) if cuda else None
    return gpus, None


class DeviceMemory:
    """The GPU memory in use (MiB, nvidia-smi) before and at most while the `with` block
    runs, sampled every quarter second: a run's peak less what was in use before it."""
    def __init__(self):
        self.before = self.peak = self._used()
        self._stop = threading.Event()
        self._thread = threading.Thread(target=self._sample, daemon=True)

    @staticmethod
    def _used():
        proc = subprocess.run(["nvidia-smi", "--query-gpu=memory.used", "--format=csv,noheader,nounits"],
                              capture_output=True, text=True)
        try:
            return float(proc.stdout.split()[0])
        except (IndexError, ValueError):
            return float("nan")

    def _sample(self):
        while not self._stop.wait(0.25):
            self.peak = max(self.peak, self._used())

    def __enter__(self):
        self._thread.start()
        return self

    def __exit__(self, *exc):
        self._stop.set()
        self._thread.join()

    def mib(self):
        return self.peak - self.before


def device_memory(result):
    """bytes per particle on the device from the column's two largest timing runs (the
    difference in their peaks over the difference in particles), and the largest column
    the GPU's memory would hold at that rate"""
    runs = sorted((t for t in result["timings"] if t["case"] == "column" and not t["blocking"]
                   and "v0" not in t["variables"] and t.get("device_mib") == t.get("device_mib")),
                  key=lambda t: t["atoms"])
    if len(runs) < 2:
        return
    small, large = runs[-2], runs[-1]
    per_particle = (large["device_mib"] - small["device_mib"]) * 2**20 / (large["atoms"] - small["atoms"])
    fixed = large["device_mib"] * 2**20 - per_particle * large["atoms"]
    total = float(result["gpus"][0]["memory.total"].split()[0]) * 2**20
    largest = (total - fixed) / per_particle if per_particle > 0 else None
    result["device_memory"] = {"bytes_per_particle": per_particle, "fixed_bytes": fixed,
                               "largest_column_particles": largest}
    say(f"  device memory: {per_particle:.0f} bytes per particle (column, {small['label']} to {large['label']}),"
        f" {fixed / 2**20:.0f} MiB besides; the GPU's {total / 2**30:.0f} GiB would hold a column of about"
        f" {largest:.2e} particles" if largest else "  device memory: no growth with the particles measured")


def example(case):
    return os.path.join(TOP, "examples", case, f"in.{case}")


def compare(runner, result):
    """The cases of ctest Kokkos:equal_to_plain (the column with each wall treatment and
    option, the jet's phase change), the GPU against the plain styles on one core; and the
    flume (walls on three sides, outflow), the landslide and the erodible bed (two
    materials). True where every double-precision case agrees;
    the single-precision sums (`precision mixed`) in another order are reported only:
    float's round-off, amplified as above, is the size of the bug it would look for."""
    import numpy as np
    import gransph_run
    import test_kokkos_equal
    result["compare"] = []
    cases = test_kokkos_equal.CASES + [("flume_impact", FLUME_COMPARE),
                                       ("landslide", LANDSLIDE_COMPARE),
                                       ("erodible_bed", ERODIBLE_COMPARE)]
    agree = True
    for k, (case, variables) in enumerate(cases):
        label = test_kokkos_equal.label_of(case, variables)
        mixed = "precision mixed" in variables.get("pair_options", "")
        entry = {"case": label, "variables": variables, "tolerance": None if mixed else TOLERANCE}
        result["compare"].append(entry)
        try:
            states = {}
            for where, args in (("gpu", KOKKOS_GPU), ("cpu", [])):
                name = f"compare{k}_{where}"
                if case == "landslide":
                    os.makedirs(os.path.join(runner.work, name), exist_ok=True)
                    for site in SITE_FILES:
                        shutil.copy(os.path.join(runner.bundle, site), os.path.join(runner.work, name))
                _, wall, _ = runner.run(name, {**variables, "dump": 1}, args, script=example(case),
                                        timeout=RUN_S)
                entry[f"{where}_s"] = wall
                states[where] = gransph_run.read_dump(os.path.join(runner.work, name, f"{case}.dump"))
        except (RuntimeError, TimeoutError) as e:
            say(f"  {label}: FAILED: {e}")
            entry["error"] = str(e)
            agree = False
            continue
        gpu, cpu = states["gpu"], states["cpu"]
        moved = float(np.max(np.abs(cpu["vx"])))
        diffs, worst, phrase = dump_comparison(cpu, gpu)
        ok = moved > 1e-3 and (mixed or diffs[worst] <= TOLERANCE)
        entry.update(atoms=len(cpu["id"]), max_relative_difference=diffs, worst=worst, ok=ok)
        agree = agree and ok
        verdict = ("reported (single-precision sums)" if mixed else "agree" if ok else "DO NOT AGREE")
        say(f"  {label}: {len(cpu['id'])} particles, GPU {entry['gpu_s']:.1f} s, CPU {entry['cpu_s']:.1f} s:"
            f" {phrase}: {verdict}"
            + ("" if moved > 1e-3 else "; nothing moved: nothing was compared"))
    return agree


def memcheck(runner, result):
    """A short GPU run under compute-sanitizer's memcheck (out-of-bounds and misaligned
    device accesses, errors of CUDA calls): reported, not part of the exit status (Kokkos'
    own start-up may trip it)."""
    sanitizer = shutil.which("compute-sanitizer") or next(
        (p for p in ("/usr/local/cuda/bin/compute-sanitizer",) if os.path.isfile(p)), None)
    if not sanitizer:
        say("  skipped: no compute-sanitizer")
        result["skipped"].append("memcheck: no compute-sanitizer")
        return
    wrapper = [sanitizer, "--tool", "memcheck", "--print-limit", "20", "--error-exitcode", "9"]
    try:
        out, wall, _ = runner.run("memcheck", {"dx": 0.04, "steps": 10}, KOKKOS_GPU,
                                  timeout=MEMCHECK_S, wrapper=wrapper)
        summary = next((l for l in out.splitlines() if "ERROR SUMMARY" in l), "no summary")
        result["memcheck"] = {"wall_s": wall, "summary": summary}
        say(f"  {summary.strip()} ({wall:.0f} s)")
    except (RuntimeError, TimeoutError) as e:
        result["memcheck"] = {"error": str(e)}
        say(f"  reported: {e}")


def force_peaks(history):
    """(last time, measures) of a flume force history: its largest sample and largest 20 ms
    mean with their times and the first impact, as tools/research/validate's flume study takes them"""
    import numpy as np
    t, f = np.loadtxt(history, unpack=True, ndmin=2)
    if len(t) < 2:
        return (float(t[-1]) if len(t) else 0.0), {}
    k = int(np.argmax(f))
    mean, mean_at, _ = windowed_peak(t, f)
    hit = np.nonzero(f > 5.0)[0]
    return float(t[-1]), {"largest_sample_N": float(f[k]), "at_s": float(t[k]),
                          "largest_20ms_mean_N": mean, "mean_at_s": mean_at,
                          "first_impact_s": float(t[hit[0]]) if len(hit) else -1.0}


def paper_flume(runner, result, model, reserve, flume):
    """examples/flume_impact at the paper's dx = 10 mm to its 3 s on the GPU (the paper:
    72 minutes on a Quadro K620), or at flume's dx and tend, stopped where the budget ends:
    how far it got, in how long, and its force history (kept with the logs)."""
    name = f"paper_flume_{model}" if flume == FLUME else f"flume_dx{flume['dx']:g}_{model}"
    limit = runner.left() - reserve
    if limit < 30:
        say(f"  {model}: skipped: {limit:.0f} s left")
        result["skipped"].append(f"{name}: {limit:.0f} s left")
        return
    variables = {**flume, "model": model}
    out, wall, finished = runner.run(name, variables, KOKKOS_GPU, script=example("flume_impact"),
                                     timeout=limit, partial=True)
    history = os.path.join(runner.work, name, "flume_impact.force")
    reached, peaks = 0.0, {}
    if os.path.isfile(history):
        shutil.copy(history, os.path.join(runner.logs, f"{name}.force"))
        reached, peaks = force_peaks(history)
    if not finished:    # LAMMPS' log is flushed as it runs, its screen output to a pipe is not
        with open(os.path.join(runner.logs, f"log.{name}")) as f:
            out = f.read()
    loops = LOOP.findall(out)
    steps = sum(int(n) for _, n, _ in loops)
    line = next((l for l in out.splitlines() if l.startswith("result:")), None)
    result.setdefault("paper_flume", []).append(
        {"model": model, **variables, "finished": finished, "simulated_s": reached, **peaks, "steps": steps,
         "wall_s": wall, "loop_s": sum(float(t) for t, _, _ in loops),
         "atoms": int(loops[-1][2]) if loops else None, "result": line})
    say(f"  {model}: {'to' if finished else 'stopped at'} t = {reached:.3f} s, {steps} steps in {wall:.0f} s wall"
        + "".join(f", {k} {v:.3f}" for k, v in peaks.items()))


def main():
    parser = argparse.ArgumentParser(prog="tools/gpu/gpu-check", description=__doc__.split("\n")[0])
    parser.add_argument("--dry-run", action="store_true",
                        help="check the bundle here (complete, resolves, fits the carry limit)")
    parser.add_argument("--bundle", default=os.environ.get("GRANSPH_GPU_BUNDLE", os.path.join(TOP, "gpu-bundle")))
    parser.add_argument("--stages", default=",".join(STAGES),
                        help=f"which stages to run, of {','.join(STAGES)} (default all)")
    parser.add_argument("--budget", type=float, default=BUDGET_S,
                        help=f"seconds for the whole check (default {BUDGET_S})")
    parser.add_argument("--flume-dx", type=float, default=FLUME["dx"],
                        help=f"the flume stage's spacing in m (default the paper's {FLUME['dx']})")
    parser.add_argument("--flume-tend", type=float, default=FLUME["tend"],
                        help=f"the flume stage's simulated time in s (default the paper's {FLUME['tend']})")
    parser.add_argument("--out", default=os.environ.get("OUT", os.path.join(os.getcwd(), "gpu-check-out")))
    opts = parser.parse_args()
    bundle = os.path.abspath(opts.bundle)

    if opts.dry_run:
        say(f"gpu-check --dry-run: {bundle}")
        if not os.path.isdir(bundle):
            say(f"NOT BUILT: no bundle in {bundle} (tools/gpu/gpu-bundle builds it)")
            return 77
        with tempfile.TemporaryDirectory() as scratch:
            unpacked = open_bundle(bundle, scratch)
            problems = check_bundle(unpacked, full=True, carried=bundle)
            if not problems:
                problems = smoke_run(unpacked)
        for inp in (COLLAPSE, os.path.join(POTENTIALS, "sand.gransph"), example("landslide"),
                    example("erodible_bed")):
            if not os.path.isfile(inp):
                problems.append(f"input missing: {inp}")
        note = stale_note(bundle)
        if note:
            say("  " + note)
        for p in problems:
            say("  FAILED: " + p)
        say("dry run: " + ("ok, ready to carry: run(command=\"tools/gpu/gpu-check\", carry=[\"gpu-bundle\"])"
                           if not problems else f"{len(problems)} problem(s)"))
        return 1 if problems else 0

    start = time.monotonic()
    os.makedirs(opts.out, exist_ok=True)
    result = {"date": datetime.datetime.now(datetime.timezone.utc).isoformat(timespec="seconds"),
              "host": os.uname().nodename, "cpus": os.cpu_count(), "skipped": [], "errors": []}
    work = tempfile.mkdtemp(prefix="gpu-check-")
    status = 1
    try:
        status = check(bundle, work, start, opts.budget, opts.stages.split(","), result,
                       {"dx": opts.flume_dx, "tend": opts.flume_tend})
    except (RuntimeError, TimeoutError) as e:
        say(f"FAILED: {e}")
        result["errors"].append(str(e))
        status = 1
    finally:
        result["total_s"] = time.monotonic() - start
        result["exit_status"] = status
        say(f"gpu-check: {result['total_s']:.0f} s, exit status {status}")
        with open(os.path.join(opts.out, "gpu-check.json"), "w") as f:
            json.dump(result, f, indent=1)
        with open(os.path.join(opts.out, "gpu-check.log"), "w") as f:
            f.write("\n".join(LOG_LINES) + "\n")
        logs = os.path.join(work, "logs")
        if os.path.isdir(logs) and os.listdir(logs):
            with tarfile.open(os.path.join(opts.out, "lammps-logs.tar.gz"), "w:gz") as tar:
                tar.add(logs, arcname="lammps-logs")
        shutil.rmtree(work, ignore_errors=True)
    return status


def check(bundle, work, start, budget, stages, result, flume):
    """the stages on the GPU machine; the exit status"""
    status = 0
    say(f"gpu-check {result['date']} on {result['host']} ({result['cpus']} CPUs)")
    gpus, why = gpu_info()
    if not gpus:
        say(f"gpu-check: no GPU found ({why}). This script runs on the borrowed GPU machine;"
            " here, use tools/gpu/gpu-check --dry-run.")
        result["errors"].append(why)
        return 2
    result["gpus"] = gpus
    for g in gpus:
        say(f"GPU: {g['name']}, driver {g['driver_version']} (CUDA {g['cuda_driver_api']}),"
            f" {g['memory.total']}, compute capability {g['compute_cap']}")
    say("bundle:")
    if os.path.isdir(bundle):
        bundle = open_bundle(bundle, os.path.join(work, "bundle"))
        problems = check_bundle(bundle, full=False)
    else:
        problems = [f"no bundle in {bundle}"]
    if problems:
        for p in problems:
            say("  " + p)
        result["errors"] += problems
        return 3
    with open(os.path.join(bundle, "MANIFEST")) as f:
        result["bundle"] = f.read().splitlines()
    runner = Runner(bundle, work, start + budget - RESERVE_S)
    result["library_path"] = runner.libpath

    result["stages"] = stages
    if "launch" in stages:
        status = max(status, first_launch(runner, result))
    if "memcheck" in stages:
        say("compute-sanitizer memcheck (column collapse dx 0.04, 10 steps, -k on g 1 -sf kk):")
        memcheck(runner, result)
    if "compare" in stages:
        say("GPU against the plain styles on one CPU core (the cases of ctest Kokkos:equal_to_plain, the flume,"
            " the landslide and the erodible bed):")
        if not compare(runner, result):
            status = 1
    if "timings" in stages:
        status = max(status, timings(runner, result))
    if "ranks" in stages:    # before the flume, which takes what is left of the budget
        status = max(status, two_ranks(runner, result))
    if "flume" in stages:
        say(f"the flume (dx = {flume['dx'] * 1000:g} mm, to {flume['tend']:g} s; the paper's: 10 mm to 3 s,"
            " 72 minutes on a Quadro K620):")
        # both models where there is time for both, else Drucker-Prager as far as it gets
        left = runner.left()
        paper_flume(runner, result, "elastoplastic", flume=flume,
                    reserve=max(FLUME_RESERVE_S, left / 2) if left > 2 * FLUME_RESERVE_S else 0)
        paper_flume(runner, result, "phasechange", reserve=0, flume=flume)
    return status


def first_launch(runner, result):
    """the first GPU run of a call timed apart from a second; the exit status"""
    say(f"first launch (column collapse dx {FIRST['dx']}, {FIRST['steps']} steps, -k on g 1 -sf kk):")
    try:
        _, first, _ = runner.run("first", FIRST, KOKKOS_GPU, timeout=RUN_S)
        _, second, _ = runner.run("second", FIRST, KOKKOS_GPU, timeout=RUN_S)
        result["first_launch"] = {"first_s": first, "second_s": second, "once_s": first - second}
        say(f"  first {first:.1f} s, second {second:.1f} s: {first - second:.1f} s once per call"
            " (device-code loading, JIT if any)")
    except (RuntimeError, TimeoutError) as e:    # the stages after it say more: each runs on
        say(f"  FAILED: {e}")
        result["errors"].append(str(e))
        return 1
    return 0


def timings(runner, result):
    """the throughput runs of SIZES, then those of BLOCKING_STEPS blocking; the exit status"""
    status = 0
    result["timings"] = []
    stages = [(case, label, variables, steps, False) for case, label, variables, steps in SIZES] + \
             [(case, label, variables, steps, True) for case, label, variables, steps in SIZES
              if label in BLOCKING_STEPS]
    say("throughput, -k on g 1 -sf kk (particle-steps/s; breakdown from CUDA_LAUNCH_BLOCKING=1 runs):")
    for case, label, variables, steps, blocking in stages:
        name = f"time_{case}_{label}" + ("_blocking" if blocking else "")
        try:
            with DeviceMemory() as memory:
                out, wall, _ = runner.run(name, {**variables, "steps": BLOCKING_STEPS[label] if blocking else steps},
                                          KOKKOS_GPU, script=os.path.join(TOP, bench.INPUTS[case]),
                                          env={"CUDA_LAUNCH_BLOCKING": "1"} if blocking else None,
                                          timeout=2 * RUN_S)
        except TimeoutError as e:
            say(f"  {name}: skipped: {e}")
            result["skipped"].append(str(e))
            continue
        except RuntimeError as e:          # one size failing (memory, say) spoils no other
            say(f"  FAILED: {e}")
            result["errors"].append(str(e))
            status = 1
            continue
        t = dict(timing(out), case=case, label=label, variables=variables, blocking=blocking, wall_s=wall,
                 device_mib=memory.mib())
        result["timings"].append(t)
        if t["bins"] == [1, 1, 1]:    # every list build O(N^2): see PairSPHGranularKokkos::init_style
            say(f"  FAILED: {name}: one neighbour bin for the whole box")
            result["errors"].append(f"{name}: one neighbour bin for the whole box")
            status = 1
        phases = ", ".join(f"{k} {v['percent']:.0f}%" for k, v in t["phases"].items() if v["percent"] >= 0.5)
        say(f"  {case} {label}{' blocking' if blocking else ''}: {t['atoms']:,} particles ({t['grains']:,} grains),"
            f" {t['steps']} steps in {t['loop_s']:.2f} s (wall {wall:.0f} s with setup):"
            f" {t['particle_steps_per_s']:.3e} particle-steps/s; {phases}; {t['list_builds']} list builds;"
            f" neighbour bins {t['bins']};"
            f" device memory {t['device_mib']:.0f} MiB")
    device_memory(result)
    return status



def two_ranks(runner, result):
    """two MPI ranks sharing the one GPU against one rank: the column compared per atom,
    then timed at RANKS_TIMING's size; the exit status"""
    import gransph_run
    say("two ranks on the one GPU (the bundle's Open MPI), -k on g 1 -sf kk:")
    mpirun = [os.path.join(runner.bundle, "bin", "mpirun"), "-np", "2"]
    entry = result["ranks"] = {"compare": RANKS_COMPARE, "tolerance": TOLERANCE}
    try:
        states = {}
        for ranks, wrapper in ((1, ()), (2, mpirun)):
            name = f"ranks{ranks}"
            _, entry[f"ranks{ranks}_s"], _ = runner.run(name, {**RANKS_COMPARE, "dump": 1}, KOKKOS_GPU,
                                                        timeout=RUN_S, wrapper=wrapper)
            states[ranks] = gransph_run.read_dump(os.path.join(runner.work, name, "column_collapse.dump"))
        diffs, worst, phrase = dump_comparison(states[1], states[2])
        entry.update(atoms=len(states[1]["id"]), max_relative_difference=diffs, worst=worst,
                     ok=diffs[worst] <= TOLERANCE)
        say(f"  column dx {RANKS_COMPARE['dx']}, {RANKS_COMPARE['steps']} steps, {entry['atoms']} particles:"
            f" 2 ranks against 1, {phrase}: {'agree' if entry['ok'] else 'DO NOT AGREE'}")
        case, label, variables, steps = RANKS_TIMING
        out, wall, _ = runner.run(f"ranks2_{case}_{label}", {**variables, "steps": steps}, KOKKOS_GPU,
                                  script=os.path.join(TOP, bench.INPUTS[case]), timeout=2 * RUN_S,
                                  wrapper=mpirun)
        t = entry["timing"] = dict(timing(out), case=case, label=label, wall_s=wall)
        one = next((o for o in result.get("timings", []) if o["label"] == label and not o["blocking"]), None)
        say(f"  {case} {label} on 2 ranks: {t['atoms']:,} particles, {t['steps']} steps in {t['loop_s']:.2f} s:"
            f" {t['particle_steps_per_s']:.3e} particle-steps/s"
            + (f", {t['particle_steps_per_s'] / one['particle_steps_per_s']:.2f} times one rank's" if one else ""))
        # where the time goes, the ranks' messages staged through the host among it
        out, _, _ = runner.run(f"ranks2_{case}_{label}_blocking", {**variables, "steps": BLOCKING_STEPS[label]},
                               KOKKOS_GPU, script=os.path.join(TOP, bench.INPUTS[case]),
                               env={"CUDA_LAUNCH_BLOCKING": "1"}, timeout=2 * RUN_S, wrapper=mpirun)
        phases = entry["blocking_phases"] = breakdown(out)
        say("  the same blocking: " + ", ".join(f"{k} {v['percent']:.0f}%" for k, v in phases.items()
                                                 if v["percent"] >= 0.5))
    except (RuntimeError, TimeoutError) as e:
        say(f"  FAILED: {e}")
        entry["error"] = str(e)
        result["errors"].append(str(e))
        return 1
    return 0 if entry["ok"] else 1


if __name__ == "__main__":
    sys.exit(main())
