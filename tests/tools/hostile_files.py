"""Hostile OpenVDB files made by code, as the fuzzers found them: a good fog
volume written by isoform itself, then one field changed. Shared by the CLI
test (test_cli_hostile.py) and the Blender add-on test (in_blender.py)."""
import os
import struct
import subprocess


def fog_vdb_bytes(cli, folder):
    """A 32^3 fog volume of varying values written by `cli convert`; its bytes
    (the files made on the way are removed)."""
    raw = os.path.join(folder, "fog.raw")
    vdb = os.path.join(folder, "fog.vdb")
    with open(raw, "wb") as f:
        f.write(struct.pack("<32768f", *[float((i * 7919) % 97) for i in range(32768)]))
    subprocess.run([cli, "convert", raw, "--dims", "32,32,32", "--type", "f32", "-o", vdb],
                   check=True, capture_output=True)
    with open(vdb, "rb") as f:
        data = bytearray(f.read())
    os.remove(raw)
    os.remove(vdb)
    return data


def leaf_chunk(data):
    """Where the first leaf's blosc chunk size lies: an int64 n, then a blosc
    header saying 2,048 bytes decoded from n."""
    for at in range(len(data) - 24):
        n = struct.unpack_from("<q", data, at)[0]
        if 16 < n < 100000 and data[at + 8] == 2 and struct.unpack_from("<I", data, at + 12)[0] == 2048 \
                and struct.unpack_from("<I", data, at + 20)[0] == n:
            return at
    raise ValueError("no leaf chunk in the fog volume")


def string_at(data, text, start=0):
    """Where the length field of the length-prefixed string text lies."""
    at = data.find(struct.pack("<I", len(text)) + text.encode(), start)
    if at < 0:
        raise ValueError(f"no string {text!r}")
    return at


def _negative_chunk(d):  # OpenVDB's bloscFromStream would write 100,000 bytes into 2,048
    struct.pack_into("<q", d, leaf_chunk(d), -100000)


def _huge_chunk(d):  # a petabyte new[]
    struct.pack_into("<q", d, leaf_chunk(d), 10 ** 15)


def _huge_type_name(d):  # GridDescriptor::read would allocate 7.5 GB
    struct.pack_into("<I", d, string_at(d, "density") + 4 + 7, 1918107664)


def _huge_metadata_string(d):  # StringMetadata::readValue would allocate 2 GB
    struct.pack_into("<I", d, string_at(d, "string", string_at(d, "class")) + 10, 2000000000)


def _lying_blosc_header(d):
    struct.pack_into("<I", d, leaf_chunk(d) + 12, 4096)


# name: (change, what the error says)
HOSTILE_VDBS = {
    "negative_chunk": (_negative_chunk, "a raw chunk of 100000 bytes where 2048 are expected"),
    "huge_chunk": (_huge_chunk, "a compressed chunk at byte"),
    "huge_type_name": (_huge_type_name, "a grid type name at byte"),
    "huge_metadata_string": (_huge_metadata_string, "a metadata value at byte"),
    "lying_blosc_header": (_lying_blosc_header, "whose header says 4096 bytes"),
}


def write_hostile_vdbs(cli, folder):
    """Writes every hostile VDB into folder; returns {path: message}."""
    good = fog_vdb_bytes(cli, folder)
    files = {}
    for name, (change, message) in HOSTILE_VDBS.items():
        data = bytearray(good)
        change(data)
        path = os.path.join(folder, name + ".vdb")
        with open(path, "wb") as f:
            f.write(data)
        files[path] = message
    return files
