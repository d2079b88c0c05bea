#!/usr/bin/env python3
"""Turns the ACC rows printed by the primitive tests into the tables of
docs/accuracy.md:
  KERF_ACCURACY_REPORT=1 build/tests/kerf_render_tests "[accuracy]" | python3 bench/accuracy_table.py
"""
import sys
from collections import OrderedDict

rows = [l.strip().split(",") for l in sys.stdin if l.startswith("ACC,")]
data = OrderedDict()
scales = []
for _, shape, prec, rays, scale, crossings, mx, med, units in rows:
    data.setdefault(shape, {})[(prec, rays, scale)] = (int(crossings), float(mx), float(med), float(units))
    if scale not in scales:
        scales.append(scale)
scales.sort(key=float)

titles = {"near": "rays starting within 3 sizes",
          "far-abs": "rays starting 1e6 away (a world translation of 1e6)",
          "far-rel": "rays starting 1e6 sizes away"}
for rays in ("near", "far-abs", "far-rel"):
    for prec in ("double", "float"):
        print(f"\n**{prec}, {titles[rays]}** — max |surface distance| / size\n")
        print("| shape | " + " | ".join(scales) + " |")
        print("|---|" + "---|" * len(scales))
        for shape, d in data.items():
            cells = []
            for s in scales:
                v = d.get((prec, rays, s))
                cells.append("—" if v is None or v[0] == 0 else f"{v[1]:.0e}")
            if all(c == "—" for c in cells):
                continue
            print(f"| {shape} | " + " | ".join(cells) + " |")

print("\n**Summary over all scales** — crossings checked, median error / size, and the")
print("largest error in units of eps·(L + |o| + |t|·|d|) (the tolerance asserts <= K of these)\n")
print("| shape | precision | rays | crossings | median err/size | max units |")
print("|---|---|---|---|---|---|")
for shape, d in data.items():
    for prec in ("double", "float"):
        for rays in ("near", "far-abs", "far-rel"):
            vals = [v for (p, r, s), v in d.items() if p == prec and r == rays]
            if not vals:
                continue
            n = sum(v[0] for v in vals)
            meds = sorted(v[2] for v in vals)
            print(f"| {shape} | {prec} | {rays} | {n} | {meds[len(meds) // 2]:.1e} | {max(v[3] for v in vals):.2f} |")
