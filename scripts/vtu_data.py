"""Decoding of the <DataArray> elements of the XML VTK files deal.II's
DataOut writes (inline base64, zlib compressed or not, UInt32 or UInt64
headers, or ascii), with numpy only: shared by the scripts that read the
.vtu output (render_shapes.py, plot_free_surface.py) so that no VTK
installation is needed."""
import base64
import zlib

import numpy as np

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
