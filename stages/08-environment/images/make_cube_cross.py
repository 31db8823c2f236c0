#!/usr/bin/env python3
"""Draws cube_cross.svg for docs/conventions.md#environment-maps: the six faces of a cube map
unfolded into OpenGL's horizontal cross, each face as its file stores it (u to the right, v
down, (0, 0) marked), with the world axis u and v run along. The axes come from the same table
as stage08.h (OpenGL's "Cube Map Texture Selection"), so the picture cannot disagree with it.
Run: python3 make_cube_cross.py"""

# face: (name, colour, sc axis, tc axis): u = (sc/|ma| + 1)/2, v = (tc/|ma| + 1)/2
TABLE = {
    "+x": ("px", "#cc3333", "-z", "-y"), "-x": ("nx", "#33b3b3", "+z", "-y"),
    "+y": ("py", "#4d80e6", "+x", "+z"), "-y": ("ny", "#734d26", "+x", "-z"),
    "+z": ("pz", "#d9cc33", "+x", "-y"), "-z": ("nz", "#b34dcc", "-x", "-y"),
}
# Cross cells (column, row): the middle row -x +z +x -z, +y above +z, -y below it.
CELLS = {"-x": (0, 1), "+z": (1, 1), "+x": (2, 1), "-z": (3, 1), "+y": (1, 0), "-y": (1, 2)}
S, M = 120, 20  # face size, margin

out = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{4 * S + 2 * M}" height="{3 * S + 2 * M + 40}" '
       'font-family="sans-serif">',
       '<defs><marker id="a" markerWidth="8" markerHeight="8" refX="6" refY="3" orient="auto">'
       '<path d="M0,0 L6,3 L0,6 z" fill="black"/></marker></defs>',
       f'<rect width="100%" height="100%" fill="white"/>']
for face, (name, colour, sc, tc) in TABLE.items():
    c, r = CELLS[face]
    x, y = M + c * S, M + r * S
    out.append(f'<rect x="{x}" y="{y}" width="{S}" height="{S}" fill="{colour}" stroke="black"/>')
    out.append(f'<rect x="{x + 4}" y="{y + 4}" width="10" height="10" fill="black"/>')
    out.append(f'<text x="{x + S / 2}" y="{y + S / 2 + 4}" font-size="26" text-anchor="middle" '
               f'fill="white">{face.upper()}</text>')
    out.append(f'<text x="{x + S / 2}" y="{y + S / 2 + 24}" font-size="12" text-anchor="middle" '
               f'fill="white">{name}.png</text>')
    # u along the top edge, v down the left edge, labelled with the world axis they follow.
    out.append(f'<line x1="{x + 20}" y1="{y + 12}" x2="{x + S - 12}" y2="{y + 12}" stroke="black" '
               'stroke-width="1.5" marker-end="url(#a)"/>')
    out.append(f'<text x="{x + S - 14}" y="{y + 28}" font-size="12" text-anchor="end">u: {sc}</text>')
    out.append(f'<line x1="{x + 9}" y1="{y + 20}" x2="{x + 9}" y2="{y + S - 12}" stroke="black" '
               'stroke-width="1.5" marker-end="url(#a)"/>')
    out.append(f'<text x="{x + 14}" y="{y + S - 10}" font-size="12">v: {tc}</text>')
out.append(f'<text x="{M}" y="{3 * S + M + 18}" font-size="13">Each face as its file stores it, '
           'seen from outside the cube; from inside (y up, right-handed)</text>')
out.append(f'<text x="{M}" y="{3 * S + M + 36}" font-size="13">every face appears mirrored '
           'left-right. Black square: (u, v) = (0, 0), the first texel.</text>')
out.append('</svg>')
open("cube_cross.svg", "w").write("\n".join(out) + "\n")

# cube_cross.png: the committed face files themselves, unfolded the same way (4x enlarged).
import struct
import zlib


def read_png(path):  # 8-bit RGB or RGBA, not interlaced (what the framework writes)
    data = open(path, "rb").read()
    pos, idat, w = 8, b"", 0
    while pos < len(data):
        n, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + n]
        if kind == b"IHDR":
            w, h, depth, ctype = struct.unpack(">IIBB", body[:10])
            ch = {2: 3, 6: 4}[ctype]
        elif kind == b"IDAT":
            idat += body
        pos += 12 + n
    raw, rows, prev, stride = zlib.decompress(idat), [], bytearray(w * ch), w * ch
    for j in range(h):
        f, line = raw[j * (stride + 1)], bytearray(raw[j * (stride + 1) + 1:(j + 1) * (stride + 1)])
        for i in range(stride):
            a = line[i - ch] if i >= ch else 0
            b, c = prev[i], prev[i - ch] if i >= ch else 0
            p = a + b - c
            pred = [0, a, b, (a + b) // 2,
                    a if abs(p - a) <= abs(p - b) and abs(p - a) <= abs(p - c) else b if abs(p - b) <= abs(p - c) else c][f]
            line[i] = (line[i] + pred) & 255
        rows.append([tuple(line[i * ch:i * ch + 3]) for i in range(w)])
        prev = line
    return rows


def write_png(path, rows):
    h, w = len(rows), len(rows[0])
    raw = b"".join(b"\0" + bytes(v for px in row for v in px) for row in rows)

    def chunk(kind, body):
        return struct.pack(">I", len(body)) + kind + body + struct.pack(">I", zlib.crc32(kind + body))
    open(path, "wb").write(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", w, h, 8, 2, 0, 0, 0))
                           + chunk(b"IDAT", zlib.compress(raw, 9)) + chunk(b"IEND", b""))


Z, N = 4, 32
canvas = [[(255, 255, 255)] * (4 * N * Z) for _ in range(3 * N * Z)]
for face, (name, _, _, _) in TABLE.items():
    c, r = CELLS[face]
    pixels = read_png(f"../scenes/cube/{name}.png")
    for j in range(N * Z):
        for i in range(N * Z):
            canvas[r * N * Z + j][c * N * Z + i] = pixels[j // Z][i // Z]
write_png("cube_cross.png", canvas)
