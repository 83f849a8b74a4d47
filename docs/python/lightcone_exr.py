"""Reads lightcone's EXR frames with numpy alone (any pip or conda Python).

lightcone writes its frames as single-part scanline OpenEXR files: FLOAT
channels (R, G, B, an alpha, and with --layers the data layers hit.r,
hit.kind, ...), ZIP-compressed.  Debian's python3-openimageio reads them, but
a Python from pip or conda has no such module; this file needs only numpy and
the standard library, so it can be copied next to a notebook.  It reads what
lightcone writes (and any single-part scanline EXR with UINT, HALF or FLOAT
channels stored raw, ZIPS or ZIP); anything else (tiled, multi-part, deep,
PIZ, DWA ...) is refused with a message: read those with OpenImageIO or the
`OpenEXR` package.  The format is OpenEXR's "Technical Introduction" and
"OpenEXR File Layout" documents.

    import lightcone_exr
    frame = lightcone_exr.read("out/kerr/kerr_disk.0000.exr")
    frame.channels["hit.r"][150, 180]      # row 150, column 180
    frame.header["lightcone/shot"]         # the frame's own attributes
"""

import struct
import zlib
from dataclasses import dataclass, field

import numpy as np

_MAGIC = 20000630
_PIXEL_TYPES = {0: np.dtype("<u4"), 1: np.dtype("<f2"), 2: np.dtype("<f4")}
_COMPRESSIONS = {0: ("none", 1), 2: ("zips", 1), 3: ("zip", 16)}  # name, scanlines per block
_MAX_SIDE = 1 << 20


@dataclass
class ExrFrame:
    """channels: name -> 2D array [row, column] (row 0 at the top); header:
    the attributes a reader can show as text or numbers."""

    width: int
    height: int
    channels: dict = field(default_factory=dict)
    header: dict = field(default_factory=dict)


class ExrError(ValueError):
    pass


def _cstring(data, pos, what):
    end = data.find(b"\0", pos)
    if end < 0 or end - pos > 255:
        raise ExrError(f"{what}: a name without its end")
    return data[pos:end].decode("latin-1"), end + 1


def _attribute_value(kind, raw):
    # The attribute types a lightcone frame carries; others are kept as bytes.
    if kind == "string":
        return raw.decode("utf-8", "replace")
    if kind == "int" and len(raw) == 4:
        return struct.unpack("<i", raw)[0]
    if kind == "float" and len(raw) == 4:
        return struct.unpack("<f", raw)[0]
    if kind in ("box2i", "v2f", "v2i") and len(raw) in (8, 16):
        return struct.unpack("<4i" if kind == "box2i" else "<2f" if kind == "v2f" else "<2i", raw)
    if kind in ("compression", "lineOrder") and len(raw) == 1:
        return raw[0]
    return raw


def _channel_list(raw):
    channels, pos = [], 0
    while pos < len(raw) and raw[pos] != 0:
        name, pos = _cstring(raw, pos, "channel list")
        if pos + 16 > len(raw):
            raise ExrError("channel list: cut short")
        pixel_type, _linear, xs, ys = struct.unpack_from("<iB3xii", raw, pos)
        pos += 16
        if pixel_type not in _PIXEL_TYPES:
            raise ExrError(f"channel {name}: unknown pixel type {pixel_type}")
        if xs != 1 or ys != 1:
            raise ExrError(f"channel {name}: subsampled channels are not read here")
        channels.append((name, _PIXEL_TYPES[pixel_type]))
    return channels


def _undo_zip(block, raw_size):
    # ZIP/ZIPS: zlib over bytes that were split into even and odd halves and
    # delta-coded (each byte stored as the difference to the one before + 128).
    t = np.frombuffer(zlib.decompress(block, bufsize=raw_size), np.uint8)
    if t.size != raw_size:
        raise ExrError(f"a block inflates to {t.size} bytes, not {raw_size}")
    d = t.astype(np.int64)
    d[1:] -= 128
    t = (np.cumsum(d) & 0xFF).astype(np.uint8)
    half = (raw_size + 1) // 2
    out = np.empty(raw_size, np.uint8)
    out[0::2] = t[:half]
    out[1::2] = t[half:]
    return out.tobytes()


def read(path):
    """Reads the EXR at `path` into an ExrFrame; raises ExrError naming what
    it cannot read."""
    with open(path, "rb") as f:
        data = f.read()
    if len(data) < 8 or struct.unpack_from("<i", data, 0)[0] != _MAGIC:
        raise ExrError(f"{path}: not an OpenEXR file")
    version = data[4]
    flags = struct.unpack_from("<I", data, 4)[0] >> 8
    if version != 2 or flags & ~0x4:  # 0x4: long names; tiled, deep and multi-part are not read here
        raise ExrError(f"{path}: not a single-part scanline EXR (version {version}, flags {flags:#x})")
    pos, header, kinds = 8, {}, {}
    while True:
        if pos >= len(data):
            raise ExrError(f"{path}: the header is cut short")
        if data[pos] == 0:
            pos += 1
            break
        name, pos = _cstring(data, pos, f"{path}: header")
        kind, pos = _cstring(data, pos, f"{path}: header")
        if pos + 4 > len(data):
            raise ExrError(f"{path}: the header is cut short")
        (size,) = struct.unpack_from("<i", data, pos)
        pos += 4
        if size < 0 or pos + size > len(data):
            raise ExrError(f"{path}: attribute {name} claims {size} bytes")
        raw = data[pos : pos + size]
        pos += size
        kinds[name] = kind
        header[name] = _channel_list(raw) if kind == "chlist" else _attribute_value(kind, raw)
    for required in ("channels", "compression", "dataWindow"):
        if required not in header:
            raise ExrError(f"{path}: no {required} attribute")
    compression = header["compression"]
    if compression not in _COMPRESSIONS:
        raise ExrError(f"{path}: compression {compression} is not read here (only none, zips, zip)")
    x0, y0, x1, y1 = header["dataWindow"]
    width, height = x1 - x0 + 1, y1 - y0 + 1
    if not (0 < width <= _MAX_SIDE and 0 < height <= _MAX_SIDE):
        raise ExrError(f"{path}: data window {width}x{height} out of range")
    channels = header["channels"]
    lines = _COMPRESSIONS[compression][1]
    blocks = (height + lines - 1) // lines
    if pos + 8 * blocks > len(data):
        raise ExrError(f"{path}: the offset table is cut short")
    offsets = struct.unpack_from(f"<{blocks}Q", data, pos)
    line_bytes = sum(width * dt.itemsize for _, dt in channels)
    planes = {name: np.empty((height, width), dt) for name, dt in channels}
    for offset in offsets:
        if offset + 8 > len(data):
            raise ExrError(f"{path}: a block lies beyond the file's end")
        y, size = struct.unpack_from("<ii", data, offset)
        first = y - y0
        count = min(lines, height - first)
        if not (0 <= first < height) or size < 0 or offset + 8 + size > len(data):
            raise ExrError(f"{path}: a damaged block at offset {offset}")
        raw_size = count * line_bytes
        block = data[offset + 8 : offset + 8 + size]
        # A block that did not shrink is stored as it is.
        raw = block if compression == 0 or size == raw_size else _undo_zip(block, raw_size)
        if len(raw) != raw_size:
            raise ExrError(f"{path}: a block of {len(raw)} bytes, not {raw_size}")
        at = 0
        for row in range(first, first + count):
            for name, dt in channels:  # each scanline: every channel's row in turn
                n = width * dt.itemsize
                planes[name][row] = np.frombuffer(raw, dt, width, at)
                at += n
    for name in planes:
        if planes[name].dtype != np.uint32:
            planes[name] = planes[name].astype(np.float32)
    header.pop("channels")
    return ExrFrame(width, height, planes, header)
