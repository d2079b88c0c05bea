# Render time of --facets openscad against the default auto (docs/quality.md,
# "Facets"): alternating runs of each scene in each mode, medians of
# wall-clock seconds, and the leaves `kerf dump` counts.
# python3 bench/facets_cost.py build/kerf SCENE... [--rounds 3]
import subprocess, sys, time, statistics
args = sys.argv[2:]
rounds = 3
if "--rounds" in args:
    i = args.index("--rounds")
    rounds = int(args[i + 1])
    del args[i:i + 2]
kerf, modes = sys.argv[1], ["auto", "openscad"]
times = {(s, m): [] for s in args for m in modes}
for r in range(rounds):
    for s in args:
        for m in modes:
            t = time.perf_counter()
            subprocess.run([kerf, "render", s, "-o", "/tmp/kerf_facets_cost.png", "-W", "400", "-H", "300",
                            "--threads", "2", "--no-progress", "--facets", m], check=True, stderr=subprocess.DEVNULL)
            times[(s, m)].append(time.perf_counter() - t)
for s in args:
    base = statistics.median(times[(s, "auto")])
    for m in modes:
        dump = subprocess.run([kerf, "dump", s, "--facets", m], capture_output=True, text=True).stdout
        leaves = dump.split("leaves=")[1].split()[0]
        med = statistics.median(times[(s, m)])
        print(f"| {s} | {m} | {med:.2f} s | {med / base:.2f}× | {leaves} |")
