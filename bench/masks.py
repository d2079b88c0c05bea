"""Object masks from the two renderers' silhouette images, and their IoU.

kerf writes its depth AOV as an 8-bit PNM (misses 0, hits at least 0.2 of
full scale); POV-Ray's Mask variant is a white object on black. Both are
read as binary PNM (P5/P6) so no image library is needed.
"""


def read_pnm(path):
    """(width, height, channels, bytes) of a binary 8-bit P5/P6 file."""
    data = open(path, "rb").read()
    fields, pos = [], 0
    while len(fields) < 4:  # magic, width, height, maxval; '#' comments allowed
        while data[pos:pos + 1].isspace():
            pos += 1
        if data[pos:pos + 1] == b"#":
            pos = data.index(b"\n", pos) + 1
            continue
        end = pos
        while not data[end:end + 1].isspace():
            end += 1
        fields.append(data[pos:end])
        pos = end
    magic, w, h, maxval = fields[0], int(fields[1]), int(fields[2]), int(fields[3])
    if magic not in (b"P5", b"P6") or maxval > 255:
        raise ValueError(f"{path}: not an 8-bit binary PNM ({magic!r}, maxval {maxval})")
    ch = 1 if magic == b"P5" else 3
    pixels = data[pos + 1:pos + 1 + w * h * ch]
    if len(pixels) != w * h * ch:
        raise ValueError(f"{path}: truncated")
    return w, h, ch, pixels


def mask(path, threshold=25):
    """Set of object pixels: any channel above threshold (of 255)."""
    w, h, ch, px = read_pnm(path)
    # Taking the first channel is enough: both masks are grey.
    return w, h, bytes(1 if v > threshold else 0 for v in px[::ch])


def iou(path_a, path_b):
    wa, ha, a = mask(path_a)
    wb, hb, b = mask(path_b)
    if (wa, ha) != (wb, hb):
        raise ValueError(f"mask sizes differ: {wa}x{ha} vs {wb}x{hb}")
    both = sum(x & y for x, y in zip(a, b))
    either = sum(x | y for x, y in zip(a, b))
    return 1.0 if either == 0 else both / either, sum(a), sum(b)
