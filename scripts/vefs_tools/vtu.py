"""The .vtu/.pvtu output of vefs (deal.II's DataOut XML files: inline
base64, zlib compressed or not, UInt32 or UInt64 headers, or ascii) read
with numpy only, so that the plotting scripts need no VTK installation;
and a 2D field of it, or its section by a plane in 3D, sampled on a
regular grid for contour plots (render_shapes.py, plot_vortex_shapes.py).
"""
import base64
import collections
import os
import xml.etree.ElementTree as ET
import zlib

import numpy as np

#: VTK cell types of the cells deal.II writes for Q1 output
VTK_QUAD, VTK_HEXAHEDRON = 9, 12

VTK_TYPES = {"Float32": "<f4", "Float64": "<f8", "Int32": "<i4",
             "Int64": "<i8", "UInt8": "<u1", "UInt32": "<u4",
             "UInt64": "<u8", "Int8": "<i1"}


def _b64(text):
    """Decode base64 that may lack its padding (VTK's separate chunks)."""
    text = "".join(text.split())
    return base64.b64decode(text + "=" * (-len(text) % 4))


def _b64_prefix(text, n_bytes):
    """Decode the first n_bytes of a base64 string; also return the rest.

    VTK encodes a compressed array's header and its data as two separate
    base64 strings written one after the other, so the header has to be
    decoded on its own, padding included.
    """
    n_chars = 4 * ((n_bytes + 2) // 3)
    return _b64(text[:n_chars])[:n_bytes], text[n_chars:]


def _binary_array(text, dtype, compressed, header):
    """Bytes of an inline binary DataArray -> numpy array."""
    text = "".join(text.split())
    if not text:                         # a rank without cells
        return np.zeros(0, dtype)
    hsize = np.dtype(header).itemsize
    if not compressed:
        raw = _b64(text)
        count = int(np.frombuffer(raw[:hsize], header)[0])
        if len(raw) >= hsize + count:
            return np.frombuffer(raw[hsize:hsize + count], dtype)
        # header and data encoded separately
        head, rest = _b64_prefix(text, hsize)
        count = int(np.frombuffer(head, header)[0])
        return np.frombuffer(_b64(rest)[:count], dtype)
    first, _ = _b64_prefix(text, hsize)
    n_blocks = int(np.frombuffer(first, header)[0])
    head, rest = _b64_prefix(text, hsize * (3 + n_blocks))
    sizes = np.frombuffer(head, header)[3:]
    data, pos, out = _b64(rest), 0, []
    for size in sizes:
        out.append(zlib.decompress(data[pos:pos + int(size)]))
        pos += int(size)
    return np.frombuffer(b"".join(out), dtype)


def data_array(element, compressed, header):
    """One <DataArray> as a numpy array, (n, components) if vector-valued."""
    dtype = np.dtype(VTK_TYPES[element.get("type")])
    fmt = element.get("format", "ascii")
    text = element.text or ""
    if fmt == "ascii":
        values = np.array(text.split(), dtype=dtype)
    elif fmt == "binary":
        values = _binary_array(text, dtype, compressed, header)
    else:
        raise NotImplementedError("DataArray format '%s' (only the inline "
                                  "ascii/binary that deal.II writes)" % fmt)
    components = int(element.get("NumberOfComponents", "1"))
    return values.reshape(-1, components) if components > 1 else values


# ---------------------------------------------------------------- files

#: one .vtu file or a .pvtu record with its pieces merged: points (n, 3)
#: float64, the cells' vertex indices (connectivity, offsets as in VTK),
#: the VTK cell types, {name: point values} (1D for scalars, (n, k) for
#: vectors) and the number of pieces
Mesh = collections.namedtuple(
    "Mesh", "points connectivity offsets types point_data pieces")


def _merge(meshes, pieces):
    """One Mesh of several, indices shifted; pieces without points (a rank
    without cells) are left out, and so are point fields that some piece
    lacks."""
    meshes = [m for m in meshes if len(m.points)]
    if not meshes:
        empty = np.zeros(0, np.int64)
        return Mesh(np.zeros((0, 3)), empty, empty, empty, {}, pieces)
    shift = np.cumsum([0] + [len(m.points) for m in meshes[:-1]])
    conn_shift = np.cumsum([0] + [len(m.connectivity) for m in meshes[:-1]])
    names = set.intersection(*(set(m.point_data) for m in meshes))
    return Mesh(np.concatenate([m.points for m in meshes]),
                np.concatenate([m.connectivity + s
                                for m, s in zip(meshes, shift)]),
                np.concatenate([m.offsets + s
                                for m, s in zip(meshes, conn_shift)]),
                np.concatenate([m.types for m in meshes]),
                {k: np.concatenate([m.point_data[k] for m in meshes])
                 for k in names}, pieces)


def read_vtu(path, fields=None):
    """The Mesh of one .vtu file (all its <Piece>s) with the point fields
    named in `fields` (all if None)."""
    root = ET.parse(path).getroot()
    if root.get("byte_order", "LittleEndian") != "LittleEndian":
        raise ValueError("%s: only little-endian files are supported" % path)
    compressor = root.get("compressor")
    if compressor is not None and compressor != "vtkZLibDataCompressor":
        raise ValueError("%s: compressor %s not supported" % (path,
                                                             compressor))
    compressed = compressor is not None
    header = VTK_TYPES[root.get("header_type", "UInt32")]
    meshes = []
    for piece in root.iter("Piece"):
        points = data_array(piece.find("Points/DataArray"), compressed,
                            header).reshape(-1, 3).astype(float)
        arrays = {a.get("Name"): a for a in piece.find("Cells")}
        cells = [data_array(arrays[name], compressed, header).astype(np.int64)
                 for name in ("connectivity", "offsets", "types")]
        values = {}
        point_data = piece.find("PointData")
        for a in (point_data if point_data is not None else []):
            if fields is None or a.get("Name") in fields:
                values[a.get("Name")] = data_array(a, compressed, header)
        meshes.append(Mesh(points, *cells, values, 1))
    return _merge(meshes, 1)


def read_pvtu(path, fields=None):
    """The Mesh of a .pvtu record: its .vtu pieces (one per MPI rank)
    merged."""
    root = ET.parse(path).getroot()
    sources = [p.get("Source") for p in root.iter("Piece")]
    base = os.path.dirname(path)
    return _merge([read_vtu(os.path.join(base, s), fields) for s in sources],
                  len(sources))


def read_any(path, fields=None):
    """read_pvtu or read_vtu, by the file's ending."""
    return read_pvtu(path, fields) if path.endswith(".pvtu") \
        else read_vtu(path, fields)


def read_series(output_dir):
    """[(time, path of .pvtu or .vtu)] from OUTPUT_DIR/solution.pvd, else
    the .pvtu files of the directory in name order (times 0, 1, ...)."""
    pvd = os.path.join(output_dir, "solution.pvd")
    if os.path.exists(pvd):
        root = ET.parse(pvd).getroot()
        return [(float(d.get("timestep")), os.path.join(output_dir,
                                                        d.get("file")))
                for d in root.iter("DataSet")]
    files = sorted(f for f in os.listdir(output_dir) if f.endswith(".pvtu"))
    return [(float(i), os.path.join(output_dir, f))
            for i, f in enumerate(files)]


def cell_list(mesh):
    """The cells as a list of vertex index arrays (any cell sizes)."""
    return np.split(mesh.connectivity, mesh.offsets[:-1])


def cell_rows(mesh):
    """The cells as rows (n, vertices per cell); ValueError if they differ
    in size."""
    sizes = np.diff(np.concatenate([[0], mesh.offsets]))
    if len(sizes) and np.any(sizes != sizes[0]):
        raise ValueError("cells of different sizes")
    return mesh.connectivity.reshape(len(mesh.types), -1)


# ---------------------------------------------------------- a regular grid

def tensor_order(points, corners, inplane):
    """Sort 4 corner indices per row (n, 4) of axis-aligned rectangles into
    tensor order (lower left, lower right, upper left, upper right)."""
    p = points[corners][:, :, inplane]
    k = np.lexsort((p[:, :, 0], p[:, :, 1]), axis=1)
    return np.take_along_axis(corners, k, axis=1)


def rectangles_2d(points, quads, values):
    """(lower corners (n, 2), upper corners (n, 2), corner values (n, 4) in
    tensor order) of the quadrilateral cells."""
    corners = tensor_order(points, quads, [0, 1])
    xy = points[corners][:, :, :2]
    return xy[:, 0], xy[:, 3], values[corners]


def section(points, hexes, values, axis, c):
    """Section of axis-aligned hexahedra by the plane x[axis] = c, as
    rectangles like rectangles_2d: the 4 edges of each cut box parallel to
    `axis` are interpolated linearly at c, which is exact for the trilinear
    Q1 output. Boxes with lo <= c < hi are cut (lo <= c <= hi on the top
    face of the mesh): they tile the plane once, also where it is a face."""
    inplane = [d for d in range(3) if d != axis]
    x = points[hexes][:, :, axis]            # (n, 8)
    lo, hi = x.min(1), x.max(1)
    # a plane within rounding (float32 output) of the top face is on it
    top = c >= points[:, axis].max() - 1e-6 * np.ptp(points[:, axis])
    c = min(c, points[:, axis].max())
    cut = (lo <= c) & ((c < hi) | (top & (c <= hi)))
    hexes, x, lo, hi = hexes[cut], x[cut], lo[cut], hi[cut]
    # per box the 4 vertices of the low face and of the high face along
    # `axis`, each in tensor order, so that low[k] and high[k] share an edge
    order = np.argsort(x, axis=1, kind="stable")
    low = tensor_order(points, np.take_along_axis(hexes, order[:, :4], 1),
                       inplane)
    high = tensor_order(points, np.take_along_axis(hexes, order[:, 4:], 1),
                        inplane)
    if not (np.allclose(points[low][:, :, axis], lo[:, None])
            and np.allclose(points[high][:, :, axis], hi[:, None])
            and np.allclose(points[low][:, :, inplane],
                            points[high][:, :, inplane])):
        raise ValueError("section: the cells are not axis-aligned boxes")
    w = ((c - lo) / np.where(hi > lo, hi - lo, 1))[:, None]
    v = (1 - w) * values[low] + w * values[high]
    xy = points[low][:, :, inplane]
    return xy[:, 0], xy[:, 3], v


def resample(lower, upper, corner_values):
    """The cells' bilinear fields on the regular grid of the smallest cell
    size: (x (nx,), y (ny,), values (ny, nx), masked where no cell is).

    A conforming grid, so that contour/contourf are valid where the
    adaptive mesh has hanging nodes (a matplotlib triangulation of the
    cells would have T-junctions, which it does not support: its filled
    contours came out up to 25 % too large); exact at the grid points
    since the cells are refinements of one coarse grid and each cell's
    field is bilinear. Values at points on cell boundaries are averaged
    over the cells (they agree for the continuous level set; for
    cell-constant fields this is the nodal average).
    """
    h = (upper - lower).min(0)
    x0, x1 = lower.min(0), upper.max(0)
    n = np.rint((x1 - x0) / h).astype(int) + 1
    total = np.zeros((n[1], n[0]))
    count = np.zeros((n[1], n[0]))
    i0 = np.rint((lower - x0) / h).astype(int)
    i1 = np.rint((upper - x0) / h).astype(int)
    for a, b, v in zip(i0, i1, corner_values):
        s = np.linspace(0, 1, b[0] - a[0] + 1)[None, :]
        t = np.linspace(0, 1, b[1] - a[1] + 1)[:, None]
        total[a[1]:b[1] + 1, a[0]:b[0] + 1] += (
            (1 - t) * ((1 - s) * v[0] + s * v[1])
            + t * ((1 - s) * v[2] + s * v[3]))
        count[a[1]:b[1] + 1, a[0]:b[0] + 1] += 1
    values = np.ma.masked_array(total / np.maximum(count, 1), count == 0)
    return (x0[0] + h[0] * np.arange(n[0]), x0[1] + h[1] * np.arange(n[1]),
            values)


def plane_data(points, cells, types, g, dim, axis, c):
    """The body function on a regular grid of the 2D domain or of the
    section plane (see resample), or None if the plane misses the mesh."""
    if dim == 2:
        if np.any(types != VTK_QUAD):
            raise ValueError("2D output with cells other than quadrilaterals")
        rects = rectangles_2d(points, cells, g)
    else:
        if np.any(types != VTK_HEXAHEDRON):
            raise ValueError("3D output with cells other than hexahedra")
        rects = section(points, cells, g, axis, c)
    if not len(rects[0]):
        return None
    return resample(*rects)
