#!/usr/bin/env python3
# Writes the test images of test_surface.cpp (standard library only):
# small PNGs whose decoded samples the tests know, each a different
# encoding surface() must read as OpenSCAD 2021.01 does.
import struct
import zlib


def chunk(kind, data):
    return struct.pack('>I', len(data)) + kind + data + struct.pack('>I', zlib.crc32(kind + data) & 0xffffffff)


def png(path, width, height, rows, color_type, depth=8, palette=None):
    raw = b''.join(b'\x00' + r for r in rows)  # filter 0 on every row
    data = b'\x89PNG\r\n\x1a\n' + chunk(b'IHDR', struct.pack('>IIBBBBB', width, height, depth, color_type, 0, 0, 0))
    if palette:
        data += chunk(b'PLTE', palette)
    data += chunk(b'IDAT', zlib.compress(raw)) + chunk(b'IEND', b'')
    with open(path, 'wb') as f:
        f.write(data)


# 3 x 2 RGBA: alpha (0, 128, 255, 10) must not change the heights.
png('rgba8.png', 3, 2, [bytes([255, 0, 0, 0, 0, 255, 0, 128, 0, 0, 255, 255]),
                        bytes([10, 20, 30, 10, 200, 100, 50, 255, 255, 255, 255, 0])], 6)
# 2 x 3 grey, 16 bits: a sample's high byte counts (0x80ff is 128, not 129).
png('grey16.png', 2, 3, [struct.pack('>HH', 0x1234, 0xffff), struct.pack('>HH', 0x80ff, 0x0001),
                         struct.pack('>HH', 0x00ff, 0x4000)], 0, 16)
# 3 x 3 palette, 4 bits per index.
png('palette4.png', 3, 3, [bytes([0x01, 0x20]), bytes([0x12, 0x00]), bytes([0x21, 0x10])], 3, 4,
    bytes([10, 20, 30, 100, 150, 200, 255, 0, 128]))
