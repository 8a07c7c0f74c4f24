# SPDX-License-Identifier: GPL-2.0-only (GRANSPH: LICENSE)
"""Linear stability of a sand layer at rest on a GRANSPH dummy floor.

  tools/research/wall-stability [--layers 1] [--columns 8] [--rows 1] [--theta 20] [--dx 0.02]
                       [--wall-stress ratio|paper] [--material Chen2019]
                       [--design adjoint frozen slow] [--tau 0.01]
  tools/research/wall-stability --table validation/wall_stability/wall_stability.md

A layer of `layers` grains on three layers of dummies, periodic along the slope over
`columns` grains and across it over `rows` (1: modes uniform across the slope), gravity
tilted by theta. The rates are those of pair_style sph/granular with its defaults and an
elastic grain (the layer below yield): Wendland C2 at h = 1.2 dx, full neighbour sums
with sigma_i + sigma_j (eq. 6b), the plain velocity gradient, the Jaumann rate with
Hooke's law, dummies at rest whose stress is eq. 8 under wall/stress ratio or paper
(gransph_pair_terms.h, WallSums).
The equilibrium is the uniform stress per grain layer that balances gravity in these sums;
the eigenvalues of the Jacobian of the rates there (central differences) are the modes'
growth rates (real part) and frequencies, in continuous time: any positive real part is an
instability of the discrete equations, whatever the integrator. Printed: the equilibrium,
the largest growth rate, its frequency, and the growth per step at the CFL step of cfl 0.2.

--design adds what the styles do not do, to try a wall before building it:
  frozen   the ratio wall's growth s = q / |sigma_nn| held at its equilibrium value (the
           wall's stress follows the grains' with a fixed weight)
  slow     s from each dummy's sigma_nn relaxed towards the grains' with the time
           constant --tau (a state of the dummy), rather than from the grains' at once
  adjoint  each grain's velocity gradient takes the adjoint of the wall stress's
           dependence on the grains' stress: for every dummy d whose extrapolation holds
           grain k with Shepard weight w_dk, L_k += w_dk M_d(L_d), with L_d the dummy's
           SPH velocity gradient from its grains and M_d(X) = (1 + s) X - s (n.X.n) n n the
           wall's linear response; so that the work of the wall stress on the grains is
           the elastic power of the grains' stress (the grain-grain sums are so already).

The artificial viscosity is left out (it acts on approaching pairs only, and is not
linear at rest). Analysis only: numpy, no LAMMPS.
"""

import argparse
import os
import sys

import numpy as np

from . import TOP


def read_material(name):
    """rho0, E, nu of material `name` in potentials/sand.gransph"""
    with open(os.path.join(TOP, "potentials", "sand.gransph")) as f:
        for line in f:
            words = line.split("#")[0].split()
            if words and words[0] == name:
                return float(words[1]), float(words[2]), float(words[3])
    sys.exit(f"wall-stability: no material {name} in potentials/sand.gransph")


def sym(s):
    """xx yy zz xy xz yz -> 3x3"""
    return np.array([[s[0], s[3], s[4]], [s[3], s[1], s[5]], [s[4], s[5], s[2]]])


def voigt(m):
    return np.array([m[0, 0], m[1, 1], m[2, 2], m[0, 1], m[0, 2], m[1, 2]])


class Layer:
    """The grains, the dummies, their pairs and the SPH rates of the layer."""

    def __init__(self, layers, columns, theta, dx, wall_stress, material, design, tau=0.01,
                 rows=1):
        self.dx, self.h = dx, 1.2 * dx
        self.rho0, E, nu = read_material(material)
        self.G, self.K = E / (2 * (1 + nu)), E / (3 * (1 - 2 * nu))
        self.c = np.sqrt(E / self.rho0)
        self.volume = dx ** 3
        self.mass = self.rho0 * self.volume
        self.wall_stress, self.design = wall_stress, set(design)
        t = np.radians(theta)
        self.g = 9.81 * np.array([np.sin(t), 0.0, -np.cos(t)])
        self.layers, self.columns, self.rows = layers, columns, rows
        self.per_layer = columns * rows
        self.grains = np.array([[(i + 0.5) * dx, (j + 0.5) * dx, (l + 0.5) * dx]
                                for l in range(layers) for j in range(rows)
                                for i in range(columns)])
        self.dummies = np.array([[(i + 0.5) * dx, (j + 0.5) * dx, -(k + 0.5) * dx]
                                 for k in range(3) for j in range(rows) for i in range(columns)])
        self.n = len(self.grains)
        # pairs within the support, with the image offset of the second particle
        self.gg = self.pairs(self.grains, self.grains)
        self.gd = self.pairs(self.grains, self.dummies)
        self.dg = self.pairs(self.dummies, self.grains)
        self.frozen_growth = None
        self.tau = tau
        self.slow = "slow" in self.design

    def pairs(self, a, b):
        out = []
        length, width = self.columns * self.dx, self.rows * self.dx
        for i, xa in enumerate(a):
            for j, xb in enumerate(b):
                for ix in (-1, 0, 1):
                    for iy in range(-3, 4):
                        off = np.array([ix * length, iy * width, 0.0])
                        r = xa - xb - off
                        if 0.0 < np.linalg.norm(r) < 2 * self.h:
                            out.append((i, j, off))
        return out

    def kernel(self, r):
        """W and grad W at separation r (Wendland C2, 3d)"""
        d = np.linalg.norm(r)
        q = d / self.h
        a = 21.0 / (16.0 * np.pi * self.h ** 3)
        if q >= 2.0:
            return 0.0, np.zeros(3)
        return a * (1 - q / 2) ** 4 * (2 * q + 1), a * (-5 * q * (1 - q / 2) ** 3) / self.h * r / d

    def wall(self, x, sigma, v, slow_nn=None):
        """each dummy's stress (eq. 8), its growth s, normal, Shepard weights of its
        grains, its SPH velocity gradient from them, and the grains' sigma_nn there
        (slow_nn: the dummies' relaxed sigma_nn of the slow design)"""
        out = []
        sums = [dict(w=0.0, s=np.zeros((3, 3)), r=np.zeros(3), grains={}, L=np.zeros((3, 3)))
                for _ in self.dummies]
        for d, k, off in self.dg:
            r = self.dummies[d] - (x[k] + off)
            w, _ = self.kernel(r)
            _, grad_k = self.kernel(-r)    # grad_k W_kd
            e = sums[d]
            e["w"] += w
            e["s"] += w * sigma[k]
            e["r"] += self.rho0 * w * r
            e["grains"][k] = e["grains"].get(k, 0.0) + w
            e["L"] += -self.volume * np.outer(v[k], grad_k)
        for d, e in enumerate(sums):
            if e["w"] == 0.0:
                out.append((np.zeros((3, 3)), 0.0, np.zeros(3), {}, e["L"], 0.0))
                continue
            s_e, big_r = e["s"] / e["w"], e["r"] / e["w"]
            n = big_r / np.linalg.norm(big_r)
            nn = np.outer(n, n)
            s_nn = n @ s_e @ n
            weights = {k: w / e["w"] for k, w in e["grains"].items()}
            if self.wall_stress == "paper":
                out.append((s_e - np.diag(self.g * big_r), 0.0, n, weights, e["L"], s_nn))
                continue
            q = max(self.g @ big_r, min(s_nn, 0.0))
            base = max(-(s_nn if slow_nn is None else slow_nn[d]), abs(q) / 4.0)
            growth = q / base if base > 0.0 else 0.0
            if self.frozen_growth is not None:
                growth = self.frozen_growth[d]
            out.append((s_e + growth * (s_e - s_nn * nn) - q * nn, growth, n, weights, e["L"],
                        s_nn))
        return out

    def rates(self, y):
        n = self.n
        u, v = y[:3 * n].reshape(n, 3), y[3 * n:6 * n].reshape(n, 3)
        sigma = np.array([sym(s) for s in y[6 * n:12 * n].reshape(n, 6)])
        slow_nn = y[12 * n:] if self.slow else None
        x = self.grains + u
        walls = self.wall(x, sigma, v, slow_nn)
        acc = np.tile(self.g, (n, 1))
        grad_v = np.zeros((n, 3, 3))
        per_pair = self.mass / self.rho0 ** 2
        for i, j, off in self.gg:
            _, gw = self.kernel(x[i] - x[j] - off)
            acc[i] += per_pair * (sigma[i] + sigma[j]) @ gw
            grad_v[i] += -self.volume * np.outer(v[i] - v[j], gw)
        for i, d, off in self.gd:
            _, gw = self.kernel(x[i] - self.dummies[d] - off)
            acc[i] += per_pair * (sigma[i] + walls[d][0]) @ gw
            grad_v[i] += -self.volume * np.outer(v[i], gw)
        if "adjoint" in self.design:
            for s_d, growth, nd, weights, big_l, _ in walls:
                response = (1 + growth) * big_l - growth * (nd @ big_l @ nd) * np.outer(nd, nd)
                for k, w in weights.items():
                    grad_v[k] += w * response
        dsigma = np.zeros((n, 6))
        for i in range(n):
            d = 0.5 * (grad_v[i] + grad_v[i].T)
            spin = 0.5 * (grad_v[i] - grad_v[i].T)
            tr = np.trace(d)
            rate = (2 * self.G * (d - tr / 3 * np.eye(3)) + self.K * tr * np.eye(3)
                    + sigma[i] @ spin.T + spin @ sigma[i])
            dsigma[i] = voigt(rate)
        rates = [v.ravel(), acc.ravel(), dsigma.ravel()]
        if self.slow:
            rates.append((np.array([w[5] for w in walls]) - slow_nn) / self.tau)
        return np.concatenate(rates)

    def state(self, layer_stress):
        """rest, each grain layer at its (sigma_zz, sigma_xz), sigma_xx = sigma_yy = K0 sigma_zz"""
        k0 = (1.5 * self.K - self.G) / (1.5 * self.K + 2 * self.G)    # nu / (1 - nu)
        sig = np.zeros((self.n, 6))
        for l in range(self.layers):
            szz, sxz = layer_stress[2 * l], layer_stress[2 * l + 1]
            sig[l * self.per_layer:(l + 1) * self.per_layer] = [k0 * szz, k0 * szz, szz, 0, sxz, 0]
        y = np.concatenate([np.zeros(6 * self.n), sig.ravel()])
        if self.slow:    # the dummies' relaxed sigma_nn at rest: the grains'
            walls = self.wall(self.grains, np.array([sym(r) for r in sig]), np.zeros((self.n, 3)))
            y = np.concatenate([y, [w[5] for w in walls]])
        return y

    def equilibrium(self):
        """the uniform stress per grain layer at which the grains do not accelerate"""
        def residual(p):
            a = self.rates(self.state(p))[3 * self.n:6 * self.n].reshape(self.n, 3)
            return np.array([c for l in range(self.layers)
                             for c in (a[l * self.per_layer, 2], a[l * self.per_layer, 0])])
        weight = self.rho0 * self.dx
        p = np.array([c for l in range(self.layers)
                      for c in (self.g[2] * weight * (self.layers - l - 0.5),
                                -self.g[0] * weight * (self.layers - l - 0.5))])
        for _ in range(8):
            r = residual(p)
            jac = np.zeros((len(p), len(p)))
            for c in range(len(p)):
                e = np.zeros(len(p))
                e[c] = 1e-3 * max(1.0, abs(p[c]))
                jac[:, c] = (residual(p + e) - r) / e[c]
            p = p - np.linalg.solve(jac, r)
        if "frozen" in self.design:    # s from here on: its value at rest
            rest = self.state(p)[6 * self.n:12 * self.n].reshape(self.n, 6)
            sigma = np.array([sym(r) for r in rest])
            walls = self.wall(self.grains, sigma, np.zeros((self.n, 3)))
            self.frozen_growth = [w[1] for w in walls]
        return p

    def modes(self, layer_stress):
        """eigenvalues of the rates' Jacobian at the equilibrium, largest growth first"""
        y0 = self.state(layer_stress)
        scale = np.concatenate([np.full(3 * self.n, 1e-9), np.full(3 * self.n, 1e-7),
                                np.full(len(y0) - 6 * self.n, 1e-3)])
        jac = np.zeros((len(y0), len(y0)))
        for c in range(len(y0)):
            e = np.zeros(len(y0))
            e[c] = scale[c]
            jac[:, c] = (self.rates(y0 + e) - self.rates(y0 - e)) / (2 * scale[c])
        lam = np.linalg.eigvals(jac)
        return lam[np.argsort(-lam.real)]

    def cfl_step(self, cfl=0.2):
        return cfl * self.h / self.c


def analyse(args):
    layer = Layer(args.layers, args.columns, args.theta, args.dx, args.wall_stress,
                  args.material, args.design, getattr(args, "tau", 0.01), getattr(args, "rows", 1))
    p = layer.equilibrium()
    lam = layer.modes(p)[0]
    return p, lam, layer.cfl_step()


TABLE = [  # (layers, columns, theta, wall stress, design): what validation/wall_stability/wall_stability.md shows
    (1, 8, 0, "paper", ()), (1, 8, 20, "paper", ()),
    (1, 8, 0, "ratio", ()), (1, 8, 20, "ratio", ()), (1, 16, 28.1, "ratio", ()),
    (2, 8, 0, "ratio", ()), (2, 8, 20, "ratio", ()),
    (1, 8, 0, "ratio", ("adjoint",)), (1, 8, 20, "ratio", ("adjoint",)),
    (1, 8, 20, "ratio", ("frozen",)),
    (1, 8, 0, "ratio", ("adjoint", "frozen")), (1, 8, 20, "ratio", ("adjoint", "frozen")),
    (1, 16, 28.1, "ratio", ("adjoint", "frozen")),
    (2, 8, 0, "ratio", ("adjoint", "frozen")), (2, 8, 20, "ratio", ("adjoint", "frozen")),
    (1, 8, 20, "ratio", ("adjoint", "slow")), (1, 16, 28.1, "ratio", ("adjoint", "slow")),
]
TABLE_TAU = 0.05    # s, the slow design's time constant in the table


def write_table(path, material, dx):
    rows = []
    for layers, columns, theta, wall_stress, design in TABLE:
        args = argparse.Namespace(layers=layers, columns=columns, theta=theta, dx=dx,
                                  wall_stress=wall_stress, material=material, design=design,
                                  tau=TABLE_TAU)
        p, lam, dt = analyse(args)
        rows.append(f"| {wall_stress} | {' '.join(design) or '-'} | {layers} | {columns} | "
                    f"{theta:g} | {p[0]:.1f} | {p[1]:.1f} | {lam.real:.3g} | "
                    f"{abs(lam.imag):.0f} | {lam.real * dt:.2e} |")
        print(rows[-1], flush=True)
    with open(path, "w") as f:
        f.write(f"""# Linear stability of a layer at rest on a dummy floor

Written by `tools/research/wall-stability --table {os.path.relpath(path, TOP)}` ({material}, dx = {dx} m,
elastic grains, no artificial viscosity; see the tool's help for the model). Each row: the
wall's stress rule, the design options tried (`-`: the styles as they are), the layer, the
slope, the base grain layer's equilibrium sigma_zz and sigma_xz (Pa), and the fastest-growing
mode: its growth rate (1/s, positive = unstable), its angular frequency (rad/s) and its
growth per step at cfl 0.2 (dt = {analyse_dt(material, dx):.3g} s). The slow design's
time constant: {TABLE_TAU} s. Modes across the slope (`--rows`) add none: 8 x 4 grains
gives the rows of 8 x 1 (ratio 227 and 295 1/s level and at 20 degrees, adjoint frozen
neutral), 4 x 4 is neutral level.

| wall/stress | design | layers | columns | theta (deg) | sigma_zz | sigma_xz | growth (1/s) | omega (rad/s) | growth per step |
|---|---|---|---|---|---|---|---|---|---|
""")
        f.write("\n".join(rows) + "\n")


def analyse_dt(material, dx):
    rho0, E, _ = read_material(material)
    return 0.2 * 1.2 * dx / np.sqrt(E / rho0)


def main():
    parser = argparse.ArgumentParser(prog="wall-stability", description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--layers", type=int, default=1)
    parser.add_argument("--columns", type=int, default=8)
    parser.add_argument("--rows", type=int, default=1,
                        help="grains across the slope (1: modes uniform across it)")
    parser.add_argument("--theta", type=float, default=20.0, help="slope (degrees)")
    parser.add_argument("--dx", type=float, default=0.02)
    parser.add_argument("--wall-stress", choices=("ratio", "paper"), default="ratio")
    parser.add_argument("--material", default="Chen2019")
    parser.add_argument("--design", nargs="*", choices=("adjoint", "frozen", "slow"), default=[])
    parser.add_argument("--tau", type=float, default=0.01,
                        help="time constant of the slow design (s, default 0.01)")
    parser.add_argument("--table", metavar="OUT.md")
    args = parser.parse_args()
    if args.layers < 1 or args.columns < 3:
        parser.error("--layers must be at least 1 and --columns at least 3")
    if args.table:
        write_table(args.table, args.material, args.dx)
        return
    p, lam, dt = analyse(args)
    for l in range(args.layers):
        print(f"equilibrium, grain layer {l + 1}: sigma_zz {p[2 * l]:.2f} Pa, "
              f"sigma_xz {p[2 * l + 1]:.2f} Pa (ratio {p[2 * l + 1] / -p[2 * l]:.4f}, "
              f"tan theta {np.tan(np.radians(args.theta)):.4f})")
    print(f"fastest mode: growth {lam.real:.4g} 1/s, omega {abs(lam.imag):.4g} rad/s; "
          f"growth per step at cfl 0.2 (dt {dt:.3g} s): {lam.real * dt:.3g}")


if __name__ == "__main__":
    main()
