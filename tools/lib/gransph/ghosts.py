# SPDX-License-Identifier: GPL-2.0-only (GRANSPH: LICENSE)
"""What the ranks of a run on several GPUs would send each other, and
an estimate of weak scaling to 16 GPUs from it (bench/README.md, "Several GPUs: an
estimate of weak scaling"; issue 51).

  bench/ghosts.py                    # measure on 2 and 4 ranks, then estimate: ~5 minutes
  bench/ghosts.py --estimate-only    # the estimate from the lattice model alone: seconds
  bench/ghosts.py --ranks 2 --case jet --out /tmp/g

Measured (plain styles, `mpirun --oversubscribe -np N`, the runs niced: counts, not
timings), for each case below: owned particles, ghosts and neighbours per rank (LAMMPS'
Nlocal, Nghost and FullNghs summaries at the end of the run), the neighbour list builds,
and the atoms that change rank at a build, counted from a dump of `id proc` (the example's
input with the dump added): an atom whose owner differs between two snapshots moved once
(every few steps: within them an atom crosses no more than one boundary, once).

  column         examples/column_collapse at dx = 3.1 mm (690,888 particles), 10 steps
  column-flow    the same at dx = 10 mm (41,020) mid-collapse: 3800 steps (t = 0.1 s),
                 then 300 with a snapshot every 5 (the first steps from rest build no list)
  column-flow-x  the same on a 4x1x1 grid balanced along x (`processors * 1 1`, `balance
                 1.0 shift x 20 1.0` after the 3800 steps): cuts across the radial flow,
                 which the even 1x2x1 and 2x2x1 grids' cuts at x = 0, y = 0 are not
  jet            examples/jet_collision at dx = 6 mm (the bench's 108,800 particles), 200
                 steps from the start, a snapshot every 5

The model: the examples' particles as create_atoms places them (a simple cubic lattice,
coordinates (i + 1/2) dx; a disc in a plane extruded along the third axis: the column's
and the floor's discs along z, the jets' along x), the processor grid LAMMPS picks
(ProcMap::best_factors: the least sub-domain surface) and sub-domains split evenly (the
column's input) or at equal particle counts along each split axis (`balance shift`, the
jet's fix balance); owned = the particles in a sub-domain, ghosts = those within the
ghost cut-off (2h + skin) of it (CommBrick::borders). Checked against the runs above,
then evaluated at ~4e6 particles per GPU for 1 to 16 GPUs, where the bytes per step come
from the code (bench/README.md) and the times from the assumptions printed with them.
"""

import argparse
import math
import os
import re
import time

import numpy as np

from . import TOP
from .lammps import Runner

COLUMN = os.path.join(TOP, "examples", "column_collapse", "in.column_collapse")
JET = os.path.join(TOP, "examples", "jet_collision", "in.jet_collision")
# name -> input, variables, warm-up steps, steps, a snapshot every so many steps, and
# optionally the processor grid and a balance of the ranks before the measured run
MEASURES = {
    "column": dict(input=COLUMN, variables={"dx": 0.0031}, warm=0, steps=10, every=10),
    "column-flow": dict(input=COLUMN, variables={"dx": 0.01}, warm=3800, steps=300, every=5),
    "column-flow-x": dict(input=COLUMN, variables={"dx": 0.01}, warm=3800, steps=300, every=5,
                          grid="* 1 1", balance="shift x 20 1.0", ranks=[4]),
    "jet": dict(input=JET, variables={"dx": 0.006}, warm=0, steps=200, every=5),
}

# ---------------------------------------------------------------------------------------
# bytes, from the code (src/GRANSPH and LAMMPS 29Sep2021)
ROW_XV = 6 * 8           # a ghost's x and v each step (comm_modify vel yes: pack_comm_vel)
ROW_STATE = 7 * 8        # FixSPHIntegrate::pack_forward_comm: NCOMM = 7 (rho, sigma)
STATE_COMMS = {"column": 2, "jet": 1}    # PairSPHGranular: one per step, one more after
                         # the walls pass where there are dummy walls (the column's floor)
ROW_BORDER = 9 * 8       # a ghost at a list build: x, tag, type, mask and v (borders)
ROW_EXCHANGE = (1 + 10 + 32) * 8    # an atom that changes rank: its size, AtomVec's x, v,
                         # tag, type, mask, image, and the integrator's 8 + 13 + 11 columns
ROW_FIX = 32 * 8         # the integrator's per-atom arrays (state, rates, start values)
ROW_STATE_ARRAY = 8 * 8  # the state array a host sync copies whole (NSTATE = 8)

# assumptions (bench/README.md names their sources)
RATE = {"column": 1.44e8, "jet": 5.32e7}    # one H200, particle-steps/s (bench/README.md)
PER_GPU = 4.0e6
PCIE = 50e9              # B/s each way, PCIe gen5 x16 (64 GB/s raw)
NET = 50e9               # B/s each way, InfiniBand NDR (400 Gb/s)
LATENCY = 10e-6          # s a message (MPI) or a device-host copy
KERNEL = 5e-6            # s a pack or unpack kernel with its fence (GPU-aware path)
HOST = 5e9               # B/s of one core packing and unpacking the ghosts (host path)


# ---------------------------------------------------------------------------------------
# the lattice model

class Lattice:
    """The particles of an example at spacing dx as create_atoms places them (sc lattice,
    origin 0.5), counted in boxes. parts: (radius, lo, hi): a disc about the axis through
    the origin, in the plane normal to `axis`, extruded from lo to hi along it."""

    def __init__(self, box, axis, parts, dx, cut):
        self.box, self.axis, self.dx, self.cut = box, axis, dx, cut
        self.plane = [d for d in range(3) if d != axis]
        n = int(math.ceil(max(r for r, _, _ in parts) / dx)) + 1
        self.i0 = -n
        self.coords = (np.arange(-n, n) + 0.5) * dx
        u, w = np.meshgrid(self.coords, self.coords, indexing="ij")
        rr = u * u + w * w
        self.parts = []
        for r, lo, hi in parts:
            mask = rr <= r * r
            prefix = np.zeros((2 * n + 1, 2 * n + 1), dtype=np.int64)
            prefix[1:, 1:] = mask.cumsum(0).cumsum(1)
            k = np.arange(math.floor(lo / dx) - 2, math.ceil(hi / dx) + 2)
            layers = (k + 0.5) * dx
            layers = layers[(layers >= lo) & (layers <= hi)]
            self.parts.append((mask, prefix, layers))

    def total(self):
        return int(sum(mask.sum() * len(layers) for mask, _, layers in self.parts))

    def index(self, a):
        """the first grid index whose coordinate is >= a"""
        return int(min(max(math.ceil(a / self.dx - 0.5 - self.i0 - 1e-9), 0), len(self.coords)))

    def count(self, lo, hi):
        """particles with lo <= x < hi in each dimension"""
        (p, q) = self.plane
        a0, a1 = self.index(lo[p]), self.index(hi[p])
        b0, b1 = self.index(lo[q]), self.index(hi[q])
        total = 0
        for _, prefix, layers in self.parts:
            rect = prefix[a1, b1] - prefix[a0, b1] - prefix[a1, b0] + prefix[a0, b0]
            nl = (np.searchsorted(layers, hi[self.axis] - 1e-12 * self.dx) -
                  np.searchsorted(layers, lo[self.axis] - 1e-12 * self.dx))
            total += int(rect) * int(nl)
        return total

    def marginal(self, d):
        """(coordinates, particles) along dimension d"""
        if d == self.axis:
            xs = np.concatenate([layers for _, _, layers in self.parts])
            ws = np.concatenate([np.full(len(layers), mask.sum()) for mask, _, layers in self.parts])
            order = np.argsort(xs, kind="stable")
            return xs[order], ws[order]
        other = 1 if d == self.plane[0] else 0
        ws = sum(mask.sum(axis=other) * len(layers) for mask, _, layers in self.parts)
        return self.coords, ws


def column_lattice(dx, r0=0.2, a=0.5, skin=0.2):
    """examples/column_collapse (its defaults: a = 0.5, r0 = 0.2 m, skin 0.2 dx)"""
    lube = 1.24 * a if a < 1.7 else 1.6 * math.sqrt(a)
    h0 = a * r0
    rfloor = 1.6 * r0 * (1 + lube) + 3 * dx
    box = [(-rfloor, rfloor), (-rfloor, rfloor), (-4 * dx, 1.2 * h0 + 2 * dx)]
    return Lattice(box, 2, [(r0, 0.0, h0), (rfloor, -3 * dx, 0.0)], dx, (2.4 + skin) * dx)


def jet_lattice(dx, R=0.1, L=0.6, k=0.5, skin=0.5):
    """examples/jet_collision (its defaults: k = 0.5, R = 0.1 m, L = 0.6 m, skin 0.5 dx)"""
    box = [(-L - dx, L + dx), (-R, R), (-R, R)]
    return Lattice(box, 0, [(R, -L, 0.0), (k * R, 0.0, L)], dx, (2.4 + skin) * dx)


LATTICES = {"column": column_lattice, "jet": jet_lattice}
BALANCED = {"column": False, "jet": True}    # the inputs: the jet's fix balance shift x


def procgrid(nprocs, box):
    """ProcMap::onelevel_grid and best_factors: the grid of least sub-domain surface"""
    lx, ly, lz = (hi - lo for lo, hi in box)
    area = (lx * ly, lx * lz, ly * lz)
    best, bestsurf = None, 2.0 * sum(area)
    for i in range(1, nprocs + 1):
        if nprocs % i:
            continue
        for j in range(1, nprocs // i + 1):
            if (nprocs // i) % j:
                continue
            f = (i, j, nprocs // i // j)
            surf = area[0] / f[0] / f[1] + area[1] / f[0] / f[2] + area[2] / f[1] / f[2]
            if surf < bestsurf:
                best, bestsurf = f, surf
    return best or (1, 1, 1)


def splits(lattice, grid, balanced):
    """the sub-domain boundaries along each dimension: even, or at equal counts"""
    out = []
    for d in range(3):
        lo, hi = lattice.box[d]
        p = grid[d]
        if p == 1 or not balanced:
            out.append([lo + (hi - lo) * k / p for k in range(p + 1)])
            continue
        xs, ws = lattice.marginal(d)
        cum = np.cumsum(ws)
        cuts = [lo]
        for k in range(1, p):
            j = int(np.searchsorted(cum, cum[-1] * k / p))
            cuts.append(xs[j] + 0.5 * lattice.dx)
        out.append(cuts + [hi])
    return out


def decompose(lattice, nprocs, balanced, grid=None):
    """per rank: (owned, ghosts, messages per forward communication), on LAMMPS' grid or
    the one given"""
    grid = grid or procgrid(nprocs, lattice.box)
    cuts = splits(lattice, grid, balanced)
    ranks = []
    for ix in range(grid[0]):
        for iy in range(grid[1]):
            for iz in range(grid[2]):
                at = (ix, iy, iz)
                lo = [cuts[d][at[d]] for d in range(3)]
                hi = [cuts[d][at[d] + 1] for d in range(3)]
                owned = lattice.count(lo, hi)
                ext_lo = [max(lo[d] - lattice.cut, lattice.box[d][0]) for d in range(3)]
                ext_hi = [min(hi[d] + lattice.cut, lattice.box[d][1]) + 1e-9 for d in range(3)]
                ghosts = lattice.count(ext_lo, ext_hi) - owned
                messages = sum((at[d] > 0) + (at[d] < grid[d] - 1) for d in range(3))
                ranks.append((owned, ghosts, messages))
    return grid, ranks


def spacing_for(case, particles):
    """the spacing at which the example holds about this many particles"""
    lo, hi = 1e-4, 0.05
    for _ in range(40):
        dx = math.sqrt(lo * hi)
        if LATTICES[case](dx).total() > particles:
            lo = dx
        else:
            hi = dx
    return math.sqrt(lo * hi)


# ---------------------------------------------------------------------------------------
# the measurement

SUMMARY = re.compile(r"^(Nlocal|Nghost|FullNghs):\s+(\S+) ave\s+(\S+) max\s+(\S+) min", re.M)


def with_dump(path, workdir, every, grid=None, balance=None):
    """the example's input with a warm-up run, a balance if asked, and a dump of each
    atom's owner before its run of `steps`; the processor grid if asked"""
    lines = open(path).read().splitlines()
    at = next(i for i, l in enumerate(lines) if l.startswith('if "${steps} > 0"'))
    added = ['if "${warm} > 0" then "run ${warm} post no"']
    added += [f"balance 1.0 {balance}"] if balance else []
    added += [f"dump ghosts_owners all custom {every} owners.dump id proc",
              "dump_modify ghosts_owners sort id"]
    lines = lines[:at] + added + lines[at:]
    if grid:
        box = next(i for i, l in enumerate(lines) if l.startswith("create_box"))
        lines.insert(box, f"processors {grid}")
    copy = os.path.join(workdir, os.path.basename(path) + ".owners")
    with open(copy, "w") as f:
        f.write("\n".join(lines) + "\n")
    return copy


def snapshots(path):
    """(step, ids, owners) of each snapshot of a dump of `id proc` sorted by id"""
    out = []
    with open(path) as f:
        while True:
            line = f.readline()
            if not line:
                return out
            step = int(f.readline())
            f.readline()
            n = int(f.readline())
            for _ in range(4):
                f.readline()
            f.readline()    # ITEM: ATOMS id proc
            block = np.array([f.readline() for _ in range(n)], dtype=object)
            values = np.array(" ".join(block).split(), dtype=np.int64).reshape(n, 2)
            out.append((step, values[:, 0], values[:, 1]))


def migrations(path):
    """the atoms whose owner changed between consecutive snapshots, summed, and the steps
    at which some did"""
    snaps = snapshots(path)
    moved, steps = 0, []
    for (_, ids0, own0), (step, ids1, own1) in zip(snaps, snaps[1:]):
        common, i0, i1 = np.intersect1d(ids0, ids1, assume_unique=True, return_indices=True)
        changed = int(np.count_nonzero(own0[i0] != own1[i1]))
        moved += changed
        if changed:
            steps.append(step)
    return moved, steps


def measure(name, ranks, runner):
    config = MEASURES[name]
    variables, warm, steps = config["variables"], config["warm"], config["steps"]
    workdir = runner.workdir(f"{name}-{ranks}")
    copy = with_dump(config["input"], workdir, config["every"], config.get("grid"),
                     config.get("balance"))
    start = time.monotonic()
    runner.run("ghosts", dict(variables, warm=warm, steps=steps), ranks, f"{name}-{ranks}",
               input_file=copy)
    log = open(os.path.join(workdir, "log.lammps")).read()
    summary = {k: tuple(float(v) for v in vals) for k, *vals in SUMMARY.findall(log)}
    builds = int(re.findall(r"Neighbor list builds = (\d+)", log)[-1])
    grid = tuple(int(g) for g in re.findall(r"(\d+) by (\d+) by (\d+) MPI processor grid", log)[-1])
    created = sum(int(n) for n in re.findall(r"^Created (\d+) atoms", log, re.M))
    atoms = int(re.findall(r"Loop time of \S+ on \d+ procs for \d+ steps with (\d+) atoms", log)[-1])
    moved, at_steps = migrations(os.path.join(workdir, "owners.dump"))
    return dict(name=name, ranks=ranks, grid=grid, created=created, atoms=atoms, steps=steps,
                builds=builds, moved=moved, moved_steps=at_steps, wall=time.monotonic() - start,
                **{k: summary[k] for k in summary}, variables=variables)


def stats(values):
    return sum(values) / len(values), max(values), min(values)


def report_measure(m):
    case = "jet" if m["name"] == "jet" else "column"
    lattice = LATTICES[case](m["variables"]["dx"])
    balanced = BALANCED[case] or "balance" in MEASURES[m["name"]]
    grid = procgrid(m["ranks"], lattice.box) if "grid" not in MEASURES[m["name"]] else m["grid"]
    grid, ranks = decompose(lattice, m["ranks"], balanced, grid)
    owned = stats([r[0] for r in ranks])
    ghosts = stats([r[1] for r in ranks])
    nl, ng, nn = m["Nlocal"], m["Nghost"], m["FullNghs"]
    print(f"\n{m['name']} on {m['ranks']} ranks ({m['grid'][0]}x{m['grid'][1]}x{m['grid'][2]}; "
          f"dx {m['variables']['dx']}): {m['atoms']:,} atoms after {m['steps']} steps "
          f"(created {m['created']:,}; lattice model {lattice.total():,}, grid "
          f"{grid[0]}x{grid[1]}x{grid[2]}), {m['wall']:.0f} s")
    print(f"  Nlocal   ave {nl[0]:12,.0f} max {nl[1]:10,.0f} min {nl[2]:10,.0f}   "
          f"model ave {owned[0]:10,.0f} max {owned[1]:10,.0f} min {owned[2]:10,.0f}")
    print(f"  Nghost   ave {ng[0]:12,.0f} max {ng[1]:10,.0f} min {ng[2]:10,.0f}   "
          f"model ave {ghosts[0]:10,.0f} max {ghosts[1]:10,.0f} min {ghosts[2]:10,.0f}")
    print(f"  ghosts per owned particle {ng[0] / nl[0]:.4f} (max rank {ng[1] / nl[0]:.4f}); "
          f"neighbours per owned particle {nn[0] / nl[0]:.1f}")
    per_build = m["moved"] / m["builds"] / m["ranks"] if m["builds"] else 0.0
    print(f"  list builds {m['builds']} in {m['steps']} steps; atoms that changed rank "
          f"{m['moved']:,} (at steps {m['moved_steps'][:12]}{' ...' if len(m['moved_steps']) > 12 else ''}): "
          f"{per_build:,.0f} per build and rank, {per_build / ng[0] if ng[0] else 0:.4f} of its ghosts")
    return dict(case=case, ghost_ratio=ng[0] / nl[0],
                moved_per_ghost=per_build / ng[0] if ng[0] else 0.0,
                builds_per_step=m["builds"] / m["steps"])


# ---------------------------------------------------------------------------------------
# the estimate

def host_pack_rate():
    """bytes per second of a gather of 6-double rows by a sorted index list and its
    copy into a contiguous block, numpy on this CPU: a look at what HOST assumes for
    LAMMPS' host pack and unpack of the ghosts"""
    rng = np.random.default_rng(1)
    rows = np.zeros((2_000_000, 6))
    index = np.sort(rng.choice(len(rows), 200_000, replace=False))
    best = float("inf")
    for _ in range(5):
        start = time.perf_counter()
        buf = rows[index]
        rows[1_700_000:1_900_000] = buf
        best = min(best, time.perf_counter() - start)
    return 2 * buf.nbytes / best


def traffic(case, owned, ghosts, messages, nprocs, flow):
    """one rank's communication in a step, from the code: bytes and messages (per step,
    a list build's share included)"""
    comms = STATE_COMMS[case]
    nall = owned + ghosts
    builds = flow["builds_per_step"]
    row = ROW_XV + comms * ROW_STATE                   # a ghost's bytes each step
    mpi = (ghosts * row + builds * ghosts * (ROW_BORDER - ROW_XV) +
           builds * flow["moved_per_ghost"] * ghosts * ROW_EXCHANGE)
    fix_staging = builds * 2 * ROW_FIX * nall          # pack_exchange, unpack_exchange
    return dict(
        mpi=mpi,
        messages=messages * (1 + comms) + builds * messages * 3 +    # exchange, borders
        (2 * math.ceil(math.log2(nprocs)) if nprocs > 1 else 0),     # CFL step, list check
        # the host path: the whole x, v and state arrays to the host and back
        pcie_host=2 * (ROW_XV + comms * ROW_STATE_ARRAY) * nall + fix_staging,
        copies=4 + 2 * comms,
        pcie_aware=fix_staging,
        host_pack=2 * ghosts * row + builds * 2 * ghosts * ROW_BORDER,
        kernels=2 * messages * (1 + comms))


def seconds(t, host):
    """((PCIe, the rest) on the host path, the same on the GPU-aware path) in s"""
    common = t["mpi"] / NET + t["messages"] * LATENCY
    return ((t["pcie_host"] / PCIE, common + t["copies"] * LATENCY + t["host_pack"] / host),
            (t["pcie_aware"] / PCIE, common + t["kernels"] * KERNEL))


def estimate(flows, host):
    print(f"\nestimate: ~{PER_GPU:.0e} particles per GPU; PCIe {PCIE / 1e9:.0f} GB/s, network "
          f"{NET / 1e9:.0f} GB/s, {LATENCY * 1e6:.0f} us a message or copy, {KERNEL * 1e6:.0f} us "
          f"a pack kernel, host pack/unpack {host / 1e9:.1f} GB/s (a numpy gather and copy of "
          f"6-double rows here: {host_pack_rate() / 1e9:.1f} GB/s)")
    rows = []
    for case in ("column", "jet"):
        flow = flows[case]
        print(f"\n{case}: {RATE[case]:.3g} particle-steps/s on one GPU; list builds per step "
              f"{flow['builds_per_step']:.3f}, atoms changing rank per build "
              f"{flow['moved_per_ghost']:.4f} of a rank's ghosts (measured)")
        print("  GPUs grid   dx mm  particles/GPU  ghosts/GPU ghost%  imbalance  MPI MB "
              "PCIe MB  compute ms  comm ms host aware  efficiency host aware")
        for nprocs in (1, 2, 4, 8, 16):
            dx = spacing_for(case, PER_GPU * nprocs)
            lattice = LATTICES[case](dx)
            grid, ranks = decompose(lattice, nprocs, True)
            _, even = decompose(lattice, nprocs, False)
            total = lattice.total()
            ideal = total / nprocs / RATE[case]
            worst = None
            for owned, ghosts, messages in ranks:
                t = traffic(case, owned, ghosts, messages, nprocs, flow)
                (hl, hr), (al, ar) = seconds(t, host) if nprocs > 1 else ((0, 0), (0, 0))
                times = (owned / RATE[case] + hl + hr, owned / RATE[case] + al + ar)
                if worst is None or times[0] > worst[0][0]:
                    worst = (times, owned, ghosts, t, hl + hr, al + ar)
            (th, ta), owned, ghosts, t, host_s, aware_s = worst
            if nprocs == 1:
                t = dict(t, mpi=0, pcie_host=0)
            imbalance = (max(r[0] for r in even) / (total / nprocs),
                         max(r[0] for r in ranks) / (total / nprocs))
            rows.append(dict(case=case, gpus=nprocs, grid=grid, dx=dx, total=total, owned=owned,
                             ghosts=ghosts, imbalance=imbalance, traffic=t, compute=ideal,
                             comm=(host_s, aware_s), eff=(ideal / th, ideal / ta)))
            print(f"  {nprocs:4d} {grid[0]}x{grid[1]}x{grid[2]:<3d} {dx * 1e3:5.3f} {owned:14,d} "
                  f"{ghosts:11,d} {100 * ghosts / owned:5.1f}  {imbalance[0]:4.2f} {imbalance[1]:4.2f}"
                  f" {t['mpi'] / 1e6:7.1f} {t['pcie_host'] / 1e6:7.0f}  {ideal * 1e3:9.1f}  "
                  f"{host_s * 1e3:8.1f} {aware_s * 1e3:5.2f}  {ideal / th:10.2f} {ideal / ta:5.2f}")
    print("\n(the slowest rank, sub-domains split at equal counts along each split axis; "
          "imbalance: the most particles a rank holds over the mean, with the grid split evenly "
          "(the column's input) and at equal counts; PCIe MB: the host path's, both ways; "
          "efficiency: the mean rank's compute time over the slowest rank's compute and "
          "communication)")
    return rows


def shared_gpu(flows, host):
    """the prediction for two ranks on one GPU (gpu-check's ranks stage): the compute of
    all particles, both ranks' copies over the one PCIe link, the rest side by side"""
    print("\ntwo ranks on one GPU, against one rank (the same assumptions; the inputs' own "
          "decomposition):")
    for case, dx in (("column", 0.00163), ("column", 0.00271), ("jet", 0.006)):
        lattice = LATTICES[case](dx)
        total = lattice.total()
        _, ranks = decompose(lattice, 2, BALANCED[case])
        one = total / RATE[case]
        times = [seconds(traffic(case, o, g, m, 2, flows[case]), host) for o, g, m in ranks]
        host_path = one + sum(h[0][0] for h in times) + max(h[0][1] for h in times)
        aware = one + sum(h[1][0] for h in times) + max(h[1][1] for h in times)
        print(f"  {case} at dx {dx} ({total:,} particles, ghosts {ranks[0][1]:,} and "
              f"{ranks[1][1]:,}): 1 rank {one * 1e3:.1f} ms a step, 2 ranks {host_path * 1e3:.1f} ms "
              f"on the host path ({one / host_path:.2f}), {aware * 1e3:.1f} ms GPU-aware "
              f"({one / aware:.2f})")


def main():
    global PCIE, NET, LATENCY
    parser = argparse.ArgumentParser(prog="bench/ghosts.py", description=__doc__.split("\n")[0])
    parser.add_argument("--case", action="append", choices=list(MEASURES))
    parser.add_argument("--ranks", action="append", type=int, choices=[2, 3, 4])
    parser.add_argument("--out", default="/tmp/gransph-ghosts")
    parser.add_argument("--estimate-only", action="store_true",
                        help="no runs: the measured flow figures of bench/README.md")
    parser.add_argument("--pcie", type=float, default=PCIE / 1e9, help="GB/s each way")
    parser.add_argument("--net", type=float, default=NET / 1e9, help="GB/s each way")
    parser.add_argument("--latency", type=float, default=LATENCY * 1e6,
                        help="us a message or a device-host copy")
    parser.add_argument("--host", type=float, default=HOST / 1e9,
                        help="GB/s of the host pack and unpack of ghosts")
    opts = parser.parse_args()
    PCIE, NET, LATENCY = opts.pcie * 1e9, opts.net * 1e9, opts.latency * 1e-6
    # measured with this script (bench/README.md): the flows' list builds per step and the
    # atoms that change rank per build, as a fraction of a rank's ghosts (column-flow-x and
    # jet on 4 ranks)
    flows = {"column": dict(builds_per_step=4 / 300, moved_per_ghost=0.0021),
             "jet": dict(builds_per_step=22 / 200, moved_per_ghost=0.0382)}
    if not opts.estimate_only:
        os.nice(10)    # counts, not timings: leave the machine to the others
        os.environ.setdefault("OMPI_MCA_rmaps_base_oversubscribe", "1")
        os.environ.setdefault("OMP_NUM_THREADS", "1")
        runner = Runner(opts.out, say="[ghosts]")
        runner.command = lambda *a, **k: oversubscribed(Runner.command(runner, *a, **k))
        measured = {}
        for name in opts.case or list(MEASURES):
            for ranks in opts.ranks or MEASURES[name].get("ranks", [2, 4]):
                measured[(name, ranks)] = report_measure(measure(name, ranks, runner))
        for case, name in (("column", "column-flow-x"), ("jet", "jet")):
            got = [v for (n, _), v in sorted(measured.items()) if n == name]
            if got:    # the most ranks measured
                flows[case] = dict(builds_per_step=got[-1]["builds_per_step"],
                                   moved_per_ghost=got[-1]["moved_per_ghost"])
    estimate(flows, opts.host * 1e9)
    shared_gpu(flows, opts.host * 1e9)


def oversubscribed(cmd):
    """mpirun may place more ranks than cores: counts need no core of their own"""
    return cmd[:1] + ["--oversubscribe"] + cmd[1:] if cmd[0] == "mpirun" else cmd


if __name__ == "__main__":
    main()
