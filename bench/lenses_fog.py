# Render time of fog, depth of field and the wide cameras against the pinhole
# (docs/quality.md, "Lenses and fog"): alternating runs of each variant of a
# scene without its camera line, medians of wall-clock seconds.
# python3 bench/lenses_fog.py build/kerf SCENE_WITHOUT_CAMERA.sdl [ROUNDS]
import subprocess, sys, time, statistics, pathlib
kerf = sys.argv[1]
base = pathlib.Path(sys.argv[2]).read_text()
variants = {
  "pinhole": "",
  "fog": "fog(distance = 20, color = [0.7, 0.75, 0.8]);\n",
  "dof16": "DOF16",
  "dof64": "DOF64",
  "fisheye": "FISH",
  "panoramic": "PANO",
}
cam = 'camera(position = [9, -11, 8], look_at = [0, 0, 0.6], fov = 38%s);\n'
texts = {}
for k, v in variants.items():
    extra = ""
    if v == "DOF16": extra = ", aperture = 0.6, blur_samples = 16"
    elif v == "DOF64": extra = ", aperture = 0.6, blur_samples = 64"
    elif v == "FISH": extra = ', projection = "fisheye"'
    elif v == "PANO": extra = ', projection = "panoramic"'
    texts[k] = cam % extra + (v if v.startswith("fog") else "") + base
    pathlib.Path(f"/tmp/kerf_lenses_{k}.sdl").write_text(texts[k])
times = {k: [] for k in variants}
for r in range(int(sys.argv[3]) if len(sys.argv) > 3 else 5):
    for k in variants:
        t = time.perf_counter()
        subprocess.run([kerf, "render", f"/tmp/kerf_lenses_{k}.sdl", "-o", f"/tmp/kerf_lenses_{k}.png", "-W", "400", "-H", "300", "--threads", "2", "--no-progress"], check=True)
        times[k].append(time.perf_counter() - t)
p = statistics.median(times["pinhole"])
for k, v in times.items():
    m = statistics.median(v)
    print(f"| {k} | {m:.2f} s | {m / p:.2f}× |")
