#!/usr/bin/env bash
# Issue 4: wall time of sinew's projected Newton against legacy FEniCS on the
# cantilever scenes. For each size (c = 12: 52k tets, c = 19: 206k tets),
# straight and twisted: first sinew, then scripts/fenics/cantilever.py; then
# one markdown table. See README.md in this directory.
#
#   scripts/fenics/run_comparison.sh [OUTDIR]
#
# Environment: SINEW (default build/apps/sinew of this checkout), PYTHON (default
# /usr/bin/python3, the interpreter python3-dolfin installs into), CELLS
# (default "12 19"), FENICS_ARGS (extra arguments for cantilever.py), THREADS
# (default 2, for both codes), VARIANTS (default "straight twisted"),
# LINEAR_SOLVERS (default "cholmod": sinew's linear_solver option; each one
# listed is a sinew run and a row of the table, against the same FEniCS run).
# Raw outputs (sinew's result JSON and iteration table, the FEniCS JSON line
# and log) go to OUTDIR (default ./fenics-comparison-YYYYmmdd-HHMMSS).
set -euo pipefail

here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
SINEW="${SINEW:-$here/../../build/apps/sinew}"
PYTHON="${PYTHON:-/usr/bin/python3}"
CELLS="${CELLS:-12 19}"
FENICS_ARGS="${FENICS_ARGS:-}"
# The same threads for both: sinew's --threads, and for FEniCS OpenBLAS's
# threads (MUMPS's dense blocks through PETSc; dolfin assembles serially).
THREADS="${THREADS:-2}"
VARIANTS="${VARIANTS:-straight twisted}"
LINEAR_SOLVERS="${LINEAR_SOLVERS:-cholmod}"
export OPENBLAS_NUM_THREADS="$THREADS" OMP_NUM_THREADS="$THREADS"
out="${1:-fenics-comparison-$(date +%Y%m%d-%H%M%S)}"
mkdir -p "$out"

"$PYTHON" -c 'import dolfin' 2>/dev/null || { echo "dolfin not importable by $PYTHON (apt-get install -y python3-dolfin)" >&2; exit 2; }
[ -x "$SINEW" ] || { echo "no sinew binary at $SINEW" >&2; exit 2; }

loadavg() { cut -d' ' -f1 /proc/loadavg; }

# Warm FEniCS' JIT cache (~/.cache/fenics) so that no timed run compiles forms
# (the forms do not depend on the mesh size or the scene variant).
echo "warming the FEniCS JIT cache ..." >&2
"$PYTHON" "$here/cantilever.py" --cells 6 --compile-only 2> "$out/jit-warmup.log"

for c in $CELLS; do
    case "$c" in 6) k=6k ;; 12) k=52k ;; 19) k=206k ;; *) echo "cells must be 6, 12 or 19" >&2; exit 2 ;; esac
    for variant in $VARIANTS; do
        if [ "$variant" = twisted ]; then scene="twisted-cantilever-$k"; flag=--twisted; else scene="cantilever-$k"; flag=; fi
        for solver in $LINEAR_SOLVERS; do
            echo "== $scene: sinew, $solver (load $(loadavg))" >&2
            echo "$(loadavg)" > "$out/$scene.$solver.load-before-sinew"
            status=0
            "$SINEW" --threads "$THREADS" solve "$scene" --solver projected-newton --option "linear_solver=$solver" \
                --json "$out/$scene.$solver.sinew.json" > "$out/$scene.$solver.sinew.log" 2>&1 || status=$?
            echo "$status" > "$out/$scene.$solver.sinew.status"
            tail -n 1 "$out/$scene.$solver.sinew.log" >&2
        done
        echo "== $scene: FEniCS (load $(loadavg))" >&2
        echo "$(loadavg)" > "$out/$scene.load-before-fenics"
        status=0
        # shellcheck disable=SC2086
        "$PYTHON" "$here/cantilever.py" --cells "$c" $flag $FENICS_ARGS \
            --save-displacement "$out/$scene.fenics-u.npy" \
            > "$out/$scene.fenics.json" 2> "$out/$scene.fenics.log" || status=$?
        echo "$status" > "$out/$scene.fenics.status"
        grep -v 'JIT' "$out/$scene.fenics.log" >&2 || true
    done
done

"$PYTHON" - "$out" "$VARIANTS" "$LINEAR_SOLVERS" $CELLS <<'EOF'
import json, os, sys
out, variants, solvers, cells = sys.argv[1], sys.argv[2].split(), sys.argv[3].split(), sys.argv[4:]
size = {"6": "6k", "12": "52k", "19": "206k"}
def load(path):
    try:
        with open(path) as f:
            text = f.read().strip()
        if not text:
            return None
        try:
            return json.loads(text)                   # sinew's result file
        except ValueError:
            return json.loads(text.splitlines()[-1])  # cantilever.py: one JSON line
    except (OSError, ValueError):
        return None
def read(path):
    try:
        with open(path) as f:
            return f.read().strip()
    except OSError:
        return "?"
print("| scene | tets | ours: linear solver | ours: iterations | ours: wall s | FEniCS: linear solver | FEniCS: load steps | "
      "FEniCS: Newton iterations | FEniCS: wall s | FEniCS: failed attempts s | ratio FEniCS/ours | energy ours | "
      "energy FEniCS | load avg before ours / FEniCS |")
print("|---|---:|---|---:|---:|---|---:|---:|---:|---:|---:|---:|---:|---|")
def row(scene, solver, c):
    ours = load(os.path.join(out, "%s.%s.sinew.json" % (scene, solver)))
    fe = load(os.path.join(out, scene + ".fenics.json"))
    o_it = "%d%s" % (ours["iterations"], "" if ours.get("converged") else " (not converged)") if ours else "failed"
    o_t = "%.2f" % ours["time_s"] if ours else "-"
    if fe and fe.get("load_steps"):
        f_n, f_it, f_t = str(fe["load_steps"]), str(fe["newton_iterations"]), "%.2f" % fe["wall_s"]
        f_fail = "%.2f" % fe["failed_attempts_s"]
        ratio = "%.1f" % (fe["wall_s"] / ours["time_s"]) if ours else "-"
        e_fe = "%.12g" % fe["energy"]
    else:
        f_n, f_it, f_t, ratio, e_fe = "failed", "-", "-", "-", "-"
        f_fail = "%.2f" % fe["failed_attempts_s"] if fe else "-"
    e_ours = "%.12g" % ours["objective"] if ours else "-"
    f_solver = fe.get("linear_solver", "-") if fe else "-"
    if fe and fe.get("krylov_rtol"):
        f_solver += " (rtol %g)" % fe["krylov_rtol"]
    tets = fe["tets"] if fe else 6 * 5 * int(c) ** 3
    loads = "%s / %s" % (read(os.path.join(out, "%s.%s.load-before-sinew" % (scene, solver))),
                         read(os.path.join(out, scene + ".load-before-fenics")))
    return "| %s | %d | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s |" % (
        scene, tets, solver, o_it, o_t, f_solver, f_n, f_it, f_t, f_fail, ratio, e_ours, e_fe, loads)
for c in cells:
    for variant in variants:
        scene = ("twisted-" if variant == "twisted" else "") + "cantilever-" + size[c]
        for solver in solvers:
            print(row(scene, solver, c))
print()
print("ours: `sinew solve SCENE --solver projected-newton --option linear_solver=SOLVER`, wall = result time_s (the solver run; problem "
      "construction excluded). FEniCS: wall of the successful load-stepping run (assembly + linear solves), "
      "mesh construction and form compilation excluded (JIT cache warmed first); failed attempts with fewer "
      "load steps timed separately. Raw outputs: %s" % out)
EOF
