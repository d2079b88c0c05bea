"""What a mesh costs in volume (docs/accuracy.md): `kerf measure` of the
exact solid against the volume of OpenSCAD's STL of the same .scad model at
`$fn = 64` and `$fn = 256`, and the closed form where one exists. The
examples are turned into .scad files by dropping kerf's camera and light
statements and writing `material(...)` as `color(...)`.

    python3 bench/measure_openscad.py --kerf build/kerf
"""
import argparse
import math
import os
import re
import struct
import subprocess
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))

# name -> (.scad source or an example to convert, closed-form volume or None)
MODELS = {
    "sphere": ("sphere(r = 10);", 4000 * math.pi / 3),
    # Pappus: 2 pi R * pi r^2.
    "torus": ("rotate_extrude() translate([6, 0]) circle(r = 2);",
              2 * math.pi ** 2 * 6 * 2 ** 2),
    # The cube less the sphere inside it: the ball less its six caps of
    # height 2 (caps do not meet: the edges are 14.1 from the centre).
    "cube - sphere": ("difference() { cube(20, center = true); sphere(r = 12); }",
                      8000 - (4 * math.pi * 12 ** 3 / 3 - 6 * math.pi * 2 ** 2 * (3 * 12 - 2) / 3)),
    "examples/gear.sdl": ("examples/gear.sdl", None),
    "examples/vase.sdl": ("examples/vase.sdl", None),
}


def scad_of(source):
    if not source.startswith("examples/"):
        return source
    text = open(os.path.join(ROOT, source)).read()
    text = re.sub(r"^(camera|light)\(.*\n", "", text, flags=re.M)
    return re.sub(r"^material\([^)]*\)", 'color("gold")', text, flags=re.M)


def stl_triangles(path):
    data = open(path, "rb").read()
    if data[:5] == b"solid":
        vertices = [tuple(map(float, line.split()[1:4]))
                    for line in data.decode().splitlines() if line.split()[:1] == ["vertex"]]
        return [vertices[i:i + 3] for i in range(0, len(vertices), 3)]
    count = struct.unpack("<I", data[80:84])[0]
    out = []
    for i in range(count):
        v = struct.unpack("<12f", data[84 + 50 * i:84 + 50 * i + 48])
        out.append([v[3:6], v[6:9], v[9:12]])
    return out


def mesh_volume(path):
    """Sum of signed tetrahedra from the origin: exact for a closed mesh."""
    total = 0.0
    for a, b, c in stl_triangles(path):
        total += (a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0])
                  + a[2] * (b[0] * c[1] - b[1] * c[0])) / 6
    return total


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--kerf", default=os.path.join(ROOT, "build", "kerf"))
    parser.add_argument("--openscad", default="openscad")
    parser.add_argument("--resolution", type=int, default=2048)
    args = parser.parse_args()
    print("| model | closed form | kerf measure | OpenSCAD $fn=64 | OpenSCAD $fn=256 |")
    print("|---|---|---|---|---|")
    with tempfile.TemporaryDirectory() as tmp:
        for name, (source, exact) in MODELS.items():
            scad = os.path.join(tmp, "model.scad")
            open(scad, "w").write(scad_of(source))
            meshes = []
            for fn in (64, 256):
                stl = os.path.join(tmp, f"model_{fn}.stl")
                subprocess.run([args.openscad, "-q", "-D", f"$fn={fn}", "-o", stl, scad], check=True)
                meshes.append(mesh_volume(stl))
            out = subprocess.run([args.kerf, "measure", scad, "--resolution", str(args.resolution)],
                                 check=True, capture_output=True, text=True).stdout
            volume = re.search(r"volume: (\S+) ± (\S+)", out)
            kerf, error = float(volume.group(1)), volume.group(2)
            closed = f"{exact:.3f}" if exact is not None else "—"
            # The mesh's error against the closed form, or against kerf without one.
            reference = exact if exact is not None else kerf
            cells = " | ".join(f"{v:.3f} ({(v - reference) / reference:+.2%})" for v in meshes)
            print(f"| {name} | {closed} | {kerf:.3f} ± {error} | {cells} |")


if __name__ == "__main__":
    main()
