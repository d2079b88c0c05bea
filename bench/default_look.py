# Render time of the studio look against --look plain (docs/quality.md, "The
# default look"): alternating runs of each look, 800×600, medians of
# wall-clock seconds, and the rays each look traces (deterministic).
# python3 bench/default_look.py build/kerf SCENE.scad... [--rounds N]
import subprocess, sys, time, statistics, re
kerf, args = sys.argv[1], sys.argv[2:]
rounds = 3
if "--rounds" in args:
    i = args.index("--rounds"); rounds = int(args[i + 1]); del args[i:i + 2]
for scene in args:
    times = {"plain": [], "studio": []}
    rays = {}
    for r in range(rounds):
        for look in times:
            t = time.perf_counter()
            p = subprocess.run([kerf, "render", scene, "-o", f"/tmp/kerf_look_{look}.png", "-W", "800", "-H", "600",
                                "--threads", "2", "--no-progress", "--stats", "--look", look],
                               check=True, capture_output=True, text=True)
            times[look].append(time.perf_counter() - t)
            rays[look] = re.search(r"stats: 800x600, (\d+) rays \((\d+) primary, (\d+) shadow", p.stderr).groups()
    p_med, s_med = statistics.median(times["plain"]), statistics.median(times["studio"])
    print(f"| {scene.split('/')[-1]} | {p_med:.2f} s | {s_med:.2f} s | {s_med / p_med:.1f}× | "
          f"{int(rays['plain'][0]):,} / {int(rays['studio'][0]):,} ({int(rays['studio'][2]):,} shadow) |")
