"""Benchmark scenes, each written twice from one description: as kerf .sdl
and as an equivalent POV-Ray 3.7 .pov, so both renderers see the same model.

A scene is a small tree (prim / op / xf / loop). Loops stay loops in both
languages (a 10^6-sphere scene is a few lines, not 60 MB), and expressions
are strings that read the same in both (numbers, loop variables, + - * /,
pow()).

Coordinates: kerf is right-handed with +Z up (OpenSCAD); POV-Ray is
left-handed with +Y up. The POV file keeps every number of the kerf scene
and maps the whole world through (x, y, z) -> (x, z, y). Swapping two axes
flips handedness, so the kerf world seen through that map in POV-Ray's
left-handed frame is the same picture, not its mirror image. (POV-Ray's
rotate/scale/translate matrices are numerically the usual ones, so
transforms written inside the mapped object need no change.)
"""
import math
from dataclasses import dataclass, field


# ---------------------------------------------------------------- the tree
def prim(kind, **args):
    return ("prim", kind, args)


def op(kind, *children):
    return ("op", kind, list(children))


def xf(transforms, child):
    """transforms in SDL order: [("translate", v), ("rotate", v)] means
    translate(v) rotate(v) child, i.e. the last one applies first."""
    return ("xf", transforms, child)


def loop(ranges, child):
    """ranges: [(var, lo, hi)], inclusive like both languages' loops; the
    iterations form one union."""
    return ("loop", ranges, child)


def count_prims(node):
    tag = node[0]
    if tag == "prim":
        return 1
    if tag == "op":
        return sum(count_prims(c) for c in node[2])
    if tag == "xf":
        return count_prims(node[2])
    n = 1
    for _, lo, hi in node[1]:
        n *= hi - lo + 1
    return n * count_prims(node[2])


def as_union(node):
    """The same leaves with every operation replaced by union (the CSG tax)."""
    tag = node[0]
    if tag == "prim":
        return node
    if tag == "op":
        return ("op", "union", [as_union(c) for c in node[2]])
    if tag == "xf":
        return ("xf", node[1], as_union(node[2]))
    return ("loop", node[1], as_union(node[2]))


def num(x):
    return x if isinstance(x, str) else repr(float(x)) if not float(x).is_integer() else str(int(x))


# ---------------------------------------------------------------- SDL
def sdl_vec(v):
    return "[" + ", ".join(num(c) for c in v) + "]"


def sdl_prim(kind, a):
    if kind == "sphere":
        return f"sphere({num(a['r'])});"
    if kind == "cube":
        return f"cube({sdl_vec(a['size'])});"
    if kind == "cylinder":
        return f"cylinder(h = {num(a['h'])}, r = {num(a['r'])});"
    if kind == "cone":
        return f"cone(h = {num(a['h'])}, r = {num(a['r'])});"
    if kind == "torus":
        return f"torus(R = {num(a['R'])}, r = {num(a['r'])});"
    raise ValueError(kind)


def sdl_xf(name, v):
    if name == "scale" and isinstance(v, (str, int, float)):
        return f"scale({num(v)})"
    return f"{name}({sdl_vec(v)})"


def to_sdl(node, ind="    "):
    tag = node[0]
    if tag == "prim":
        return ind + sdl_prim(node[1], node[2]) + "\n"
    if tag == "op":
        body = "".join(to_sdl(c, ind + "    ") for c in node[2])
        return f"{ind}{node[1]}() {{\n{body}{ind}}}\n"
    if tag == "xf":
        head = " ".join(sdl_xf(n, v) for n, v in node[1])
        return f"{ind}{head}\n" + to_sdl(node[2], ind + "    ")
    ranges = ", ".join(f"{v} = [{lo}:{hi}]" for v, lo, hi in node[1])
    return f"{ind}for ({ranges})\n" + to_sdl(node[2], ind + "    ")


# ---------------------------------------------------------------- POV-Ray
def pov_vec(v):
    return "<" + ", ".join(num(c) for c in v) + ">"


def pov_prim(kind, a):
    if kind == "sphere":
        return f"sphere {{ <0, 0, 0>, {num(a['r'])}"
    if kind == "cube":
        return f"box {{ <0, 0, 0>, {pov_vec(a['size'])}"
    if kind == "cylinder":
        return f"cylinder {{ <0, 0, 0>, <0, 0, {num(a['h'])}>, {num(a['r'])}"
    if kind == "cone":
        return f"cone {{ <0, 0, 0>, {num(a['r'])}, <0, 0, {num(a['h'])}>, 0"
    if kind == "torus":  # POV-Ray's torus lies in XZ; kerf's in XY
        return f"torus {{ {num(a['R'])}, {num(a['r'])} rotate <90, 0, 0>"
    raise ValueError(kind)


def pov_xf(name, v):
    if name == "mirror":  # axis-aligned normals only, which is all we use
        return "scale " + pov_vec([-1 if float(c) != 0 else 1 for c in v])
    if name == "scale" and isinstance(v, (str, int, float)):
        return f"scale {num(v)}"
    return f"{name} {pov_vec(v)}"


def to_pov(node, ind="  ", bare_ok=False, xfs=()):
    """One POV object (or, when bare_ok, a loop's objects spliced into the
    parent CSG: right for union and for subtrahends of a difference).
    xfs: pending transforms (POV order) to put inside the object's braces."""
    tag = node[0]
    tail = "".join(" " + t for t in xfs)
    if tag == "prim":
        return f"{ind}{pov_prim(node[1], node[2])}{tail} }}\n"
    if tag == "xf":
        mine = [pov_xf(n, v) for n, v in reversed(node[1])]
        return to_pov(node[2], ind, False, tuple(mine) + tuple(xfs))
    if tag == "op":
        kids = []
        for i, c in enumerate(node[2]):
            splice = node[1] == "union" or (node[1] == "difference" and i > 0)
            kids.append(to_pov(c, ind + "  ", splice))
        return f"{ind}{node[1]} {{\n{''.join(kids)}{ind}{tail.strip()}\n{ind}}}\n" if xfs else \
            f"{ind}{node[1]} {{\n{''.join(kids)}{ind}}}\n"
    # loop
    heads = "".join(f"{ind}#for ({v}, {lo}, {hi})\n" for v, lo, hi in node[1])
    ends = "".join(f"{ind}#end\n" for _ in node[1])
    inner = heads + to_pov(node[2], ind + "  ", True) + ends
    if bare_ok and not xfs:
        return inner
    return f"{ind}union {{\n{inner}{ind}{tail.strip()}\n{ind}}}\n"


# ---------------------------------------------------------------- scenes
@dataclass
class Scene:
    name: str
    group: str        # "ref" (docs/spec.md §9 model), or a family name
    param: float      # the family's size parameter (for plots)
    tree: tuple
    camera: tuple     # (position, look_at, vertical fov)
    light: tuple
    note: str = ""
    prims: int = field(init=False)

    def __post_init__(self):
        self.prims = count_prims(self.tree)


COLOR = (0.8, 0.8, 0.8)


def sdl_text(s, union=False):
    (pos, at, fov), tree = s.camera, (as_union(s.tree) if union else s.tree)
    return (f"// {s.name}: generated by bench/scenes.py ({s.prims} primitives). {s.note}\n"
            f"camera(position = {sdl_vec(pos)}, look_at = {sdl_vec(at)}, fov = {num(fov)});\n"
            f"light(position = {sdl_vec(s.light)}, intensity = 1);\n"
            f"background([0.2, 0.2, 0.2]);\n"
            f"material(color = {sdl_vec(COLOR)}, diffuse = 0.8, specular = 0.2, shininess = 32)\n"
            + to_sdl(tree))


def swap(v):
    return (v[0], v[2], v[1])


def pov_text(s, width, height):
    pos, at, fov = s.camera
    hfov = math.degrees(2 * math.atan(math.tan(math.radians(fov / 2)) * width / height))
    return (f"// {s.name}: generated by bench/scenes.py ({s.prims} primitives). {s.note}\n"
            "// kerf's world (right-handed, Z up) mapped by (x,y,z) -> (x,z,y); see scenes.py.\n"
            "#version 3.7;\n"
            "global_settings { assumed_gamma 1.0 }\n"
            f"camera {{ perspective location {pov_vec(swap(pos))} right x*{num(width / height)} up y\n"
            f"         sky <0, 1, 0> angle {hfov!r} look_at {pov_vec(swap(at))} }}\n"
            "#ifdef (Mask)  // silhouette variant: white object on black, no light\n"
            "  background { rgb 0 }\n"
            "  #declare Look = texture { pigment { rgb 1 } finish { ambient 1 diffuse 0 } }\n"
            "#else\n"
            "  background { srgb 0.2 }  // kerf reads colours as sRGB\n"
            f"  light_source {{ {pov_vec(swap(s.light))} color rgb 1 }}\n"
            f"  #declare Look = texture {{ pigment {{ srgb {pov_vec(COLOR)} }}\n"
            "                            finish { ambient 0.1 diffuse 0.8 phong 0.2 phong_size 32 } }\n"
            "#end\n"
            "object {\n" + to_pov(s.tree) +
            "  texture { Look }\n"
            "  matrix <1, 0, 0,  0, 0, 1,  0, 1, 0,  0, 0, 0>\n"
            "}\n")


def grooved():
    groove = xf([("translate", (0, 0, 0.374)), ("scale", 0.9)], prim("torus", R=1, r=0.1))
    pair = op("union", groove, xf([("rotate", (0, 180, 0))], groove))
    tree = op("difference", prim("sphere", r=1), pair,
              xf([("rotate", (0, 90, 0))], pair), xf([("rotate", (90, 0, 0))], pair))
    return Scene("grooved_sphere", "ref", 7, tree, ((2.6, -2.6, 2.1), (0, 0, 0), 40), (4, -1, 6))


def checkered(k, group="ref"):
    p = 2.0 / k  # pitch; the spec's model is k = 5: 0.2 cubes 0.4 apart, centres at ±0.8
    small = xf([("translate", (f"{1 - p / 2!r} - {p!r}*i", f"{1 - p / 2!r} - {p!r}*j", 1.1)),
                ("scale", 1.0 / k), ("translate", (-0.5, -0.5, -0.5))], prim("cube", size=(1, 1, 1)))
    grid = loop([("j", 0, k - 1), ("i", 0, k - 1)], small)
    tree = op("difference",
              xf([("scale", 2.2), ("translate", (-0.5, -0.5, -0.5))], prim("cube", size=(1, 1, 1))),
              loop([("m", 0, 3)], xf([("rotate", ("90*m", 0, 0))], grid)),
              loop([("m", 0, 1)], xf([("rotate", (0, "90 + 180*m", 0))], grid)))
    name = "checkered_cube" if group == "ref" else f"checkered_k{k}"
    return Scene(name, group, k, tree, ((3.6, -4.2, 3.4), (0, 0, 0), 40), (5, -2, 7),
                 f"{k}x{k} small cubes per face, pitch 2/{k}, size 1/{k}.")


def small_shell():
    plane = lambda a: xf([("rotate", (0, 0, a)), ("scale", 10), ("translate", (0, -0.5, -0.5))],
                         prim("cube", size=(1, 1, 1)))
    seg = op("difference", xf([("translate", (0, -2, 0))], prim("sphere", r=1)),
             xf([("translate", (0, -2, 0)), ("scale", 0.95)], prim("sphere", r=1)), plane(18), plane(162))
    tree = loop([("k", 0, 15)], xf([("scale", "pow(0.93, k)"), ("rotate", (0, 0, "22.5*k"))], seg))
    return Scene("small_shell", "ref", 16, op("union", tree), ((5, -7.5, 7.5), (0.5, -0.65, 0), 40), (3, -4, 9))


def large_shell(n, group="ref"):
    """group "shell": N segments spread over the 65-segment model's spiral
    (same overall size, segments pile up as N grows); group "spiral": the
    spec's recurrence continued for N segments (rotZ 12 deg, scale 0.979 per
    segment: the same large segments, then ever smaller ones inside)."""
    s = 0.989227963463
    seg = xf([("translate", (3, 0, 0))], op(
        "difference", prim("sphere", r=1),
        xf([("scale", s), ("translate", (0, -0.02, 0))], prim("sphere", r=1)),
        xf([("scale", s), ("translate", (0, 0.02, 0))], prim("sphere", r=1))))
    spread = group == "shell"
    step, q = (12.0 * 65 / n, 0.979 ** (65.0 / n)) if spread else (12.0, 0.979)
    tree = loop([("k", 0, n - 1)], xf([("scale", f"pow({q!r}, k)"), ("rotate", (0, 0, f"{step!r}*k"))], seg))
    name = {"ref": "large_shell", "shell": f"shell_{n}", "spiral": f"spiral_{n}"}[group]
    how = (f"rotZ {step:.6g} deg and scale 0.979^(65/{n}) per segment (same spiral as 65)" if spread
           else "rotZ 12 deg and scale 0.979 per segment (the spec's recurrence, continued)")
    return Scene(name, group, n, op("union", tree), ((6, -9, 8), (0, 0, 0), 40), (4, -6, 10), f"{n} segments, {how}.")


def fishbowl():
    tree = op("difference",
              op("difference", prim("sphere", r=1), xf([("scale", 0.9)], prim("sphere", r=1))),
              xf([("translate", (0, 0, 1.2)), ("mirror", (0, 0, 1))], prim("cone", h=1.2, r=0.6)))
    return Scene("fishbowl", "ref", 3, tree, ((2.0, -2.6, 3.4), (0, 0, 0), 40), (3, -4, 6))


def lens():
    tree = op("intersection", xf([("translate", (0, 0, -0.6))], prim("sphere", r=1)),
              xf([("translate", (0, 0, 0.6))], prim("sphere", r=1)))
    return Scene("lens", "ref", 2, tree, ((2.2, -2.2, 1.4), (0, 0, 0), 40), (3, -2, 5))


def holes(n, group="ref", radius=None):
    cell = 10.0 / n
    r = 0.1 if radius is None else radius
    hole = xf([("translate", (f"(i + 0.5)*{cell!r}", f"(j + 0.5)*{cell!r}", -1))], prim("cylinder", h=3, r=r))
    tree = op("difference", prim("cube", size=(10, 10, 1)), loop([("i", 0, n - 1), ("j", 0, n - 1)], hole))
    name = f"holes_{n}" if group == "ref" else f"holes_n{n}"
    return Scene(name, group, n, tree, ((-4, -7, 11), (5, 5, 0), 40), (2, -3, 15),
                 f"{n}x{n} cylinders of radius {r:.4g} in cells {cell:.4g} wide.")


def cells(n):
    """A crowd of overlapping differences: n hollow cells along a conical log
    spiral, the same spiral for every n (so cells pile up as n grows). Cell
    k sits at u = k/n of 3 turns, its size and distance from the axis shrink
    by 0.15^u and it rises as it shrinks (a cone, apex up). Each cell is a
    sphere minus a smaller sphere offset upwards, which breaks through the
    top: a cup. n = 1000 puts ~20 cells over every point of the spiral."""
    cup = op("difference", prim("sphere", r=0.7), xf([("translate", (0, 0, 0.15))], prim("sphere", r=0.6)))
    u = f"k/{n}"
    tree = loop([("k", 0, n - 1)], xf([("rotate", (0, 0, f"1080*{u}")),
                                       ("translate", (0, 0, f"3*(1 - pow(0.15, {u}))")),
                                       ("scale", f"pow(0.15, {u})"), ("translate", (3, 0, 0))], cup))
    return Scene(f"cells_{n}", "cells", n, op("union", tree), ((5, -7.5, 7), (0, 0, 0.8), 40), (4, -6, 12),
                 f"{n} hollow cells (sphere r 0.7 minus sphere r 0.6 raised 0.15) along a conical log spiral, "
                 "3 turns, size and radius x0.15.")


SPHERE_GRIDS = {100: (5, 5, 4), 1000: (10, 10, 10), 10000: (25, 20, 20),
                100000: (50, 50, 40), 1000000: (100, 100, 100)}


def spheres(n):
    a, b, c = SPHERE_GRIDS[n]
    p = 10.0 / max(a, b, c)
    ball = xf([("translate", (f"(i + 0.5)*{p!r}", f"(j + 0.5)*{p!r}", f"(l + 0.5)*{p!r}"))],
              prim("sphere", r=0.35 * p))
    centre = (a * p / 2, b * p / 2, c * p / 2)
    radius = 0.5 * p * math.sqrt(a * a + b * b + c * c)
    d = radius / math.sin(math.radians(20)) / math.sqrt(1 + 1 + 0.64)
    cam = tuple(round(x + d * u, 6) for x, u in zip(centre, (1, -1, 0.8)))
    light = tuple(round(x + d * u, 6) for x, u in zip(centre, (0.2, -1.2, 1.6)))
    tree = op("union", loop([("i", 0, a - 1), ("j", 0, b - 1), ("l", 0, c - 1)], ball))
    return Scene(f"spheres_{n}", "spheres", n, tree, (cam, tuple(round(x, 6) for x in centre), 40), light,
                 f"{a}x{b}x{c} lattice, pitch {p:.4g}, radius 0.35*pitch; no CSG.")


def reference_models():
    return [grooved(), checkered(5), small_shell(), large_shell(65), fishbowl(), lens(), holes(40)]


def families(quick=False):
    if quick:
        return [large_shell(10, "shell"), large_shell(100, "shell"), holes(10, "holes", 0.4),
                holes(20, "holes", 0.2), checkered(10, "checkered"), spheres(100), spheres(1000)]
    out = [large_shell(n, "shell") for n in (10, 100, 1000, 10000)]
    out += [large_shell(n, "spiral") for n in (100, 1000, 10000)]
    # Hole radius 4/n keeps the removed fraction of the slab fixed (0.1 at n = 40,
    # the spec's model); a fixed 0.1 would merge the holes from n = 50 on.
    out += [holes(n, "holes", 4.0 / n) for n in (10, 20, 40, 70, 100)]
    out += [checkered(k, "checkered") for k in (5, 10, 20, 40)]
    out += [spheres(n) for n in sorted(SPHERE_GRIDS)]
    # Crowds of overlapping differences (issue 18: depth complexity).
    out += [cells(n) for n in (100, 1000, 2000)]
    return out


if __name__ == "__main__":  # write them all for a look: python3 bench/scenes.py DIR
    import os
    import sys
    d = sys.argv[1] if len(sys.argv) > 1 else "bench/out/scenes"
    os.makedirs(d, exist_ok=True)
    for s in reference_models() + families():
        open(os.path.join(d, s.name + ".sdl"), "w").write(sdl_text(s))
        open(os.path.join(d, s.name + ".pov"), "w").write(pov_text(s, 512, 512))
        print(f"{s.name:20} {s.prims:8d} primitives")
