#!/usr/bin/env python3
"""Cost growth of the quasistatic solve with the mesh (issue 14, item 4):
the straight cantilevers at 6k, 52k and 206k tets (built-in scenes) and about
1M tets (bench/scenes/cantilever-1m.json), each solved by `sinew solve` in
its own process under /usr/bin/time (peak RSS), with projected Newton in
four variants: CHOLMOD factorizing every iteration (plain), CHOLMOD
factorizations reused as CG preconditioners (reuse), and PETSc's CG with
GAMG (gamg) or hypre's BoomerAMG (hypre), set up every iteration. Prints one
markdown table and the least-squares slope of log(time) against
log(unknowns) for each variant. "setups" are numeric factorizations, or
multigrid setups; "CG iterations" and "CG (s)" those on a reused
factorization or the multigrid's.

Usage: scripts/cost_growth.py SINEW [--variants plain,reuse,gamg,hypre] [--skip plain:cantilever-1m ...]
                              [--threads N]
  --skip VARIANT:SCENE   leave one run out (e.g. plain Newton on the 1M beam)
"""
import json
import math
import os
import subprocess
import sys
import tempfile

repo = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SCENES = ["cantilever-6k", "cantilever-52k", "cantilever-206k", os.path.join(repo, "bench", "scenes", "cantilever-1m.json")]
VARIANTS = {
    "plain": ["linear_solver=cholmod", "reuse_factorization=off"],
    "reuse": ["linear_solver=cholmod", "reuse_factorization=on"],
    "gamg": ["linear_solver=petsc-cg-gamg"],
    "hypre": ["linear_solver=petsc-cg-hypre"],
}


def scene_label(scene):
    return os.path.splitext(os.path.basename(scene))[0]


def run(sinew, scene, variant, threads):
    with tempfile.TemporaryDirectory() as folder:
        options = [word for option in VARIANTS[variant] for word in ("--option", option)]
        command = ["/usr/bin/time", "-f", "peak_rss_kb %M", sinew, "--threads", str(threads), "solve", scene,
                   *options, "--output", folder, "--verbosity", "0"]
        done = subprocess.run(command, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
        rss_lines = [l for l in done.stderr.splitlines() if l.startswith("peak_rss_kb ")]
        if done.returncode not in (0, 3) or not rss_lines:
            sys.exit(f"cost_growth: {' '.join(command)} exited {done.returncode}: {done.stderr.strip()}")
        with open(os.path.join(folder, "result.json")) as f:
            result = json.load(f)["result"]
    stats = result["statistics"]
    return {
        "scene": scene_label(scene),
        "variant": variant,
        "status": result["status"],
        "unknowns": len(result["x"]),
        "iterations": result["iterations"],
        "factorizations": int(stats["factorizations"]),
        "cg_iterations": int(stats.get("cg_iterations", 0) + stats.get("linear_iterations", 0)),
        "factorization_s": stats["factorization_s"],
        "one_factorization_s": stats["factorization_s"] / max(1, stats["factorizations"]),
        "cg_s": stats.get("cg_s", 0.0) if variant in ("plain", "reuse") else stats["linear_solve_s"],
        "time_s": result["time_s"],
        "peak_rss_gb": int(rss_lines[-1].split()[1]) / 1024.0 ** 2,
    }


def slope(points):
    """Least-squares slope of log t against log n."""
    if len(points) < 2:
        return float("nan")
    xs = [math.log(n) for n, _ in points]
    ys = [math.log(t) for _, t in points]
    mx, my = sum(xs) / len(xs), sum(ys) / len(ys)
    return sum((x - mx) * (y - my) for x, y in zip(xs, ys)) / sum((x - mx) ** 2 for x in xs)


def main():
    args = sys.argv[1:]
    if not args:
        sys.exit(__doc__)
    sinew, skip, threads, variants = args[0], set(), 2, list(VARIANTS)
    i = 1
    while i < len(args):
        if args[i] == "--variants" and i + 1 < len(args):
            variants = args[i + 1].split(",")
            unknown = [v for v in variants if v not in VARIANTS]
            if unknown:
                sys.exit(f"cost_growth: unknown variant {unknown[0]} (valid: {', '.join(VARIANTS)})")
            i += 2
        elif args[i] == "--skip" and i + 1 < len(args):
            skip.add(args[i + 1])
            i += 2
        elif args[i] == "--threads" and i + 1 < len(args):
            threads = int(args[i + 1])
            i += 2
        else:
            sys.exit(f"cost_growth: unknown argument {args[i]}\n{__doc__}")
    rows = []
    print("| scene | variant | status | unknowns | iterations | setups | CG iterations | one setup (s) "
          "| CG (s) | total (s) | per iteration (s) | peak RSS (GB) |")
    print("|---|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|")
    for scene in SCENES:
        for variant in variants:
            if f"{variant}:{scene_label(scene)}" in skip:
                continue
            r = run(sinew, scene, variant, threads)
            rows.append(r)
            print(f"| {r['scene']} | {variant} | {r['status']} | {r['unknowns']} | {r['iterations']} | "
                  f"{r['factorizations']} | {r['cg_iterations']} | {r['one_factorization_s']:.3f} | {r['cg_s']:.2f} | "
                  f"{r['time_s']:.2f} | {r['time_s'] / max(1, r['iterations']):.3f} | {r['peak_rss_gb']:.2f} |", flush=True)
    print()
    for variant in variants:
        points = [(r["unknowns"], r["time_s"]) for r in rows if r["variant"] == variant]
        factor = [(r["unknowns"], r["one_factorization_s"]) for r in rows if r["variant"] == variant]
        memory = [(r["unknowns"], r["peak_rss_gb"]) for r in rows if r["variant"] == variant]
        print(f"- {variant}: total time ~ n^{slope(points):.2f}, one setup ~ n^{slope(factor):.2f}, "
              f"peak RSS ~ n^{slope(memory):.2f} ({len(points)} sizes)")


if __name__ == "__main__":
    main()
