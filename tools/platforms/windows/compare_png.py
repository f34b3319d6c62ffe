#!/usr/bin/env python3
"""Compare two PNGs pixel by pixel (python3 standard library only: zlib + struct).

usage: compare_png.py A.png B.png [--threshold 2]
Prints the size, mean absolute difference per channel (0..255), the max difference per channel,
and how many pixels differ by more than THRESHOLD/255 in any channel. Exit 0 if sizes match.
Reads 8-bit greyscale, grey+alpha, RGB, RGBA (non-interlaced), and 8-bit palette PNGs.
"""
import struct
import sys
import zlib


def read_png(path):
    data = open(path, "rb").read()
    if data[:8] != b"\x89PNG\r\n\x1a\n":
        raise ValueError(f"{path}: not a PNG")
    pos, idat, palette = 8, [], None
    width = height = depth = ctype = interlace = None
    while pos < len(data):
        (length,) = struct.unpack(">I", data[pos:pos + 4])
        kind = data[pos + 4:pos + 8]
        body = data[pos + 8:pos + 8 + length]
        pos += 12 + length
        if kind == b"IHDR":
            width, height, depth, ctype, _, _, interlace = struct.unpack(">IIBBBBB", body)
        elif kind == b"PLTE":
            palette = [tuple(body[i:i + 3]) for i in range(0, len(body), 3)]
        elif kind == b"IDAT":
            idat.append(body)
        elif kind == b"IEND":
            break
    if depth != 8 or interlace != 0:
        raise ValueError(f"{path}: only 8-bit non-interlaced PNGs (depth {depth}, interlace {interlace})")
    channels = {0: 1, 2: 3, 3: 1, 4: 2, 6: 4}[ctype]
    raw = zlib.decompress(b"".join(idat))
    stride = width * channels
    rows, prev, p = [], bytearray(stride), 0
    for _ in range(height):
        f = raw[p]
        line = bytearray(raw[p + 1:p + 1 + stride])
        p += 1 + stride
        for i in range(stride):
            a = line[i - channels] if i >= channels else 0
            b = prev[i]
            c = prev[i - channels] if i >= channels else 0
            if f == 1:
                line[i] = (line[i] + a) & 255
            elif f == 2:
                line[i] = (line[i] + b) & 255
            elif f == 3:
                line[i] = (line[i] + ((a + b) >> 1)) & 255
            elif f == 4:
                pa, pb, pc = abs(b - c), abs(a - c), abs(a + b - 2 * c)
                pred = a if pa <= pb and pa <= pc else (b if pb <= pc else c)
                line[i] = (line[i] + pred) & 255
        rows.append(line)
        prev = line
    # to RGBA
    pixels = []
    for line in rows:
        for x in range(width):
            px = line[x * channels:(x + 1) * channels]
            if ctype == 0:
                pixels.append((px[0], px[0], px[0], 255))
            elif ctype == 4:
                pixels.append((px[0], px[0], px[0], px[1]))
            elif ctype == 2:
                pixels.append((px[0], px[1], px[2], 255))
            elif ctype == 6:
                pixels.append(tuple(px))
            else:
                r, g, b = palette[px[0]]
                pixels.append((r, g, b, 255))
    return width, height, pixels


def main():
    args = sys.argv[1:]
    threshold = 2
    if "--threshold" in args:
        k = args.index("--threshold")
        threshold = int(args[k + 1])
        del args[k:k + 2]
    if len(args) != 2:
        print(__doc__)
        return 2
    wa, ha, pa = read_png(args[0])
    wb, hb, pb = read_png(args[1])
    print(f"A: {args[0]} {wa}x{ha}")
    print(f"B: {args[1]} {wb}x{hb}")
    if (wa, ha) != (wb, hb):
        print("sizes differ: no pixel comparison")
        return 1
    n = wa * ha
    total = [0, 0, 0, 0]
    peak = [0, 0, 0, 0]
    over = 0
    identical = 0
    for a, b in zip(pa, pb):
        d = [abs(a[c] - b[c]) for c in range(4)]
        for c in range(4):
            total[c] += d[c]
            peak[c] = max(peak[c], d[c])
        m = max(d)
        if m > threshold:
            over += 1
        if m == 0:
            identical += 1
    names = "RGBA"
    print("mean abs diff (0..255): " + "  ".join(f"{names[c]} {total[c] / n:.4f}" for c in range(4)))
    print("max diff (0..255):      " + "  ".join(f"{names[c]} {peak[c]}" for c in range(4)))
    print(f"pixels differing by > {threshold}/255 in any channel: {over} of {n} ({100.0 * over / n:.3f}%)")
    print(f"pixels identical: {identical} of {n} ({100.0 * identical / n:.3f}%)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
