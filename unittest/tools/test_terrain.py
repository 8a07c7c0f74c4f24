#!/usr/bin/python3
# SPDX-License-Identifier: GPL-2.0-only (GRANSPH: LICENSE)
"""tools/terrain: dummy layers beneath a terrain surface (its module gransph.terrain, and the
command line through the launcher).

  PYTHONPATH=tools/lib /usr/bin/python3 unittest/tools/test_terrain.py                 # everything
  PYTHONPATH=tools/lib /usr/bin/python3 unittest/tools/test_terrain.py TestLammpsRead  # LAMMPS reads the normals

Every check runs or fails: a missing reader (python3-gdal, python3-stl) or a missing LAMMPS
is an error here, not a skip. TestLammpsRead needs neither reader (it builds its surface
from numpy).
"""
import math
import os
import subprocess
import sys
import tempfile
import unittest
import warnings

import numpy as np

from gransph import terrain

TOP = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
TOOL = os.path.join(TOP, "tools", "terrain")
LMP = os.path.join(TOP, "tools", "lmp")


def run_tool(*args):
    p = subprocess.run([TOOL] + [str(a) for a in args], capture_output=True, text=True)
    return p.returncode, p.stdout, p.stderr


def read_data(path):
    """Atoms of a data file the tool wrote and WallNormals of the normals file beside it:
    ids, types, x (n,3), normals (n,3) in id order, and the box."""
    sections, cur, box = {}, None, {}
    with open(path) as f:
        lines = f.read().split("\n")[1:]
    with open(terrain.normals_path(path)) as f:
        lines += f.read().split("\n")
    for line in lines:
        s = line.split("#")[0].strip()
        if not s:
            continue
        w = s.split()
        if len(w) == 4 and w[2].endswith("lo") and w[3].endswith("hi"):
            box[w[2][0]] = (float(w[0]), float(w[1]))
        elif w[0] in ("Atoms", "WallNormals"):
            cur = sections.setdefault(w[0], [])
        elif cur is not None:
            cur.append([float(v) for v in w])
    A = np.array(sections["Atoms"])
    N = np.array(sections["WallNormals"])
    A = A[np.argsort(A[:, 0])]
    N = N[np.argsort(N[:, 0])]
    assert (A[:, 0] == N[:, 0]).all()
    return A[:, 0].astype(int), A[:, 1].astype(int), A[:, 2:5], N[:, 1:4], box


def nearest(X):
    """Distance from each point to its nearest other point (brute force, small sets)."""
    out = np.empty(len(X))
    for s in range(0, len(X), 500):
        d = np.linalg.norm(X[s:s + 500, None, :] - X[None, :, :], axis=2)
        d[np.arange(d.shape[0]), np.arange(s, s + d.shape[0])] = np.inf
        out[s:s + 500] = d.min(axis=1)
    return out


def write_asc(path, text):
    with open(path, "w") as f:
        f.write(text)


def make_stl(path, tris, mode="binary"):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        import stl
        from stl import mesh
    m = mesh.Mesh(np.zeros(len(tris), dtype=mesh.Mesh.dtype))
    m.vectors[:] = tris
    m.update_normals()
    m.save(path, mode=stl.Mode.BINARY if mode == "binary" else stl.Mode.ASCII)


def sphere_cap(c, R, rplan, h):
    """Triangles of the sphere |p - c| = R above a plan-view disk of radius rplan, from a
    square grid of spacing h mapped up onto the sphere, wound counter-clockwise from above."""
    n = int(math.ceil(rplan / h))
    g = np.arange(-n, n + 1) * h
    X, Y = np.meshgrid(g, g)
    inside = X ** 2 + Y ** 2 <= rplan ** 2
    Z = c[2] + np.sqrt(np.maximum(R ** 2 - (X - c[0]) ** 2 - (Y - c[1]) ** 2, 0))
    P = np.stack([X, Y, Z], axis=-1)
    tris = []
    for i in range(len(g) - 1):
        for j in range(len(g) - 1):
            a, b, cc, d = (i, j), (i, j + 1), (i + 1, j + 1), (i + 1, j)
            for t in ((a, b, cc), (a, cc, d)):
                if all(inside[v] for v in t):
                    tris.append([P[v] for v in t])
    return np.array(tris)


class TmpDir(unittest.TestCase):
    def setUp(self):
        self._tmp = tempfile.TemporaryDirectory(prefix="gransph_terrain_")
        self.tmp = self._tmp.name

    def tearDown(self):
        self._tmp.cleanup()

    def path(self, name):
        return os.path.join(self.tmp, name)

    def assertFailsClearly(self, args, *words):
        rc, out, err = run_tool(*args)
        self.assertNotEqual(rc, 0, "tools/terrain %s succeeded: %s" % (" ".join(map(str, args)), out))
        self.assertNotIn("Traceback", err)
        self.assertIn("tools/terrain: error:", err)
        for w in words:
            self.assertIn(w, err)
        return err


class TestPlaneGrid(TmpDir):
    """A plane tilted in x and y, written as a grid by `tools/terrain grid`."""
    a, b, dx = 0.45, -0.25, 0.02

    def test_normals_and_depths(self):
        asc, data = self.path("plane.asc"), self.path("plane.data")
        rc, out, err = run_tool("grid", "--function", "0.1 + %r*x + %r*y" % (self.a, self.b),
                                "--xlim", 0, 0.6, "--ylim", 0, 0.4, "--cell", 0.01, asc)
        self.assertEqual(rc, 0, err)
        rc, out, err = run_tool("layers", asc, data, "--dx", self.dx, "--height", 0.3,
                                "--xlim", 0.05, 0.55, "--ylim", 0.05, 0.35)
        self.assertEqual(rc, 0, err)
        ids, types, X, N, box = read_data(data)
        self.assertTrue((types == 2).all())
        self.assertEqual(list(ids), list(range(1, len(ids) + 1)))
        n = np.array([-self.a, -self.b, 1.0]) / math.sqrt(1 + self.a ** 2 + self.b ** 2)
        # normals exact (to the grid's 15 significant digits)
        self.assertLess(np.abs(N - n).max(), 1e-9)
        # each particle at depth (k + 1/2) dx beneath the plane, k = 0, 1, 2, in equal numbers
        depth = -((X - [0, 0, 0.1]) @ n) / self.dx - 0.5
        k = np.rint(depth)
        self.assertLess(np.abs(depth - k).max(), 1e-9)
        self.assertEqual(sorted(set(k.astype(int))), [0, 1, 2])
        counts = [int((k == i).sum()) for i in range(3)]
        self.assertEqual(counts[0], counts[1])
        self.assertEqual(counts[0], counts[2])
        # the layers are copies of one another along the normal (ids layer by layer)
        m = counts[0]
        self.assertLess(np.abs(X[m:2 * m] - (X[:m] - self.dx * n)).max(), 1e-12)
        # about one particle per dx^2 of surface: the region's area along the plane
        area = 0.5 * 0.3 * math.sqrt(1 + self.a ** 2 + self.b ** 2)
        self.assertLess(abs(counts[0] * self.dx ** 2 / area - 1), 0.05)
        # surface points in the plan-view region, the box holds the particles and the room
        S = X[:m] + 0.5 * self.dx * n
        self.assertGreaterEqual(S[:, 0].min(), 0.05 - 1e-12)
        self.assertLessEqual(S[:, 0].max(), 0.55 + 1e-12)
        self.assertGreaterEqual(S[:, 1].min(), 0.05 - 1e-12)
        self.assertLessEqual(S[:, 1].max(), 0.35 + 1e-12)
        for i, ax in enumerate("xyz"):
            self.assertLessEqual(box[ax][0], X[:, i].min())
            self.assertGreaterEqual(box[ax][1], X[:, i].max())
        self.assertAlmostEqual(box["z"][1], S[:, 2].max() + 0.3, places=9)

    def test_geotiff(self):
        """The same reader takes a GeoTIFF."""
        tif, data = self.path("plane.tif"), self.path("plane.data")
        rc, out, err = run_tool("grid", "--function", "%r*x" % self.a, "--xlim", 0, 0.2,
                                "--ylim", 0, 0.1, "--cell", 0.01, tif)
        self.assertEqual(rc, 0, err)
        rc, out, err = run_tool("layers", tif, data, "--dx", self.dx, "--layers", 4)
        self.assertEqual(rc, 0, err)
        ids, types, X, N, box = read_data(data)
        n = np.array([-self.a, 0, 1]) / math.sqrt(1 + self.a ** 2)
        self.assertLess(np.abs(N - n).max(), 1e-9)
        depth = -(X @ n) / self.dx - 0.5
        self.assertEqual(sorted(set(np.rint(depth).astype(int))), [0, 1, 2, 3])
        self.assertLess(np.abs(depth - np.rint(depth)).max(), 1e-9)


class TestSteepSlope(TmpDir):
    """A 60-degree slope: the surface is sampled about dx apart along the slope, where a
    plan-view lattice would leave 2 dx between rows."""
    dx = 0.02

    def test_spacing_along_the_slope(self):
        asc, data = self.path("steep.asc"), self.path("steep.data")
        t = math.tan(math.radians(60))
        rc, out, err = run_tool("grid", "--function", "%r*x" % t, "--xlim", 0, 0.5, "--ylim",
                                0, 0.3, "--cell", 0.01, asc)
        self.assertEqual(rc, 0, err)
        rc, out, err = run_tool("layers", asc, data, "--dx", self.dx)
        self.assertEqual(rc, 0, err)
        ids, types, X, N, box = read_data(data)
        n = np.array([-t, 0, 1]) / math.sqrt(1 + t * t)
        depth = -(X @ n) / self.dx - 0.5
        k = np.rint(depth).astype(int)
        m = int((k == 0).sum())
        # twice as many points as the plan view's 0.5 x 0.3 / dx^2
        self.assertLess(abs(m * self.dx ** 2 / (1.0 * 0.3) - 1), 0.03)
        for layer in range(3):
            L = X[k == layer]
            nn = nearest(L) / self.dx
            self.assertGreaterEqual(nn.min(), 0.5, "near-coincident pair in layer %d" % layer)
            self.assertLessEqual(nn.max(), 1.5, "gap in layer %d" % layer)
            self.assertLess(abs(np.median(nn) - 1), 0.15)
        # no holes: every point of the slope (a fine sample of it, away from its edges) is
        # within 0.78 dx of a surface-layer particle (a square lattice's holes: 0.71 dx)
        S = X[k == 0] + 0.5 * self.dx * n
        u = np.linspace(0.02, 0.98, 97)          # along the slope, as a fraction
        v = np.linspace(0.02, 0.28, 27)
        U, V = np.meshgrid(u, v)
        Q = np.stack([0.5 * U.ravel(), V.ravel(), t * 0.5 * U.ravel()], axis=1)
        d = np.linalg.norm(Q[:, None, :] - S[None, :, :], axis=2).min(axis=1)
        self.assertLessEqual(d.max() / self.dx, 0.78)


class TestSphereCapSTL(TmpDir):
    """A sphere cap (R 0.5 about (0, 0, -0.3), plan radius 0.35) as an STL made here."""
    c, R, rplan, dx = np.array([0.0, 0.0, -0.3]), 0.5, 0.35, 0.025

    def check(self, data, layers=3):
        ids, types, X, N, box = read_data(data)
        r = X - self.c
        radial = r / np.linalg.norm(r, axis=1, keepdims=True)
        ang = np.degrees(np.arccos(np.clip(np.einsum("ij,ij->i", N, radial), -1, 1)))
        self.assertLess(ang.max(), 2.0, "normal off the sphere's by %.2f degrees" % ang.max())
        depth = (self.R - np.linalg.norm(r, axis=1)) / self.dx - 0.5
        k = np.rint(depth)
        self.assertEqual(sorted(set(k.astype(int))), list(range(layers)))
        self.assertLess(np.abs(depth - k).max(), 0.05, "layer off its depth")
        return X, N, k

    def test_binary_and_ascii(self):
        tris = sphere_cap(self.c, self.R, self.rplan, 0.01)
        for mode in ("binary", "ascii"):
            stlp, data = self.path("cap_%s.stl" % mode), self.path("cap_%s.data" % mode)
            make_stl(stlp, tris, mode)
            rc, out, err = run_tool("layers", stlp, data, "--dx", self.dx, "--height", 0.2)
            self.assertEqual(rc, 0, err)
            self.assertIn("open surface", out)
            X, N, k = self.check(data)
            # spacing within the first layer about dx
            nn = nearest(X[k == 0]) / self.dx
            self.assertGreaterEqual(nn.min(), 0.5)
            self.assertLessEqual(nn.max(), 1.5)

    def test_inverted_and_flip(self):
        tris = sphere_cap(self.c, self.R, self.rplan, 0.01)[:, ::-1, :]
        stlp, data = self.path("down.stl"), self.path("down.data")
        make_stl(stlp, tris)
        self.assertFailsClearly(["layers", stlp, data, "--dx", self.dx], stlp, "inverted normals", "--flip")
        rc, out, err = run_tool("layers", stlp, data, "--dx", self.dx, "--flip", "--layers", 4)
        self.assertEqual(rc, 0, err)
        self.check(data, layers=4)

    def test_inconsistent_orientation(self):
        tris = sphere_cap(self.c, self.R, self.rplan, 0.01)
        tris[10] = tris[10][::-1]
        stlp = self.path("mixed.stl")
        make_stl(stlp, tris)
        self.assertFailsClearly(["layers", stlp, self.path("x.data"), "--dx", self.dx],
                                stlp, "inconsistent facet orientation", "facets 10 and")

    def test_closed_inside_out(self):
        """A closed surface (a cube) must have outward normals; inside out it fails."""
        v = np.array([[x, y, z] for x in (0, .2) for y in (0, .2) for z in (0, .2)])
        quads = [(0, 1, 3, 2), (4, 6, 7, 5), (0, 4, 5, 1), (2, 3, 7, 6), (0, 2, 6, 4), (1, 5, 7, 3)]
        tris = np.array([[v[q[0]], v[q[1]], v[q[2]]] for q in quads] +
                        [[v[q[0]], v[q[2]], v[q[3]]] for q in quads])
        good, bad = self.path("cube.stl"), self.path("cube_in.stl")
        make_stl(good, tris)
        make_stl(bad, tris[:, ::-1, :])
        rc, out, err = run_tool("layers", good, self.path("cube.data"), "--dx", 0.02)
        self.assertEqual(rc, 0, err)
        self.assertIn("closed surface", out)
        ids, types, X, N, box = read_data(self.path("cube.data"))
        # a flat face keeps its own normal (crease), the particles inside the cube
        self.assertTrue(((X >= -1e-6) & (X <= 0.2 + 1e-6)).all())  # float32 STL
        axis = np.abs(N).max(axis=1)
        self.assertGreater(np.mean(axis > 1 - 1e-12), 0.5)
        self.assertFailsClearly(["layers", bad, self.path("x.data"), "--dx", 0.02], bad, "inverted normals")

    def test_empty_and_nan(self):
        empty = self.path("empty.stl")
        with open(empty, "wb") as f:
            f.write(b"\0" * 80 + np.uint32(0).tobytes())
        self.assertFailsClearly(["layers", empty, self.path("x.data"), "--dx", 0.02], empty, "no facets")
        zero = self.path("zero.stl")
        open(zero, "w").close()
        self.assertFailsClearly(["layers", zero, self.path("x.data"), "--dx", 0.02], zero, "no facets")
        tris = sphere_cap(self.c, self.R, self.rplan, 0.05)
        tris[3, 1, 2] = np.nan
        nanp = self.path("nan.stl")
        make_stl(nanp, tris)
        self.assertFailsClearly(["layers", nanp, self.path("x.data"), "--dx", 0.02], nanp,
                                "NaN", "facet 3")
        junk = self.path("junk.stl")
        with open(junk, "w") as f:
            f.write("solid x\n facet normal 0 0 1\n outer loop\n vertex 0 0 zero\n")
        self.assertFailsClearly(["layers", junk, self.path("x.data"), "--dx", 0.02], junk,
                                "line 4: a vertex needs three numbers")
        two = self.path("two.stl")
        with open(two, "w") as f:
            f.write("solid x\n facet normal 0 0 1\n outer loop\n vertex 0 0\n")
        self.assertFailsClearly(["layers", two, self.path("x.data"), "--dx", 0.02], two,
                                "line 4: a vertex needs three numbers: 'vertex 0 0'")

    def test_truncated_binary(self):
        tris = sphere_cap(self.c, self.R, self.rplan, 0.05)
        whole = self.path("whole.stl")
        make_stl(whole, tris)
        with open(whole, "rb") as f:
            data = f.read()
        cut = self.path("cut.stl")
        with open(cut, "wb") as f:
            f.write(data[:84 + 50 * (len(tris) // 2)])
        self.assertFailsClearly(["layers", cut, self.path("x.data"), "--dx", 0.02], cut,
                                "truncated or padded binary STL: its header says %d facets" % len(tris))

    def test_millimetres(self):
        """The cap written in millimetres: refused with the particle count it would make,
        and read as the metre one with --units mm."""
        tris = sphere_cap(self.c, self.R, self.rplan, 0.05)
        mm = self.path("mm.stl")
        make_stl(mm, 1000 * tris)
        self.assertFailsClearly(["layers", mm, self.path("x.data"), "--dx", 0.02], mm,
                                "more than --max-particles", "--units mm")
        rc, out, err = run_tool("layers", mm, self.path("mm.data"), "--dx", 0.02, "--units", "mm")
        self.assertEqual(rc, 0, err)


HEADER = "ncols 5\nnrows 4\nxllcorner 0\nyllcorner 0\ncellsize 0.05\n%s"


class TestGridErrors(TmpDir):
    rows = ["0.0 0.01 0.02 0.03 0.04"] * 4

    def grid(self, name, rows=None, header=HEADER):
        p = self.path(name)
        write_asc(p, header % "\n".join(rows or self.rows) + "\n")
        return p

    def test_good_grid(self):
        p = self.grid("good.asc")
        rc, out, err = run_tool("layers", p, self.path("good.data"), "--dx", 0.02)
        self.assertEqual(rc, 0, err)

    def test_nan_cell(self):
        rows = list(self.rows)
        rows[1] = "0.0 0.01 nan 0.03 0.04"
        p = self.grid("nan.asc", rows)
        self.assertFailsClearly(["layers", p, self.path("x.data"), "--dx", 0.02], p,
                                "no-data", "row 1, column 2", "x = 0.125, y = 0.125")

    def test_nodata_value_cell(self):
        rows = list(self.rows)
        rows[3] = "0.0 -9999 0.02 0.03 0.04"
        p = self.grid("nodata.asc", rows,
                      "ncols 5\nnrows 4\nxllcorner 0\nyllcorner 0\ncellsize 0.05\nNODATA_value -9999\n%s")
        self.assertFailsClearly(["layers", p, self.path("x.data"), "--dx", 0.02], p,
                                "no-data", "row 3, column 1")
        # a region of interest that keeps clear of it (and of its 2 dx margin) is fine
        rc, out, err = run_tool("layers", p, self.path("x.data"), "--dx", 0.01,
                                "--xlim", 0.175, 0.225, "--ylim", 0.075, 0.175)
        self.assertEqual(rc, 0, err)

    def test_malformed_header(self):
        p = self.grid("bad.asc", header=HEADER.replace("ncols 5", "ncols five"))
        self.assertFailsClearly(["layers", p, self.path("x.data"), "--dx", 0.02], p,
                                "header must give ncols and nrows")
        p = self.grid("short.asc", rows=self.rows[:2])
        self.assertFailsClearly(["layers", p, self.path("x.data"), "--dx", 0.02], p,
                                "10 values; the header says 4 rows of 5 (20)")
        self.assertFailsClearly(["layers", self.path("missing.asc"), self.path("x.data"),
                                 "--dx", 0.02], "missing.asc", "no such file")

    def test_malformed_values(self):
        rows = list(self.rows)
        rows[2] = "0.0 0.01 1.2.3 0.03 0.04"
        p = self.grid("spike.asc", rows)
        self.assertFailsClearly(["layers", p, self.path("x.data"), "--dx", 0.02], p,
                                "line 8, value 3: '1.2.3' is not a number")
        rows = list(self.rows)
        rows[1] = "0.0 0.01 0.02 0.03"
        rows[2] = "0.0 0.01 0.02 0.03 0.04 0.05"
        p = self.grid("ragged.asc", rows)
        self.assertFailsClearly(["layers", p, self.path("x.data"), "--dx", 0.02], p,
                                "line 7 holds 4 values; the header says ncols 5")

    def test_units_and_origin(self):
        """A grid in centimetres with its corner at (1000, 2000, 50) cm: the model's
        particles lie where the same grid in metres at the origin puts them."""
        p = self.grid("m.asc")
        cm_rows = [" ".join("%g" % (100 * float(v) + 50) for v in r.split()) for r in self.rows]
        q = self.grid("cm.asc", cm_rows, HEADER.replace("xllcorner 0", "xllcorner 1000")
                      .replace("yllcorner 0", "yllcorner 2000").replace("cellsize 0.05", "cellsize 5"))
        rc, out, err = run_tool("layers", p, self.path("m.data"), "--dx", 0.02)
        self.assertEqual(rc, 0, err)
        rc, out, err = run_tool("layers", q, self.path("cm.data"), "--dx", 0.02, "--units", "cm",
                                "--origin", 1000, 2000, 50)
        self.assertEqual(rc, 0, err)
        _, _, Xm, _, _ = read_data(self.path("m.data"))
        _, _, Xc, _, _ = read_data(self.path("cm.data"))
        self.assertEqual(Xm.shape, Xc.shape)
        self.assertLess(np.abs(Xm - Xc).max(), 1e-9)

    def test_caret_in_function(self):
        self.assertFailsClearly(["grid", self.path("c.asc"), "--function", "x^2",
                                 "--xlim", 0, 1, "--ylim", 0, 1, "--cell", 0.1],
                                "write powers as ** (x**2)")

    def test_resolution_against_dx(self):
        p = self.grid("coarse.asc")
        self.assertFailsClearly(["layers", p, self.path("x.data"), "--dx", 0.004], p, "too coarse")
        self.assertFailsClearly(["layers", p, self.path("x.data"), "--dx", 0.6], p, "too fine")

    def test_region_outside(self):
        p = self.grid("small.asc")
        self.assertFailsClearly(["layers", p, self.path("x.data"), "--dx", 0.02,
                                 "--xlim", 0, 0.5], p, "beyond the grid")


class TestLammpsRead(TmpDir):
    """LAMMPS reads the data file, and fix sph/normals the normals file beside it, as the
    doc says; built from numpy alone (no GDAL needed)."""

    def test_read_data(self):
        a, dx = 0.3, 0.02
        xs = np.linspace(0, 0.2, 21)
        ys = np.linspace(0, 0.1, 11)
        Z = 0.05 + a * xs[None, :] + 0 * ys[:, None]
        tri, nrm = terrain.soup_from_heights(xs, ys, Z)
        S, X, N, L, dropped = terrain.make_dummies(tri, nrm, dx, 3, ((0, 0.2), (0, 0.1)))
        self.assertEqual(dropped, 0)
        lo, hi = terrain.box_for(X, S, dx, 0.1, ((0, 0.2), (0, 0.1)))
        data = self.path("terrain.data")
        terrain.write_data(data, X, 2, 2, (lo, hi), "test terrain")
        terrain.write_normals(terrain.normals_path(data), N, data)
        with open(self.path("in.read"), "w") as f:
            f.write("""plugin load gransphplugin.so
units si
atom_style atomic
read_data terrain.data
mass * 1.0
group walls type 2
fix NORMALS walls sph/normals file terrain.normals
compute nsum walls reduce sum f_NORMALS[1] f_NORMALS[2] f_NORMALS[3]
thermo_style custom step atoms c_nsum[1] c_nsum[2] c_nsum[3]
thermo_modify format float %.15g
write_dump walls custom normals.dump id type x y z f_NORMALS[1] f_NORMALS[2] &
           f_NORMALS[3] modify sort id format float %.17g
run 0
""")
        env = dict(os.environ, OMP_NUM_THREADS="1")
        p = subprocess.run([LMP, "-in", "in.read", "-log", "log.read", "-screen", "none"],
                           cwd=self.tmp, capture_output=True, text=True, env=env, timeout=120)
        log = ""
        if os.path.exists(self.path("log.read")):
            with open(self.path("log.read")) as f:
                log = f.read()
        self.assertEqual(p.returncode, 0, p.stdout + p.stderr + log)
        rows = []
        with open(self.path("normals.dump")) as f:
            lines = f.read().split("\n")
        i = lines.index(next(l for l in lines if l.startswith("ITEM: ATOMS")))
        rows = np.array([[float(v) for v in l.split()] for l in lines[i + 1:] if l.strip()])
        self.assertEqual(len(rows), len(X))
        self.assertEqual(list(rows[:, 0].astype(int)), list(range(1, len(X) + 1)))
        self.assertLess(np.abs(rows[:, 2:5] - X).max(), 1e-12)
        self.assertLess(np.abs(rows[:, 5:8] - N).max(), 1e-15)
        n = np.array([-a, 0, 1]) / math.sqrt(1 + a * a)
        self.assertLess(np.abs(rows[:, 5:8] - n).max(), 1e-12)
        # and the compute sees them: the sum of the normals in the thermo line
        line = next(l for l in log.split("\n") if l.split()[:2] == ["0", str(len(X))])
        self.assertLess(np.abs(np.array([float(v) for v in line.split()[2:5]]) - len(X) * n).max(), 1e-9)


if __name__ == "__main__":
    unittest.main(verbosity=2)
