#!/usr/bin/env python3
"""The options of PETSc's multigrids on one scene (issue 14, item 3): each
setting solved by `sinew solve SCENE --option linear_solver=...` with the
setting in PETSC_OPTIONS, in its own process, one after the other. Prints a
markdown table: Newton iterations, multigrid setups, CG iterations, seconds
in setups and in CG, total seconds. The first row of each solver is sinew's
default (solvers/linear/petsc_solver.cpp); the others override it.

Usage: scripts/amg_options.py SINEW [SCENE] [--threads N]   (default scene: cantilever-52k)
"""
import json
import os
import subprocess
import sys
import tempfile

SETTINGS = [
    ("petsc-cg-gamg", ""),
    ("petsc-cg-gamg", "-pc_gamg_reuse_interpolation false"),
    ("petsc-cg-gamg", "-pc_gamg_agg_nsmooths 1 -pc_gamg_threshold 0"),
    ("petsc-cg-gamg", "-pc_gamg_agg_nsmooths 1 -pc_gamg_threshold 0.02"),
    ("petsc-cg-gamg", "-pc_gamg_threshold 0"),
    ("petsc-cg-gamg", "-pc_gamg_threshold 0.05"),
    ("petsc-cg-gamg", "-pc_gamg_square_graph 0"),
    ("petsc-cg-gamg", "-pc_gamg_coarse_eq_limit 2000"),
    ("petsc-cg-gamg", "-mg_levels_ksp_max_it 3"),
    ("petsc-cg-hypre", ""),
    ("petsc-cg-hypre", "-pc_hypre_boomeramg_coarsen_type Falgout -pc_hypre_boomeramg_interp_type classical "
                       "-pc_hypre_boomeramg_P_max 0 -pc_hypre_boomeramg_agg_nl 0"),
    ("petsc-cg-hypre", "-pc_hypre_boomeramg_strong_threshold 0.5"),
    ("petsc-cg-hypre", "-pc_hypre_boomeramg_agg_nl 0"),
]


def run(sinew, scene, solver, options, threads):
    with tempfile.TemporaryDirectory() as folder:
        environment = dict(os.environ, PETSC_OPTIONS=options)
        command = [sinew, "--threads", str(threads), "solve", scene, "--option", f"linear_solver={solver}",
                   "--output", folder, "--verbosity", "0"]
        try:
            done = subprocess.run(command, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True,
                                  env=environment, timeout=600)
        except subprocess.TimeoutExpired:
            return None
        if done.returncode not in (0, 3):
            sys.exit(f"amg_options: {' '.join(command)} exited {done.returncode}: {done.stderr.strip()}")
        with open(os.path.join(folder, "result.json")) as f:
            return json.load(f)["result"]


def main():
    args = sys.argv[1:]
    if not args:
        sys.exit(__doc__)
    sinew, scene, threads = args[0], "cantilever-52k", 2
    rest = args[1:]
    if "--threads" in rest:
        i = rest.index("--threads")
        threads = int(rest[i + 1])
        del rest[i:i + 2]
    if rest:
        scene = rest[0]
    print(f"| solver | PETSC_OPTIONS | status | iterations | setups | CG iterations | setups (s) | CG (s) | total (s) |")
    print("|---|---|---|---:|---:|---:|---:|---:|---:|")
    for solver, options in SETTINGS:
        r = run(sinew, scene, solver, options, threads)
        shown = f"`{options}`" if options else "(sinew's default)"
        if r is None:
            print(f"| {solver} | {shown} | over 600 s | | | | | | |", flush=True)
            continue
        s = r["statistics"]
        print(f"| {solver} | {shown} | {r['status']} | {r['iterations']} | {int(s['factorizations'])} | "
              f"{int(s.get('linear_iterations', 0))} | {s['factorization_s']:.2f} | {s['linear_solve_s']:.2f} | "
              f"{r['time_s']:.2f} |", flush=True)


if __name__ == "__main__":
    main()
