# SPDX-License-Identifier: GPL-2.0-only (GRANSPH: LICENSE)
"""Turn a terrain surface into the dummy (wall) particles of a GRANSPH wall.

  tools/terrain layers SURFACE OUT.data --dx DX [--layers 3] [--type 2] [--height H] ...
  tools/terrain grid --function "0.3*exp(-((x-1)**2)/0.2)" --xlim 0 2 --ylim 0 0.5 \\
                     --cell 0.01 OUT.asc
  tools/terrain preview OUT.data [--dump DUMP] [--out terrain.png]

SURFACE is an elevation grid (ESRI ASCII grid .asc, GeoTIFF .tif, or anything else GDAL
reads; the values are heights z at the cell centres, x and y from the grid's geotransform)
or a triangulated surface (.stl, ASCII or binary). Grids are read with GDAL (Debian's
python3-gdal) rather than rasterio: GDAL is the library underneath rasterio, its Python
binding is the one Debian ships for every GDAL format, and it needs no further package;
STL files with numpy-stl (python3-stl). OUT.data is a LAMMPS data file (atom_style atomic,
`id type x y z`); beside it, OUT.normals (the name with .normals for .data) holds the unit
outward normal of the surface at each particle (a section `WallNormals`, `id nx ny nz`),
which the input gives the dummies with

    read_data terrain.data
    fix       NORMALS all sph/normals file terrain.normals

(the IDs are the data file's: read it without an ID offset, e.g. as the first read_data).

How the particles are placed (doc/terrain.md): the surface is sampled at spacing about dx
ALONG it (area/dx^2 points, relaxed by a short repulsion on the surface itself, so that a
steep slope gets its full share of points and no steps), and each sample is copied into
the layers k = 0, 1, ..., N-1 at depth (k + 1/2) dx along its own outward normal: the
layers follow the surface, and its plane lies half a spacing above the first layer, as the
top of a lattice box floor (particles at -dx/2, -3dx/2, ...) lies under grains that start
at +dx/2. Grid normals come from the grid's central differences (exact on a plane), STL
normals from the facets' vertex order (right-hand rule, the STL convention; --flip
reverses it), averaged over the facets at each vertex that meet at less than --crease
degrees, and interpolated across each facet.
"""
import argparse
import math
import os
import sys
import warnings

import numpy as np


class TerrainError(Exception):
    """A problem with the input, reported as one line without a traceback."""


def fail(msg):
    raise TerrainError(msg)


# ----------------------------------------------------------------------------- surfaces
# A surface is a triangle soup: tri (T,3,3) corner positions, nrm (T,3,3) corner normals
# (unit, outward), interpolated linearly across each triangle.

def soup_from_heights(xs, ys, Z):
    """Triangles of a height field z = Z[i, j] at (xs[j], ys[i]) (both ascending), with
    the corner normals of the field's central differences (exact on a plane)."""
    ny, nx = Z.shape
    if nx < 2 or ny < 2:
        fail("the region used holds %d x %d grid nodes; at least 2 x 2 are needed" % (nx, ny))
    zy, zx = np.gradient(Z, ys, xs)
    n = np.stack([-zx, -zy, np.ones_like(Z)], axis=-1)
    n /= np.linalg.norm(n, axis=-1, keepdims=True)
    X, Y = np.meshgrid(xs, ys)
    P = np.stack([X, Y, Z], axis=-1)
    a = (slice(0, -1), slice(0, -1))
    b = (slice(0, -1), slice(1, None))
    c = (slice(1, None), slice(1, None))
    d = (slice(1, None), slice(0, -1))
    tri = np.concatenate([np.stack([P[a], P[b], P[c]], axis=2).reshape(-1, 3, 3),
                          np.stack([P[a], P[c], P[d]], axis=2).reshape(-1, 3, 3)])
    nrm = np.concatenate([np.stack([n[a], n[b], n[c]], axis=2).reshape(-1, 3, 3),
                          np.stack([n[a], n[c], n[d]], axis=2).reshape(-1, 3, 3)])
    return tri, nrm


def _quiet_gdal():
    try:
        from osgeo import gdal
    except ImportError:
        fail("GDAL's Python binding is missing: apt-get install python3-gdal (tools/stack/deps.sh)")
    gdal.UseExceptions()
    gdal.PushErrorHandler("CPLQuietErrorHandler")
    return gdal


def check_ascii_grid(path):
    """An ESRI ASCII grid as its header declares it, before GDAL reads it (which takes a
    malformed number such as 1.2.3 for a spike and pads short rows): every value a number,
    nrows rows of ncols."""
    with open(path) as f:
        lines = [l.split() for l in f.read().splitlines()]
    header, rows = {}, []
    for number, words in enumerate(lines, 1):
        if not words:
            continue
        if not rows and words[0].lower() in ("ncols", "nrows", "xllcorner", "yllcorner", "xllcenter",
                                             "yllcenter", "cellsize", "dx", "dy", "nodata_value"):
            header[words[0].lower()] = words[1] if len(words) > 1 else None
            continue
        rows.append((number, words))
    try:
        ncols, nrows = int(header["ncols"]), int(header["nrows"])
    except (KeyError, TypeError, ValueError):
        fail("%s: an ESRI ASCII grid's header must give ncols and nrows" % path)
    for number, words in rows:
        for column, word in enumerate(words):
            try:
                float(word)
            except ValueError:
                fail("%s: line %d, value %d: %r is not a number" % (path, number, column + 1, word))
    per_line = [len(w) for _, w in rows]
    if len(rows) == nrows and any(n != ncols for n in per_line):
        bad = next(i for i, n in enumerate(per_line) if n != ncols)
        fail("%s: line %d holds %d values; the header says ncols %d"
             % (path, rows[bad][0], per_line[bad], ncols))
    if sum(per_line) != ncols * nrows:
        fail("%s: %d values; the header says %d rows of %d (%d)"
             % (path, sum(per_line), nrows, ncols, ncols * nrows))


def read_grid(path, dx, xlim=None, ylim=None, place=lambda v, axis: v):
    """Nodes of an elevation grid covering the region of interest, plus a margin of about
    2 dx where the grid has it. Returns xs, ys (ascending), Z and the region (xlim, ylim).
    place(values, axis) maps the grid's coordinates to the model's (--units, --origin)."""
    gdal = _quiet_gdal()
    if not os.path.isfile(path):
        fail("%s: no such file" % path)
    if path.lower().endswith(".asc"):
        check_ascii_grid(path)
    try:
        # Float64: GDAL's ASCII grid reader otherwise guesses integers from the first
        # values and reads a later "nan" as 0
        ds = gdal.OpenEx(path, gdal.OF_RASTER, open_options=["DATATYPE=Float64"])
        band = ds.GetRasterBand(1)
        data = band.ReadAsArray().astype(np.float64)
        nodata = band.GetNoDataValue()
        gt = ds.GetGeoTransform()
    except (RuntimeError, AttributeError) as e:
        fail("%s: GDAL cannot read it as an elevation grid: %s" % (path, str(e).strip() or "no driver recognises it"))
    if gt[2] != 0 or gt[4] != 0:
        fail("%s: the grid is rotated (geotransform %s); warp it to north-up first (gdalwarp)" % (path, gt))
    nrow, ncol = data.shape
    scale = place(1.0, 2) - place(0.0, 2)
    cw, ch = gt[1] * scale, gt[5] * scale
    if abs(abs(cw) - abs(ch)) > 1e-6 * abs(cw):
        # not an error: the sampling does not need square cells, but say it
        pass
    cell = max(abs(cw), abs(ch))
    if cell > 10 * dx:
        fail("%s: the grid is too coarse for dx = %g: its cells (%g) are more than 10 dx; "
             "resample it (gdalwarp -tr %g %g -r cubic) or use a larger dx" % (path, dx, cell, 5 * dx, 5 * dx))
    if min(abs(cw), abs(ch)) < 0.1 * dx:
        fail("%s: the grid is too fine for dx = %g: its cells (%g) are less than dx/10, so its "
             "normals would follow roughness the particles cannot represent; resample it "
             "(gdalwarp -tr %g %g -r average) or use a smaller dx" % (path, dx, min(abs(cw), abs(ch)), dx / 2, dx / 2))
    xs = place(gt[0] + (np.arange(ncol) + 0.5) * gt[1], 0)
    ys = place(gt[3] + (np.arange(nrow) + 0.5) * gt[5], 1)
    cols = np.argsort(xs)
    rows = np.argsort(ys)
    xs, ys = xs[cols], ys[rows]
    Z = data[np.ix_(rows, cols)]
    region = []
    for name, lim, v in (("x", xlim, xs), ("y", ylim, ys)):
        lo, hi = (v[0], v[-1]) if lim is None else lim
        if not lo < hi:
            fail("--%slim %g %g: the lower limit must be below the upper" % (name, lo, hi))
        if lo < v[0] - 1e-9 * cell or hi > v[-1] + 1e-9 * cell:
            fail("%s: the region %s in [%g, %g] reaches beyond the grid's nodes (cell centres), "
                 "%s in [%g, %g]" % (path, name, lo, hi, name, v[0], v[-1]))
        region.append((lo, hi))
    sel = []
    for (lo, hi), v in zip(region, (xs, ys)):
        m = np.ceil(2 * dx / cell)
        i0 = max(0, np.searchsorted(v, lo + 1e-9 * cell, "right") - 1 - int(m))
        i1 = min(len(v), np.searchsorted(v, hi - 1e-9 * cell, "left") + 1 + int(m))
        sel.append((i0, i1))
    (j0, j1), (i0, i1) = sel
    Zr = Z[i0:i1, j0:j1]
    bad = (~np.isfinite(Zr)) if nodata is None else (~np.isfinite(Zr) | (Zr == nodata))
    if bad.any():
        bi, bj = np.argwhere(bad)[0]
        r, c = rows[i0 + bi], cols[j0 + bj]
        fail("%s: %d no-data cell(s) in the region used (x %g..%g, y %g..%g), the first at "
             "row %d, column %d (from the top left, 0-based; x = %g, y = %g); fill them "
             "(gdal_fillnodata.py) or choose --xlim/--ylim that avoid them"
             % (path, bad.sum(), xs[j0], xs[j1 - 1], ys[i0], ys[i1 - 1], r, c, xs[j0 + bj], ys[i0 + bi]))
    return xs[j0:j1], ys[i0:i1], place(Zr, 2), region


def check_stl_file(path):
    """The file as STL requires it, before numpy-stl reads it (which takes a truncated
    binary file's first facets, or a vertex of two coordinates, without a word): a binary
    file's size must be that of the facet count in its header; an ASCII file's facets must
    have three vertices of three numbers each."""
    size = os.path.getsize(path)
    with open(path, "rb") as f:
        head = f.read(84)
    text = head[:5].lower() == b"solid"
    if text:
        with open(path, "rb") as f:
            raw = f.read()
        try:
            lines = raw.decode("ascii").splitlines()
        except UnicodeDecodeError:
            text = False          # binary files may start with "solid" too
    if not text:
        if size < 84:
            fail("%s: a binary STL file has an 84-byte header, this one holds %d bytes" % (path, size))
        count = int.from_bytes(head[80:84], "little")
        if size != 84 + 50 * count:
            fail("%s: truncated or padded binary STL: its header says %d facets (%d bytes), the "
                 "file holds %d bytes (%.1f facets)" % (path, count, 84 + 50 * count, size, (size - 84) / 50))
        return
    vertices = 0
    for number, line in enumerate(lines, 1):
        words = line.split()
        if not words:
            continue
        if words[0] == "vertex":
            try:
                if len(words) != 4:
                    raise ValueError
                [float(w) for w in words[1:]]
            except ValueError:
                fail("%s: line %d: a vertex needs three numbers: %r" % (path, number, line.strip()))
            vertices += 1
        elif words[0] == "endloop":
            if vertices != 3:
                fail("%s: line %d: a facet of %d vertices (STL facets have 3)" % (path, number, vertices))
            vertices = 0


def read_stl(path, flip=False, crease=60.0):
    """Triangles and corner normals of an STL surface, after checking it."""
    if not os.path.isfile(path):
        fail("%s: no such file" % path)
    if os.path.getsize(path) > 0:
        check_stl_file(path)
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            from stl import mesh
    except ImportError:
        fail("numpy-stl is missing: apt-get install python3-stl (tools/stack/deps.sh)")
    if os.path.getsize(path) == 0:
        fail("%s: the STL file is empty (no facets)" % path)
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            m = mesh.Mesh.from_file(path, calculate_normals=False)
    except Exception as e:  # numpy-stl raises many kinds for a bad file
        fail("%s: numpy-stl cannot read it as an STL surface: %s" % (path, str(e).strip() or type(e).__name__))
    V = np.asarray(m.vectors, dtype=np.float64).reshape(-1, 3, 3)
    stored = np.asarray(m.normals, dtype=np.float64).reshape(-1, 3)
    if len(V) == 0:
        fail("%s: the STL surface has no facets" % path)
    badf = ~np.isfinite(V).all(axis=(1, 2))
    if badf.any():
        fail("%s: %d facet(s) with NaN or infinite coordinates, the first is facet %d (0-based)"
             % (path, badf.sum(), np.flatnonzero(badf)[0]))
    if flip:
        V = V[:, ::-1, :].copy()
        stored = -stored
    cr = np.cross(V[:, 1] - V[:, 0], V[:, 2] - V[:, 0])
    area2 = np.linalg.norm(cr, axis=1)
    keep = area2 > 1e-12 * max(area2.max(), 1e-300)
    if not keep.any():
        fail("%s: every facet of the STL surface has zero area" % path)
    V, cr, area2, stored = V[keep], cr[keep], area2[keep], stored[keep]
    fid = np.flatnonzero(keep)            # facet numbers in the file, for messages
    fn = cr / area2[:, None]
    # stored normals that contradict the vertex order: the vertex order wins (say so)
    sn = np.linalg.norm(stored, axis=1)
    contra = (sn > 0) & (np.einsum("ij,ij->i", stored, fn) < 0)
    if contra.any():
        print("tools/terrain: warning: %s: %d facet(s) whose stored normal points against "
              "their vertex order (first: facet %d); the vertex order (right-hand rule) is used"
              % (path, contra.sum(), fid[np.flatnonzero(contra)[0]]), file=sys.stderr)
    # weld vertices and check the edges
    verts, inv = np.unique(V.reshape(-1, 3), axis=0, return_inverse=True)
    inv = inv.reshape(-1)                   # numpy 2.0 gave it another shape
    F = inv.reshape(-1, 3)
    e0 = F.reshape(-1)
    e1 = F[:, [1, 2, 0]].reshape(-1)
    lo, hi = np.minimum(e0, e1), np.maximum(e0, e1)
    forward = e0 < e1
    key = lo * len(verts) + hi
    order = np.argsort(key, kind="stable")
    uk, start, count = np.unique(key[order], return_index=True, return_counts=True)
    if (count > 2).any():
        k = order[start[np.flatnonzero(count > 2)[0]]]
        fail("%s: an edge shared by more than two facets at (%s) (facet %d): not a surface"
             % (path, ", ".join("%g" % c for c in verts[e0[k]]), fid[k // 3]))
    two = np.flatnonzero(count == 2)
    ka, kb = order[start[two]], order[start[two] + 1]
    same = forward[ka] == forward[kb]
    if same.any():
        a, b = ka[same][0], kb[same][0]
        fail("%s: inconsistent facet orientation: %d edge(s) are walked the same way by both "
             "of their facets, the first between facets %d and %d at (%s); every facet must "
             "list its vertices counter-clockwise seen from outside"
             % (path, same.sum(), fid[a // 3], fid[b // 3], ", ".join("%g" % c for c in verts[e0[a]])))
    closed = (count == 2).all()
    if closed:
        vol = np.einsum("ij,ij->i", V[:, 0], np.cross(V[:, 1], V[:, 2])).sum() / 6
        if vol < 0:
            fail("%s: inverted normals: the closed surface's facets point inwards (negative "
                 "volume %g); use --flip" % (path, vol))
    else:
        nz = cr[:, 2].sum() / area2.sum()
        if nz < 0:
            fail("%s: inverted normals: the facets of this open (terrain) surface point down, "
                 "into the ground (mean normal z = %.3g); use --flip" % (path, nz))
    # corner normals: area-weighted normals of the facets at each vertex that meet this
    # facet at less than the crease angle
    cosc = math.cos(math.radians(crease))
    cv = F.reshape(-1)                      # vertex of each corner
    cf = np.repeat(np.arange(len(F)), 3)    # facet of each corner
    o = np.argsort(cv, kind="stable")
    svtx = cv[o]
    gs = np.searchsorted(svtx, cv, "left")
    ge = np.searchsorted(svtx, cv, "right")
    cnt = ge - gs
    ci = np.repeat(np.arange(len(cv)), cnt)
    cj = o[np.arange(cnt.sum()) - np.repeat(np.cumsum(cnt) - cnt, cnt) + np.repeat(gs, cnt)]
    fi, fj = cf[ci], cf[cj]
    w = (np.einsum("ij,ij->i", fn[fi], fn[fj]) > cosc).astype(float)
    acc = np.zeros((len(cv), 3))
    np.add.at(acc, ci, w[:, None] * cr[fj])
    acc /= np.linalg.norm(acc, axis=1, keepdims=True)
    return V, acc.reshape(-1, 3, 3), closed


# ----------------------------------------------------------------------------- sampling

def pairs_within(P, r):
    """Index pairs i < j of points closer than r, and their distances (cell lists)."""
    n = len(P)
    if n < 2:
        return np.zeros(0, int), np.zeros(0, int), np.zeros(0)
    c = np.floor((P - P.min(axis=0)) / r).astype(np.int64) + 1
    dims = c.max(axis=0) + 2
    key = (c[:, 0] * dims[1] + c[:, 1]) * dims[2] + c[:, 2]
    order = np.argsort(key, kind="stable")
    skey = key[order]
    I, J = [], []
    for ox in (-1, 0, 1):
        for oy in (-1, 0, 1):
            for oz in (-1, 0, 1):
                nk = key + (ox * dims[1] + oy) * dims[2] + oz
                lo = np.searchsorted(skey, nk, "left")
                cnt = np.searchsorted(skey, nk, "right") - lo
                tot = cnt.sum()
                if tot == 0:
                    continue
                i = np.repeat(np.arange(n), cnt)
                j = order[np.arange(tot) - np.repeat(np.cumsum(cnt) - cnt, cnt) + np.repeat(lo, cnt)]
                m = i < j
                I.append(i[m])
                J.append(j[m])
    I = np.concatenate(I) if I else np.zeros(0, int)
    J = np.concatenate(J) if J else np.zeros(0, int)
    d = np.linalg.norm(P[I] - P[J], axis=1)
    m = d < r
    return I[m], J[m], d[m]


def subdivide(tri, nrm, L):
    """Split triangles at their edge midpoints until no edge is longer than L (flat
    pieces of the same triangles; corner normals interpolated linearly)."""
    while True:
        e = np.linalg.norm(tri - tri[:, [1, 2, 0]], axis=2).max(axis=1)
        big = e > L
        if not big.any():
            return tri, nrm
        t, n = tri[big], nrm[big]
        out_t, out_n = [tri[~big]], [nrm[~big]]
        for src, out in ((t, out_t), (n, out_n)):
            c0, c1, c2 = src[:, 0], src[:, 1], src[:, 2]
            m01, m12, m20 = (c0 + c1) / 2, (c1 + c2) / 2, (c2 + c0) / 2
            for piece in ((c0, m01, m20), (m01, c1, m12), (m20, m12, c2), (m01, m12, m20)):
                out.append(np.stack(piece, axis=1))
        tri, nrm = np.concatenate(out_t), np.concatenate(out_n)


def closest_on_triangles(p, a, b, c):
    """Closest points q of triangles (a, b, c) to points p, their barycentric coordinates
    and distances (row by row)."""
    ab, ac, ap = b - a, c - a, p - a
    d00 = np.einsum("ij,ij->i", ab, ab)
    d01 = np.einsum("ij,ij->i", ab, ac)
    d11 = np.einsum("ij,ij->i", ac, ac)
    d20 = np.einsum("ij,ij->i", ap, ab)
    d21 = np.einsum("ij,ij->i", ap, ac)
    den = d00 * d11 - d01 * d01
    v = (d11 * d20 - d01 * d21) / den
    w = (d00 * d21 - d01 * d20) / den
    bary = np.stack([1 - v - w, v, w], axis=1)
    inside = (bary >= 0).all(axis=1)
    q = a + v[:, None] * ab + w[:, None] * ac
    best = np.where(inside, np.linalg.norm(p - q, axis=1), np.inf)
    for s, e, i, j in ((a, b, 0, 1), (b, c, 1, 2), (c, a, 2, 0)):
        se = e - s
        t = np.clip(np.einsum("ij,ij->i", p - s, se) / np.einsum("ij,ij->i", se, se), 0, 1)
        qe = s + t[:, None] * se
        de = np.linalg.norm(p - qe, axis=1)
        m = ~inside & (de < best)
        best[m] = de[m]
        q[m] = qe[m]
        bb = np.zeros((m.sum(), 3))
        bb[:, i] = 1 - t[m]
        bb[:, j] = t[m]
        bary[m] = bb
    return q, bary, best


class Projector:
    """Closest point on a triangle soup of small triangles (edges <= cell), through
    3D bins of the triangles' boxes grown by `reach`."""

    def __init__(self, tri, nrm, cell, reach):
        self.tri, self.nrm, self.cell = tri, nrm, cell
        lo = tri.min(axis=1) - reach
        hi = tri.max(axis=1) + reach
        self.origin = lo.min(axis=0) - cell
        clo = np.floor((lo - self.origin) / cell).astype(np.int64)
        chi = np.floor((hi - self.origin) / cell).astype(np.int64)
        self.dims = chi.max(axis=0) + 2
        span = (chi - clo).max() + 1
        keys, tris = [], []
        for ox in range(span):
            for oy in range(span):
                for oz in range(span):
                    cc = clo + np.array([ox, oy, oz])
                    m = (cc <= chi).all(axis=1)
                    keys.append(self._key(cc[m]))
                    tris.append(np.flatnonzero(m))
        keys, tris = np.concatenate(keys), np.concatenate(tris)
        o = np.argsort(keys, kind="stable")
        self.keys, self.tris = keys[o], tris[o]

    def _key(self, c):
        return (c[:, 0] * self.dims[1] + c[:, 1]) * self.dims[2] + c[:, 2]

    def project(self, P, chunk=20000):
        """Closest surface points of P and the unit normals there."""
        Q = np.empty_like(P)
        N = np.empty_like(P)
        for s in range(0, len(P), chunk):
            p = P[s:s + chunk]
            c = np.floor((p - self.origin) / self.cell).astype(np.int64)
            c = np.clip(c, 0, self.dims - 1)
            k = self._key(c)
            lo = np.searchsorted(self.keys, k, "left")
            cnt = np.searchsorted(self.keys, k, "right") - lo
            if (cnt == 0).any():
                raise RuntimeError("a point left the surface's neighbourhood")
            i = np.repeat(np.arange(len(p)), cnt)
            t = self.tris[np.arange(cnt.sum()) - np.repeat(np.cumsum(cnt) - cnt, cnt) + np.repeat(lo, cnt)]
            T = self.tri[t]
            q, bary, d = closest_on_triangles(p[i], T[:, 0], T[:, 1], T[:, 2])
            o = np.lexsort((d, i))
            first = o[np.r_[True, i[o][1:] != i[o][:-1]]]
            Q[s:s + chunk] = q[first]
            n = np.einsum("ij,ijk->ik", bary[first], self.nrm[t[first]])
            N[s:s + chunk] = n / np.linalg.norm(n, axis=1, keepdims=True)
        return Q, N


def boundary_segments(tri, piece):
    """The open edges of a triangle soup (edges of one triangle only, after welding the
    corners), cut into pieces no longer than `piece`: (start, end) arrays."""
    P = tri.reshape(-1, 3)
    scale = max(np.abs(P).max(), 1e-300)
    q = np.round(P / (1e-9 * scale)).astype(np.int64)
    _, vid = np.unique(q, axis=0, return_inverse=True)
    vid = vid.reshape(-1)
    F = vid.reshape(-1, 3)
    e0, e1 = F.reshape(-1), F[:, [1, 2, 0]].reshape(-1)
    key = np.minimum(e0, e1) * (vid.max() + 1) + np.maximum(e0, e1)
    _, inv, cnt = np.unique(key, return_inverse=True, return_counts=True)
    inv = inv.reshape(-1)
    open_ = cnt[inv] == 1
    A = tri.reshape(-1, 3)[np.arange(len(e0))[open_]]
    B = tri[:, [1, 2, 0]].reshape(-1, 3)[open_]
    n = np.maximum(1, np.ceil(np.linalg.norm(B - A, axis=1) / piece)).astype(int)
    k = np.arange(n.sum()) - np.repeat(np.cumsum(n) - n, n)
    A, B, n = np.repeat(A, n, axis=0), np.repeat(B, n, axis=0), np.repeat(n, n)
    return A + (B - A) * (k / n)[:, None], A + (B - A) * ((k + 1) / n)[:, None]


def boundary_push(P, seg, a, power):
    """Push of each point by its mirror image across the nearest open edge (within a/2),
    so that a point settles about half a spacing inside the surface's edge."""
    D = np.zeros_like(P)
    s0, s1 = seg
    if len(s0) == 0:
        return D
    M = (s0 + s1) / 2
    piece = np.linalg.norm(s1 - s0, axis=1).max()
    X = np.concatenate([P, M])
    I, J, _ = pairs_within(X, a / 2 + piece)
    m = (I < len(P)) & (J >= len(P))
    i, j = I[m], J[m] - len(P)
    if len(i) == 0:
        return D
    se = s1[j] - s0[j]
    t = np.clip(np.einsum("ij,ij->i", P[i] - s0[j], se) / np.einsum("ij,ij->i", se, se), 0, 1)
    u = P[i] - (s0[j] + t[:, None] * se)
    d = np.linalg.norm(u, axis=1)
    o = np.lexsort((d, i))
    first = o[np.r_[True, i[o][1:] != i[o][:-1]]]
    i, u, d = i[first], u[first], d[first]
    m = (d < a / 2) & (d > 0)
    f = 0.5 * a * (1 - 2 * d[m] / a) ** power / d[m]
    D[i[m]] = f[:, None] * u[m]
    return D


def sample_surface(tri, nrm, dx, seed=1, iterations=100, reach=1.8, power=2):
    """Points about dx apart along the surface (area/dx^2 of them), with their normals:
    random points relaxed by a soft repulsion of range reach*dx, moved along the surface
    and projected back onto it. The long, soft range closes the vacancies a short one
    leaves (holes of radius about dx), so that the largest hole is near a square
    lattice's (0.71 dx); open edges repel like mirrors, so that the points keep about
    dx/2 from them and the density stays 1/dx^2 up to the edge."""
    seg = boundary_segments(tri, 0.5 * dx)
    tri, nrm = subdivide(tri, nrm, dx)
    cr = np.cross(tri[:, 1] - tri[:, 0], tri[:, 2] - tri[:, 0])
    area = 0.5 * np.linalg.norm(cr, axis=1)
    total = area.sum()
    n = int(round(total / dx ** 2))
    if n < 1:
        fail("the surface (area %g) is smaller than one dx^2 = %g" % (total, dx ** 2))
    rng = np.random.default_rng(seed)
    t = rng.choice(len(tri), size=n, p=area / total)
    r1, r2 = rng.random(n), rng.random(n)
    s = np.sqrt(r1)
    bary = np.stack([1 - s, s * (1 - r2), s * r2], axis=1)
    P = np.einsum("ij,ijk->ik", bary, tri[t])
    proj = Projector(tri, nrm, cell=dx, reach=0.5 * dx)
    P, N = proj.project(P)
    a = reach * dx
    for it in range(iterations):
        I, J, d = pairs_within(P, a)
        u = P[I] - P[J]
        tiny = d < 1e-9 * dx
        if tiny.any():
            u[tiny] = rng.standard_normal((tiny.sum(), 3))
            d = np.where(tiny, np.linalg.norm(u, axis=1), d)
        f = (0.5 * a * (1 - d / a) ** power / d)[:, None] * u
        D = boundary_push(P, seg, a, power)
        np.add.at(D, I, f)
        np.add.at(D, J, -f)
        D -= np.einsum("ij,ij->i", D, N)[:, None] * N          # along the surface
        step = np.linalg.norm(D, axis=1, keepdims=True)
        D *= np.minimum(1, 0.25 * dx / np.maximum(step, 1e-300))
        P, N = proj.project(P + 0.5 * D)
    return P, N, total


def build_layers(S, N, dx, layers, min_sep=0.5):
    """Layers k = 0..layers-1 at depth (k + 1/2) dx along the normals; where the layers of
    a tightly curved surface cross, particles closer than min_sep*dx to a shallower one
    are dropped. Returns positions, normals, layer index, and how many were dropped."""
    X = np.concatenate([S - (k + 0.5) * dx * N for k in range(layers)])
    NN = np.tile(N, (layers, 1))
    L = np.repeat(np.arange(layers), len(S))
    I, J, d = pairs_within(X, min_sep * dx)
    drop = np.zeros(len(X), bool)
    if len(I):
        # keep the first (shallower, earlier) of each pair, greedily
        for i, j in sorted(zip(I.tolist(), J.tolist())):
            if not drop[i] and not drop[j]:
                drop[max(i, j)] = True
    keep = ~drop
    return X[keep], NN[keep], L[keep], int(drop.sum())


def write_data(path, X, atype, ntypes, box, title):
    lo, hi = box
    with open(path, "w") as f:
        f.write(title.replace("\n", " ") + "\n\n")
        f.write("%d atoms\n%d atom types\n\n" % (len(X), ntypes))
        for k, ax in enumerate("xyz"):
            f.write("%.17g %.17g %slo %shi\n" % (lo[k], hi[k], ax, ax))
        f.write("\nAtoms # atomic\n\n")
        for i, x in enumerate(X, start=1):
            f.write("%d %d %.17g %.17g %.17g\n" % (i, atype, x[0], x[1], x[2]))


def normals_path(data_path):
    """Where the normals of the data file data_path go: its name with .normals for .data."""
    stem = data_path[:-len(".data")] if data_path.endswith(".data") else data_path
    return stem + ".normals"


def write_normals(path, N, data_path):
    """The dummies' outward unit normals, by the data file's atom IDs, as fix sph/normals
    reads them (a WallNormals section)."""
    with open(path, "w") as f:
        f.write("# the outward unit normals of the dummy particles of %s (tools/terrain), "
                "for fix sph/normals file\n\nWallNormals\n\n" % os.path.basename(data_path))
        for i, n in enumerate(N, start=1):
            f.write("%d %.17g %.17g %.17g\n" % (i, n[0], n[1], n[2]))


def make_dummies(tri, nrm, dx, layers=3, region=None, seed=1):
    """Surface samples (cropped to the plan-view region if given) and their layers."""
    S, N, area = sample_surface(tri, nrm, dx, seed=seed)
    if region is not None:
        (x0, x1), (y0, y1) = region
        m = (S[:, 0] >= x0) & (S[:, 0] <= x1) & (S[:, 1] >= y0) & (S[:, 1] <= y1)
        S, N = S[m], N[m]
    if len(S) == 0:
        fail("no surface point in the region")
    X, NN, L, dropped = build_layers(S, N, dx, layers)
    return S, X, NN, L, dropped


def box_for(X, S, dx, height, region=None, box=None):
    if box is not None:
        lo, hi = np.array(box[0::2], float), np.array(box[1::2], float)
        out = ((X < lo) | (X > hi)).any(axis=1)
        if out.any():
            fail("--box %s leaves out %d particle(s), e.g. one at (%s); the particles span "
                 "%s to %s" % (" ".join("%g" % b for b in box), out.sum(),
                               ", ".join("%g" % c for c in X[out][0]),
                               np.array2string(X.min(0), precision=4), np.array2string(X.max(0), precision=4)))
        return lo, hi
    lo = X.min(axis=0) - 0.5 * dx
    hi = X.max(axis=0) + 0.5 * dx
    if region is not None:
        lo[:2] = np.minimum(lo[:2], [region[0][0], region[1][0]])
        hi[:2] = np.maximum(hi[:2], [region[0][1], region[1][1]])
    hi[2] = max(hi[2], S[:, 2].max() + max(height, 0.5 * dx))
    return lo, hi


# ----------------------------------------------------------------------------- commands

UNITS = {"m": 1.0, "cm": 0.01, "mm": 0.001}

FUNCTIONS = {k: getattr(np, k) for k in (
    "exp", "log", "log10", "sqrt", "sin", "cos", "tan", "arcsin", "arccos", "arctan",
    "arctan2", "sinh", "cosh", "tanh", "abs", "minimum", "maximum", "where", "clip",
    "hypot", "pi", "e", "floor", "ceil", "sign")}


def cmd_grid(a):
    gdal = _quiet_gdal()
    (x0, x1), (y0, y1), h = a.xlim, a.ylim, a.cell
    if h <= 0 or not (x0 < x1 and y0 < y1):
        fail("grid: --cell must be positive and --xlim/--ylim increasing")
    nx = int(round((x1 - x0) / h)) + 1
    ny = int(round((y1 - y0) / h)) + 1
    if abs((nx - 1) * h - (x1 - x0)) > 1e-6 * h or abs((ny - 1) * h - (y1 - y0)) > 1e-6 * h:
        fail("grid: the limits must be whole multiples of --cell %g apart" % h)
    if "^" in a.function:
        fail("grid: --function %r: write powers as ** (x**2): in Python ^ is a bitwise "
             "exclusive or, not a power" % a.function)
    xs = x0 + h * np.arange(nx)
    ys = y1 - h * np.arange(ny)          # top row first, as grids are stored
    X, Y = np.meshgrid(xs, ys)
    try:
        with np.errstate(all="ignore"):
            Z = eval(a.function, {"__builtins__": {}}, dict(FUNCTIONS, x=X, y=Y))
        Z = np.broadcast_to(np.asarray(Z, dtype=np.float64), X.shape)
    except Exception as e:
        fail("grid: cannot evaluate --function %r: %s" % (a.function, e))
    if not np.isfinite(Z).all():
        fail("grid: --function %r is not finite everywhere in the region" % a.function)
    ext = os.path.splitext(a.out)[1].lower()
    driver = {".asc": "AAIGrid", ".tif": "GTiff", ".tiff": "GTiff"}.get(ext)
    if driver is None:
        fail("grid: %s: write .asc (ESRI ASCII grid) or .tif (GeoTIFF)" % a.out)
    mem = gdal.GetDriverByName("MEM").Create("", nx, ny, 1, gdal.GDT_Float64)
    mem.SetGeoTransform((x0 - h / 2, h, 0, y1 + h / 2, 0, -h))
    mem.GetRasterBand(1).WriteArray(np.ascontiguousarray(Z))
    opts = ["SIGNIFICANT_DIGITS=15"] if driver == "AAIGrid" else []
    try:
        gdal.GetDriverByName(driver).CreateCopy(a.out, mem, options=opts)
    except RuntimeError as e:
        fail("grid: %s: %s" % (a.out, e))
    aux = a.out + ".aux.xml"
    if os.path.exists(aux):
        os.remove(aux)
    print("tools/terrain: wrote %s: %d x %d nodes, cell %g, z in [%g, %g]"
          % (a.out, nx, ny, h, Z.min(), Z.max()))


def cmd_layers(a):
    if not a.dx > 0:
        fail("--dx must be positive")
    if a.layers < 1:
        fail("--layers must be at least 1")
    ntypes = a.atom_types or max(2, a.type)
    if a.type < 1 or a.type > ntypes:
        fail("--type %d is not among the %d atom types" % (a.type, ntypes))
    scale = UNITS[a.units]
    origin = np.asarray(a.origin or (0.0, 0.0, 0.0), dtype=np.float64)

    def place(values, axis):      # the surface's coordinates in the model's metres
        return (values - origin[axis]) * scale

    if a.surface.lower().endswith(".stl"):
        if a.xlim or a.ylim:
            fail("--xlim/--ylim select a part of a grid; cut an STL in a CAD tool")
        tri, nrm, closed = read_stl(a.surface, flip=a.flip, crease=a.crease)
        tri = (tri - origin) * scale
        region = None
        kind = "STL, %s surface, %d facets" % ("closed" if closed else "open", len(tri))
    else:
        if a.flip:
            fail("--flip is for STL surfaces; a grid's normals point up")
        xs, ys, Z, region = read_grid(a.surface, a.dx, a.xlim, a.ylim, place)
        tri, nrm = soup_from_heights(xs, ys, Z)
        kind = "grid, %d x %d nodes used" % (len(xs), len(ys))
    area = 0.5 * np.linalg.norm(np.cross(tri[:, 1] - tri[:, 0], tri[:, 2] - tri[:, 0]), axis=1).sum()
    expected = area / a.dx ** 2 * a.layers
    if expected > a.max_particles:
        lo, hi = tri.reshape(-1, 3).min(0), tri.reshape(-1, 3).max(0)
        fail("%s: about %.3g particles (a surface of %.4g m^2 from %s to %s, at dx %g, %d layers), "
             "more than --max-particles %.3g: a surface in millimetres or centimetres needs --units "
             "mm or cm, one in projected coordinates --origin; or a larger dx"
             % (a.surface, expected, area, np.array2string(lo, precision=4),
                np.array2string(hi, precision=4), a.dx, a.layers, a.max_particles))
    S, X, N, L, dropped = make_dummies(tri, nrm, a.dx, a.layers, region, seed=a.seed)
    lo, hi = box_for(X, S, a.dx, a.height, region, a.box)
    title = ("LAMMPS data file: %d layers of dummy particles (dx %g, depths (k+1/2) dx) "
             "beneath %s, by tools/terrain" % (a.layers, a.dx, os.path.basename(a.surface)))
    write_data(a.out, X, a.type, ntypes, (lo, hi), title)
    write_normals(normals_path(a.out), N, a.out)
    I, J, d = pairs_within(S, 2 * a.dx)
    nn = np.full(len(S), np.inf)
    np.minimum.at(nn, I, d)
    np.minimum.at(nn, J, d)
    nn = nn[np.isfinite(nn)]
    print("tools/terrain: %s (%s): %d particles of type %d in %d layers (%d on the surface layer), "
          "nearest-neighbour spacing on it %.3g..%.3g dx (median %.3g)%s; box %s to %s; wrote %s and %s"
          % (a.surface, kind, len(X), a.type, a.layers, len(S),
             nn.min() / a.dx if len(nn) else 0, nn.max() / a.dx if len(nn) else 0,
             np.median(nn) / a.dx if len(nn) else 0,
             "; %d dropped where deeper layers crossed" % dropped if dropped else "",
             " ".join("%g" % v for v in lo), " ".join("%g" % v for v in hi), a.out,
             normals_path(a.out)))


def read_atoms(path):
    """The Atoms section of a data file (as tools/terrain writes it, or any atom_style
    atomic file): types and positions (n, 3)."""
    if not os.path.isfile(path):
        fail("%s: no such file" % path)
    rows, inside = [], False
    with open(path) as f:
        for line in f:
            words = line.split("#")[0].split()
            if not words:
                continue
            if words[0] in ("Atoms", "Velocities", "Masses"):
                inside = words[0] == "Atoms"
                continue
            if inside:
                rows.append([float(w) for w in words[1:5]])
    if not rows:
        fail("%s: no Atoms section" % path)
    A = np.array(rows)
    return A[:, 0].astype(int), A[:, 1:4]


def read_dump_last(path):
    """The last snapshot of a LAMMPS text dump with x y z columns: positions, and the
    speed where vx vy vz are dumped."""
    if not os.path.isfile(path):
        fail("%s: no such file" % path)
    with open(path) as f:
        lines = f.read().splitlines()
    heads = [i for i, l in enumerate(lines) if l.startswith("ITEM: ATOMS")]
    if not heads:
        fail("%s: not a LAMMPS dump (no ITEM: ATOMS)" % path)
    names = lines[heads[-1]].split()[2:]
    if not {"x", "y", "z"} <= set(names):
        fail("%s: the dump needs x y z columns, it has %s" % (path, " ".join(names)))
    data = np.array([[float(w) for w in l.split()] for l in lines[heads[-1] + 1:] if l.strip()], ndmin=2)
    col = {n: data[:, k] for k, n in enumerate(names)}
    X = np.stack([col["x"], col["y"], col["z"]], axis=1)
    speed = (np.sqrt(col["vx"] ** 2 + col["vy"] ** 2 + col["vz"] ** 2)
             if {"vx", "vy", "vz"} <= set(names) else None)
    return X, speed


def cmd_preview(a):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    types, X = read_atoms(a.data)
    D = X[types == a.type] if (types == a.type).any() else X
    fig, (side, top) = plt.subplots(2, 1, figsize=(9, 8))
    order = np.argsort(D[:, 2])              # the surface layer drawn last, on top
    side.scatter(D[:, 0], D[:, 2], s=2, c="0.6", label="terrain (type %d)" % a.type)
    sc = top.scatter(D[order, 0], D[order, 1], s=3, c=D[order, 2], cmap="terrain")
    fig.colorbar(sc, ax=top, label="terrain z (m)")
    title = "%s: %d dummy particles" % (os.path.basename(a.data), len(D))
    if a.dump:
        G, speed = read_dump_last(a.dump)
        shade = speed if speed is not None else G[:, 1]
        label = "speed (m/s)" if speed is not None else "y (m)"
        gs = side.scatter(G[:, 0], G[:, 2], s=3, c=shade, cmap="viridis", label="grains")
        top.scatter(G[:, 0], G[:, 1], s=3, c=shade, cmap="viridis")
        fig.colorbar(gs, ax=side, label=label)
        title += "; %s: %d grains" % (os.path.basename(a.dump), len(G))
    side.set_xlabel("x (m)")
    side.set_ylabel("z (m)")
    side.set_aspect("equal")
    side.legend(loc="upper right", fontsize=8)
    top.set_xlabel("x (m)")
    top.set_ylabel("y (m)")
    top.set_aspect("equal")
    fig.suptitle(title)
    fig.tight_layout()
    fig.savefig(a.out, dpi=110)
    print("tools/terrain: wrote %s (%s)" % (a.out, title))


def main(argv=None):
    p = argparse.ArgumentParser(prog="tools/terrain", description=__doc__,
                                formatter_class=argparse.RawDescriptionHelpFormatter)
    sub = p.add_subparsers(dest="command", required=True)
    g = sub.add_parser("layers", help="dummy particles beneath a grid or STL surface")
    g.add_argument("surface", help="elevation grid (.asc, .tif, ... via GDAL) or .stl")
    g.add_argument("out", help="LAMMPS data file to write (and OUT.normals beside it)")
    g.add_argument("--dx", type=float, required=True, help="particle spacing")
    g.add_argument("--layers", type=int, default=3, help="layers beneath the surface (3)")
    g.add_argument("--type", type=int, default=2, help="atom type of the dummies (2)")
    g.add_argument("--atom-types", type=int, default=0,
                   help="atom types the data file declares (max(2, --type))")
    g.add_argument("--height", type=float, default=0.0,
                   help="room above the highest surface point in the box (dx/2)")
    g.add_argument("--box", type=float, nargs=6, metavar=("XLO", "XHI", "YLO", "YHI", "ZLO", "ZHI"),
                   help="the box, instead of the particles' extent plus --height")
    g.add_argument("--xlim", type=float, nargs=2, help="grid: plan-view region of interest in x")
    g.add_argument("--ylim", type=float, nargs=2, help="grid: plan-view region of interest in y")
    g.add_argument("--flip", action="store_true", help="STL: outward is against the facets' normals")
    g.add_argument("--crease", type=float, default=60.0,
                   help="STL: facets meeting at more than this angle (degrees) keep their own normals (60)")
    g.add_argument("--seed", type=int, default=1, help="seed of the sampling (1)")
    g.add_argument("--units", choices=sorted(UNITS), default="m",
                   help="the length unit of the surface's coordinates (m); the model is in metres")
    g.add_argument("--origin", type=float, nargs=3, metavar=("X0", "Y0", "Z0"),
                   help="subtracted from the surface's coordinates (in its --units) before they "
                        "are scaled: e.g. the corner of a site in projected (UTM) coordinates")
    g.add_argument("--max-particles", type=float, default=2e7,
                   help="stop before sampling a surface that would give more (2e7)")
    g.set_defaults(func=cmd_layers)
    v = sub.add_parser("preview", help="draw a terrain data file, and a deposit on it, as a picture")
    v.add_argument("data", help="the data file tools/terrain layers wrote")
    v.add_argument("--dump", help="a LAMMPS text dump (x y z, and vx vy vz for the speed): its "
                                  "last snapshot is drawn on the terrain")
    v.add_argument("--type", type=int, default=2, help="atom type of the terrain's dummies (2)")
    v.add_argument("--out", default="terrain.png", help="the picture (terrain.png)")
    v.set_defaults(func=cmd_preview)
    h = sub.add_parser("grid", help="write an analytic terrain z = f(x, y) as a grid")
    h.add_argument("out", help=".asc (ESRI ASCII grid) or .tif (GeoTIFF)")
    h.add_argument("--function", required=True,
                   help="z in terms of x and y, numpy's exp, sin, sqrt, tanh, where, ... and pi")
    h.add_argument("--xlim", type=float, nargs=2, required=True)
    h.add_argument("--ylim", type=float, nargs=2, required=True)
    h.add_argument("--cell", type=float, required=True, help="node spacing")
    h.set_defaults(func=cmd_grid)
    a = p.parse_args(argv)
    try:
        a.func(a)
    except TerrainError as e:
        print("tools/terrain: error: %s" % e, file=sys.stderr)
        return 1
    except OSError as e:
        print("tools/terrain: error: %s" % e, file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
