# Time against error of the path tracer (docs/quality.md, "Path tracing"):
# a reference at REF_SPP paths per pixel, then each spp in alternating
# rounds with seeds 1, 2, 3, ...; RMSE over the linear RGB of the PFM
# images against the reference, medians over the rounds of the RMSE, the
# wall-clock seconds and the CPU seconds (the machine is shared: CPU time
# is the steadier figure).
# python3 bench/path_convergence.py build/kerf SCENE.sdl [ROUNDS] [REF_SPP]
import math, os, resource, struct, subprocess, sys, time, statistics

kerf, scene = sys.argv[1], sys.argv[2]
rounds = int(sys.argv[3]) if len(sys.argv) > 3 else 3
ref_spp = int(sys.argv[4]) if len(sys.argv) > 4 else 4096
size = ["-W", "160", "-H", "120", "--threads", "2", "--no-progress", "--integrator", "path"]

def read_pfm(path):
    with open(path, "rb") as f:
        assert f.readline().strip() == b"PF"
        w, h = map(int, f.readline().split())
        scale = float(f.readline())
        data = f.read()
    return struct.unpack(("<" if scale < 0 else ">") + "f" * (3 * w * h), data)

def render(spp, seed, out):
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    t = time.perf_counter()
    subprocess.run([kerf, "render", scene, "-o", out, "--spp", str(spp), "--seed", str(seed)] + size, check=True)
    wall = time.perf_counter() - t
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    return wall, (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)

ref_out = f"/tmp/kerf_path_ref_{ref_spp}.pfm"
if not os.path.exists(ref_out):
    render(ref_spp, 0, ref_out)
ref = read_pfm(ref_out)
spps = [4, 16, 64, 256]
rows = {s: ([], [], []) for s in spps}
for r in range(rounds):
    for s in spps:
        out = f"/tmp/kerf_path_{s}.pfm"
        wall, cpu = render(s, r + 1, out)
        img = read_pfm(out)
        rmse = math.sqrt(sum((a - b) ** 2 for a, b in zip(img, ref)) / len(ref))
        for lst, v in zip(rows[s], (wall, cpu, rmse)):
            lst.append(v)
print(f"reference: {ref_spp} spp, mean {sum(ref) / len(ref):.4f}")
print("| spp | wall (median) | CPU (median) | RMSE (median) | RMSE·√spp |")
print("|---|---|---|---|---|")
for s in spps:
    wall, cpu, rmse = (statistics.median(v) for v in rows[s])
    print(f"| {s} | {wall:.2f} s | {cpu:.2f} s | {rmse:.4f} | {rmse * math.sqrt(s):.3f} |")
