#!/usr/bin/python3
"""A stack and boxes rendered by Blender headless from isoform's PLY files.

usage: test_render.py ISOFORM_BINARY RENDER_SCRIPT

Exits 77 (CTest's skip code here) when blender is not installed. Otherwise
writes a small Gaussians volume, runs `isoform stack` and `isoform boxes`,
renders each with samples/render/render_ply.py, and checks that the picture
exists with the asked size and that the object covers its middle (the middle
pixel differs from the background in the corner).
"""
import os
import shutil
import struct
import subprocess
import sys
import tempfile
import zlib

sys.dont_write_bytecode = True  # no __pycache__ in the source tree
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import test_cli as base  # noqa: E402
import test_visualize_cli as vis  # noqa: E402

SKIP = 77


def decode_png_rgb(path):
    """(width, height, rows of (r, g, b)) of an 8-bit RGB or RGBA PNG."""
    with open(path, "rb") as f:
        blob = f.read()
    offset, idat, header = 8, b"", None
    while offset < len(blob):
        (length,) = struct.unpack_from(">I", blob, offset)
        kind, body = blob[offset + 4:offset + 8], blob[offset + 8:offset + 8 + length]
        if kind == b"IHDR":
            header = struct.unpack(">IIBBBBB", body)
        elif kind == b"IDAT":
            idat += body
        offset += 12 + length
    width, height, depth, colour = header[:4]
    if depth != 8 or colour not in (2, 6):
        raise SystemExit(f"{path}: not 8-bit RGB(A)")
    channels = 3 if colour == 2 else 4
    raw, stride, rows, previous = zlib.decompress(idat), width * channels, [], bytearray(width * channels)
    for y in range(height):
        kind, line = raw[y * (stride + 1)], bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        for i in range(stride):
            left = line[i - channels] if i >= channels else 0
            up, corner = previous[i], previous[i - channels] if i >= channels else 0
            if kind == 1:
                line[i] = (line[i] + left) & 255
            elif kind == 2:
                line[i] = (line[i] + up) & 255
            elif kind == 3:
                line[i] = (line[i] + (left + up) // 2) & 255
            elif kind == 4:
                p = left + up - corner
                pa, pb, pc = abs(p - left), abs(p - up), abs(p - corner)
                line[i] = (line[i] + (left if pa <= pb and pa <= pc else up if pb <= pc else corner)) & 255
        rows.append([tuple(line[x * channels:x * channels + 3]) for x in range(width)])
        previous = line
    return width, height, rows


def main():
    if len(sys.argv) != 3:
        sys.exit(f"usage: {sys.argv[0]} ISOFORM_BINARY RENDER_SCRIPT")
    blender = shutil.which("blender")
    if not blender:
        print("blender is not installed: skipped")
        sys.exit(SKIP)
    base.BINARY = os.path.abspath(sys.argv[1])
    script = sys.argv[2]
    with tempfile.TemporaryDirectory(prefix="isoform-render-") as tmp:
        vdb = vis.make_gaussians(tmp)
        stack, boxes = os.path.join(tmp, "stack.ply"), os.path.join(tmp, "boxes.ply")
        base.run("stack", vdb, "--n", "4", "--t", "0.5", "--view", "-1,-1,-1", "-o", stack)
        base.run("boxes", vdb, "--q", "3", "--gap", "1", "-o", boxes)
        for ply in (stack, boxes):
            png = ply[:-4] + ".png"
            proc = subprocess.run([blender, "-b", "--factory-startup", "--python-exit-code", "1",
                                   "--python", script, "--", ply, png, "--size", "96,72",
                                   "--samples", "4"], capture_output=True, text=True, timeout=300)
            if proc.returncode != 0 or not os.path.isfile(png):
                sys.exit(f"blender failed on {ply} (exit {proc.returncode}):\n{proc.stdout[-2000:]}\n{proc.stderr[-2000:]}")
            width, height, rows = decode_png_rgb(png)
            if (width, height) != (96, 72):
                sys.exit(f"{png} is {width} x {height}, expected 96 x 72")
            middle, corner = rows[36][48], rows[0][0]
            if max(abs(a - b) for a, b in zip(middle, corner)) < 10:
                sys.exit(f"{png}: the middle {middle} looks like the background {corner}")
            print(f"PASS {os.path.basename(png)}: middle {middle}, background {corner}")


if __name__ == "__main__":
    main()
