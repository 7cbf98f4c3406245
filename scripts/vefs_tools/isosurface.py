"""The zero surface of a Q1 level set on hexahedral cells, and the volume
where it is negative, by marching tetrahedra with numpy (render_surfaces.py).

Each hexahedron (VTK vertex order) is split into six tetrahedra around its
diagonal 0-6; on a tetrahedron the level set is taken linear between its
vertex values, so the surface is a triangle or a quadrilateral (two
triangles) per cut tetrahedron, and the volume of {psi < 0} is exact for
that piecewise linear level set. Neighbouring cells of the same size share
their face diagonals, so the surface is closed across them; at a hanging
face (cells of different levels) tiny cracks may remain, which a picture
does not show.
"""
import numpy as np

#: the six tetrahedra of a VTK hexahedron around its diagonal 0-6
HEX_TETS = np.array([[0, 1, 2, 6], [0, 2, 3, 6], [0, 3, 7, 6],
                     [0, 7, 4, 6], [0, 4, 5, 6], [0, 5, 1, 6]])


def tetrahedra(points, hexes, values):
    """Corner coordinates (m, 4, 3) and values (m, 4) of the tetrahedra of
    the hexahedra `hexes` (n, 8)."""
    corners = hexes[:, HEX_TETS].reshape(-1, 4)
    return points[corners], values[corners]


def _crossing(x, v, i, j):
    """Where the linear level set is zero on the edges (i, j) of each
    tetrahedron (rows of x (m, 4, 3), v (m, 4); i, j (m,) indices)."""
    rows = np.arange(len(x))
    vi, vj = v[rows, i], v[rows, j]
    t = vi / (vi - vj)
    return x[rows, i] + t[:, None] * (x[rows, j] - x[rows, i])


def _volume(a, b, c, d):
    """Volumes of the tetrahedra with corners a, b, c, d (each (m, 3))."""
    return np.abs(np.einsum("ij,ij->i", b - a, np.cross(c - a, d - a))) / 6


def zero_surface(x, v):
    """Triangles (k, 3, 3) of {psi = 0} in the tetrahedra x (m, 4, 3) with
    values v (m, 4), their unit normals (k, 3) (either side),
    and the volume where psi < 0."""
    negative = v < 0
    count = negative.sum(1)
    # by sign, negative vertices first (a stable sort keeps the rest)
    order = np.argsort(~negative, axis=1, kind="stable")
    x = np.take_along_axis(x, order[:, :, None], 1)
    v = np.take_along_axis(v, order, 1)
    full = count == 4
    volume = _volume(*(x[full, k] for k in range(4))).sum()
    triangles = []

    def lone(select, lone_vertex):
        """Triangle around a vertex of the other sign from the three."""
        xs, vs = x[select], v[select]
        n = len(xs)
        others = [k for k in range(4) if k != lone_vertex]
        p = [_crossing(xs, vs, np.full(n, lone_vertex), np.full(n, k))
             for k in others]
        triangles.append(np.stack(p, 1))
        corner = _volume(xs[:, lone_vertex], *p)
        whole = _volume(*(xs[:, k] for k in range(4)))
        return corner.sum() if lone_vertex == 0 else (whole - corner).sum()

    volume += lone(count == 1, 0)
    volume += lone(count == 3, 3)
    select = count == 2
    xs, vs = x[select], v[select]
    n = len(xs)
    a, b, c, d = (np.full(n, k) for k in range(4))
    pac, pad = _crossing(xs, vs, a, c), _crossing(xs, vs, a, d)
    pbc, pbd = _crossing(xs, vs, b, c), _crossing(xs, vs, b, d)
    triangles.append(np.stack([pac, pad, pbd], 1))
    triangles.append(np.stack([pac, pbd, pbc], 1))
    # {psi < 0}: the prism (a, pac, pad) - (b, pbc, pbd) in three tetrahedra
    xa, xb = xs[:, 0], xs[:, 1]
    volume += (_volume(xa, pac, pad, xb) + _volume(pac, pad, xb, pbc) +
               _volume(pad, xb, pbc, pbd)).sum()

    triangles = np.concatenate(triangles) if triangles else np.zeros(
        (0, 3, 3))
    normals = np.cross(triangles[:, 1] - triangles[:, 0],
                       triangles[:, 2] - triangles[:, 0])
    length = np.linalg.norm(normals, axis=1)
    keep = length > 0
    triangles, normals = triangles[keep], normals[keep] / length[keep, None]
    return triangles, normals, volume


def self_test():
    """The volume inside a sphere of radius 0.3 sampled on uniform box
    meshes of the unit cube: second order (printed)."""
    radius, centre = 0.3, np.array([0.5, 0.5, 0.5])
    exact = 4 / 3 * np.pi * radius ** 3
    errors = []
    for n in (8, 16, 32):
        g = np.linspace(0, 1, n + 1)
        X, Y, Z = np.meshgrid(g, g, g, indexing="ij")
        points = np.stack([X.ravel(), Y.ravel(), Z.ravel()], 1)
        values = np.linalg.norm(points - centre, axis=1) - radius
        index = np.arange((n + 1) ** 3).reshape(n + 1, n + 1, n + 1)
        i, j, k = np.meshgrid(*(np.arange(n),) * 3, indexing="ij")
        i, j, k = i.ravel(), j.ravel(), k.ravel()
        hexes = np.stack([index[i, j, k], index[i + 1, j, k],
                          index[i + 1, j + 1, k], index[i, j + 1, k],
                          index[i, j, k + 1], index[i + 1, j, k + 1],
                          index[i + 1, j + 1, k + 1],
                          index[i, j + 1, k + 1]], 1)
        x, v = tetrahedra(points, hexes, values)
        triangles, _, volume = zero_surface(x, v)
        errors.append(abs(volume - exact) / exact)
        print("h = 1/%d: %d triangles, volume %.6f, exact %.6f, relative "
              "error %.2e" % (n, len(triangles), volume, exact, errors[-1]))
    orders = [np.log2(errors[k] / errors[k + 1]) for k in range(2)]
    print("observed orders: %.2f, %.2f" % tuple(orders))
    return min(orders) > 1.8
