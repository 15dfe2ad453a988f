#!/usr/bin/env python3
"""Records the equilibrium of built-in scenes for the invariance test
(tests/scenes/recorded_equilibrium.hpp, issue 14).

For each scene it runs `sinew solve NAME` twice: at the scene's own settings,
for the status a default solve ends with (a scene whose solver does not
converge, like the rank-deficient locking block, is recorded as it ends), and
at --tol 1e-12 (or the tightest of 1e-11 … 1e-9 that converges; else the
default solve), for the equilibrium to round-off: its objective and a sample
of x, every s-th variable, s = max(1, n // 1500) made not a multiple of 3 so
that every coordinate direction is sampled. Tests hold the default solve of a
later commit to that equilibrium, within 1e-9 of the largest sampled
displacement.

Rerun it only when a change of an equilibrium is intended and explained in
the commit, with the sinew of the commit before the change.

Usage: scripts/record_equilibria.py SINEW [SCENE ...]   (SINEW: the executable, in its build tree
       of the commit to record; default: every scene in scenes/)
"""
import json
import os
import subprocess
import sys
import tempfile

repo = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
# The tightest of these at which the scene's solver converges; a scene whose
# equilibrium is not smooth (nodes resting on a faceted body's edges) may
# converge only at the default 1e-8, and its default solve is recorded then.
TIGHT_TOLERANCES = ["1e-12", "1e-11", "1e-10", "1e-9"]


def stride_for(n):
    s = max(1, n // 1500)
    while s > 1 and s % 3 == 0:
        s += 1
    return s


def solve(sinew, name, extra):
    with tempfile.TemporaryDirectory() as folder:
        run = subprocess.run([sinew, "solve", name, "--output", folder, "--verbosity", "0"] + extra,
                             stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
        if run.returncode not in (0, 3):  # 3: not converged, recorded as it ends
            sys.exit(f"record_equilibria: sinew solve {name} {' '.join(extra)} exited {run.returncode}: "
                     f"{run.stderr.strip()}")
        with open(os.path.join(folder, "result.json")) as f:
            return json.load(f)


def record(sinew, name, version):
    default = solve(sinew, name, [])
    tight, tolerance = default, "1e-8 (default)"
    for candidate in TIGHT_TOLERANCES:
        run = solve(sinew, name, ["--tol", candidate])
        if candidate == TIGHT_TOLERANCES[0] or run["result"]["status"] == "converged":
            tight, tolerance = run, candidate
        if run["result"]["status"] == "converged":
            break
    else:
        if default["result"]["status"] == "converged":
            tight, tolerance = default, "1e-8 (default; no tighter solve converged)"
    x = tight["result"]["x"]
    s = stride_for(len(x))
    lines = [f"# equilibrium of built-in scene {name} by {tight['solver']} at --tol {tolerance} "
             f"(status {tight['result']['status']}, {tight['result']['iterations']} iterations), "
             f"recorded with {version} by scripts/record_equilibria.py",
             f"status {default['result']['status']}",
             f"variables {len(x)}",
             f"objective {tight['result']['objective']!r}",
             f"stride {s}"]
    lines += [f"{i} {x[i]!r}" for i in range(0, len(x), s)]
    out = os.path.join(repo, "tests", "data", "equilibria", name + ".txt")
    os.makedirs(os.path.dirname(out), exist_ok=True)
    with open(out, "w") as f:
        f.write("\n".join(lines) + "\n")
    print(f"{name}: {len(x)} variables, stride {s}, default {default['result']['status']}, "
          f"tight {tight['result']['status']} in {tight['result']['iterations']} iterations", flush=True)


def main():
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    sinew = sys.argv[1]
    names = sys.argv[2:] or sorted(f[:-5] for f in os.listdir(os.path.join(repo, "scenes")) if f.endswith(".json"))
    commit = subprocess.run(["git", "-C", os.path.dirname(os.path.abspath(sinew)), "rev-parse", "--short", "HEAD"],
                            capture_output=True, text=True).stdout.strip()
    version = f"the sinew of commit {commit}" if commit else sinew
    for name in names:
        record(sinew, name, version)


if __name__ == "__main__":
    main()
