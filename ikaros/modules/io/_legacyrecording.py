"""Recordings of format 1 and 2, written before checksums: their text (model, signals,
parameters) is in HDF5 variable-length strings, kept in global heap collections that have
no checksum, and HDF5 reads a damaged collection wrongly or forever (an object whose size
is 0 makes its reader loop at full speed, deaf to Ctrl-C). So the collections are checked
here, by the HDF5 file format specification ("Global Heap"), before HDF5 reads them."""
import json
import mmap
import struct

SIGNATURE = b"GCOL"
HEADER = 16             # signature, version, reserved, collection size
OBJECT_HEADER = 16      # index, reference count, reserved, size
TEXT_ATTRIBUTES = ("model_file", "top_group", "created", "ikaros_version")
JSON_ATTRIBUTES = ("command_line", "signals", "parameters", "seeds")


def heap_damage(path: str, end: int) -> str | None:
    """What is wrong with the first global heap collection that is not whole and
    consistent among the file's bytes before ``end`` (where its values begin), or None."""
    with open(path, "rb") as f:
        if end <= 0:
            return None
        with mmap.mmap(f.fileno(), 0, access=mmap.ACCESS_READ) as data:
            size = len(data)
            at = data.find(SIGNATURE, 0, end)
            while at >= 0:
                if at + HEADER > size:
                    return f"its global heap at byte {at} is cut off"
                version, = struct.unpack_from("<B", data, at + 4)
                length, = struct.unpack_from("<Q", data, at + 8)
                if version != 1 or length < HEADER or at + length > size:
                    return f"its global heap at byte {at} has a wrong header"
                wrong = _objects_damage(data, at, at + length)
                if wrong:
                    return f"its global heap at byte {at} {wrong}"
                at = data.find(SIGNATURE, at + length, end)
    return None


def _objects_damage(data, start: int, end: int) -> str | None:
    """Whether the objects of one collection tile it (each within it, the free space at
    least its own header), as HDF5's reader needs them to."""
    p = start + HEADER
    while end - p >= OBJECT_HEADER:
        index, _, _, size = struct.unpack_from("<HHIQ", data, p)
        need = size if index == 0 else OBJECT_HEADER + -(-size // 8) * 8
        if need < OBJECT_HEADER or p + need > end:
            return f"has an object of a wrong size at byte {p}"
        p += need
    return None


def text_length_damage(path: str, offset: int | None, size: int) -> str | None:
    """A variable-length string's length (its first 4 bytes at ``offset``) that is longer
    than the file (HDF5 would read it for minutes)."""
    if offset is None:
        return None
    with open(path, "rb") as f:
        f.seek(offset)
        length = int.from_bytes(f.read(4), "little")
    return f"its model text says it is {length} bytes long" if length > size else None


def header(attrs) -> dict:
    """The header of a format 1 or 2 recording, from its attributes."""
    out = {key: str(attrs[key]) for key in TEXT_ATTRIBUTES}
    out.update({key: json.loads(attrs[key]) for key in JSON_ATTRIBUTES})
    return out
