#!/usr/bin/python3
"""t604 helper: read an MSH file with Gmsh's own reader (Debian python3-gmsh,
which works with /usr/bin/python3 only) and check it against what the writer
meant.  Usage: t604-gmsh-check.py FILE NODES QUADS LINES QUADTYPE LINETYPE
PHYSICALS AREA.  Checks node and element counts and types, the physical
groups and their names, positive Jacobian determinants at Gauss points and
the area by Gmsh's own quadrature (which is only right if Gmsh reads the
nodes in the order they were meant: a misread order changes the area by far
more than round-off).  The area tolerance is a forward round-off bound of
Gmsh's evaluation (area_roundoff_bound), so that it holds whatever BLAS
kernel or vector width either side ran with.  Silent on success; exit 77 if
gmsh cannot be imported."""
import math
import sys

try:
    import gmsh
except ImportError:
    sys.exit(77)


U = 2.0 ** -53  # unit round-off of IEEE double


def inverse(a):
    """Inverse of a small square matrix (Gauss-Jordan, partial pivoting)."""
    n = len(a)
    m = [list(row) + [float(i == j) for j in range(n)] for i, row in enumerate(a)]
    for c in range(n):
        p = max(range(c, n), key=lambda r: abs(m[r][c]))
        m[c], m[p] = m[p], m[c]
        piv = m[c][c]
        m[c] = [x / piv for x in m[c]]
        for r in range(n):
            if r != c and m[r][c] != 0.0:
                f = m[r][c]
                m[r] = [x - f * y for x, y in zip(m[r], m[c])]
    return [row[n:] for row in m]


def monomial_coefficients(order):
    """C[i][k]: the 1D Lagrange function of equispaced node i is sum_k C_ik t^k."""
    nodes = [-1.0 + 2.0 * i / order for i in range(order + 1)]
    return inverse([[x ** k for x in nodes] for k in range(order + 1)])


def basis_sums(c, t):
    """(S0, S1) at t in [-1, 1]: sum over the 1D Lagrange functions of the
    equispaced nodes (Gmsh's reference nodes for quads) of sum_k |C_ik| |t^k|
    and of sum_k |C_ik| |k t^(k-1)|, C the monomial coefficients (inverse
    Vandermonde).  Gmsh evaluates its Lagrange bases as C times monomials,
    so these bound the size of what each value and derivative is summed
    from, and with it their round-off."""
    n = len(c)
    s0 = sum(abs(c[i][k]) * abs(t) ** k for i in range(n) for k in range(n))
    s1 = sum(abs(c[i][k]) * k * abs(t) ** (k - 1) for i in range(n) for k in range(1, n))
    return s0, s1


def area_roundoff_bound(order, loc, w, jac, coords):
    """Forward round-off bound of the area sum(w det J) as Gmsh computes it.
    Each entry of J is sum_i x_i dphi_i, dphi_i = sum_k C_ik dm_k: its error
    is at most gamma * X * S, gamma = (2 (Q+1)^2 + 2) u (the lengths of the
    sums), X the element's largest coordinate, S the tensor product of
    basis_sums; det J = J00 J11 - J01 J10 inherits |J00| e11 + e00 |J11| +
    ... (first order), and the final sum over points adds n u sum |w det|.
    Our own area is computed with the same or smaller sums, so twice the
    bound covers both sides.  It is a worst case (no cancellation of
    errors): 7e-14 of the area at Q = 1, 3e-5 at Q = 10 on these meshes;
    a node read in the wrong place moves the area by a part of its
    element's area (the meshes have at most a few hundred elements), far
    more."""
    npts = len(w)
    gamma = (2 * (order + 1) ** 2 + 2) * U
    c = monomial_coefficients(order)
    sums = []
    for p in range(npts):
        a0, a1 = basis_sums(c, loc[3 * p])
        b0, b1 = basis_sums(c, loc[3 * p + 1])
        sums.append((a1 * b0, a0 * b1))  # d/dxi, d/deta
    bound, total = 0.0, 0.0
    for e, x in enumerate(coords):
        for p in range(npts):
            j = jac[9 * (e * npts + p):9 * (e * npts + p) + 9]
            exi, eeta = gamma * x * sums[p][0], gamma * x * sums[p][1]
            # Gmsh's J rows are d/dxi, d/deta; columns x, y
            err = (abs(j[0]) * eeta + exi * abs(j[4]) + abs(j[1]) * eeta + exi * abs(j[3]))
            bound += w[p] * err
            total += w[p] * abs(j[0] * j[4] - j[1] * j[3])
    return 2.0 * (bound + len(coords) * npts * U * total)


def main(argv):
    path = argv[1]
    nodes, quads, lines, qtype, ltype, nphys = (int(a) for a in argv[2:8])
    area = float(argv[8])
    fails = []
    gmsh.initialize()
    try:
        gmsh.option.setNumber("General.Terminal", 0)
        gmsh.open(path)
        tags, _, _ = gmsh.model.mesh.getNodes()
        if len(tags) != nodes:
            fails.append("nodes %d, expected %d" % (len(tags), nodes))
        types, etags, _ = gmsh.model.mesh.getElements()
        count = {t: len(e) for t, e in zip(types, etags)}
        if count.get(qtype, 0) != quads:
            fails.append("quads of type %d: %d, expected %d" % (qtype, count.get(qtype, 0), quads))
        if count.get(ltype, 0) != lines:
            fails.append("lines of type %d: %d, expected %d" % (ltype, count.get(ltype, 0), lines))
        if sum(count.values()) != quads + lines:
            fails.append("elements %s" % count)
        groups = gmsh.model.getPhysicalGroups()
        if len(groups) != nphys:
            fails.append("physical groups %d, expected %d" % (len(groups), nphys))
        for dim, tag in groups:
            name = gmsh.model.getPhysicalName(dim, tag)
            want = "domain" if dim == 2 else "boundary_%d" % (tag - 1)
            if name != want:
                fails.append("physical (%d, %d) named %r, expected %r" % (dim, tag, name, want))
        order = gmsh.model.mesh.getElementProperties(qtype)[2]
        loc, w = gmsh.model.mesh.getIntegrationPoints(qtype, "Gauss%d" % (2 * order + 1))
        jac, det, _ = gmsh.model.mesh.getJacobians(qtype, loc)
        npts = len(w)
        got = sum(w[k % npts] * det[k] for k in range(len(det)))
        if min(det) <= 0:
            fails.append("non-positive Jacobian determinant %g" % min(det))
        _, enodes = gmsh.model.mesh.getElementsByType(qtype)
        ntags, xyz, _ = gmsh.model.mesh.getNodes()
        where = {t: i for i, t in enumerate(ntags)}
        npe = len(enodes) // max(1, count.get(qtype, 1))
        coords = [max(max(abs(xyz[3 * where[t]]), abs(xyz[3 * where[t] + 1]))
                      for t in enodes[e * npe:(e + 1) * npe]) for e in range(len(enodes) // npe)]
        tol = area_roundoff_bound(order, loc, w, jac, coords)
        if abs(got - area) > tol:
            fails.append("area by Gmsh %.15g, expected %.15g (round-off bound %.3g)"
                         % (got, area, tol))
    finally:
        gmsh.finalize()
    for f in fails:
        print("%s: %s" % (path, f))
    return 1 if fails else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
