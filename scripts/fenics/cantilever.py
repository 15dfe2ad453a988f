#!/usr/bin/python3
"""The issue-4 cantilever scenes solved with legacy FEniCS (dolfin 2019.2).

Solves exactly the problem of sinew's built-in scenes cantilever-{6,52,206}k
and twisted-cantilever-{6,52,206}k (scenes/cantilever-*.json)
with dolfin's Newton solver, exact Jacobian, equal load steps and MUMPS LU
(or, with --linear-solver, a Krylov method preconditioned by PETSc's GAMG or
hypre's BoomerAMG with sinew's options for them),
and prints one JSON line with the figures (see README.md next to this file).

Run with the Debian interpreter, /usr/bin/python3 (python3-dolfin installs
into the system Python only), serially (no mpirun).

What matches sinew, and why, is commented at each place:
  mesh       box_tets_arrays() == sinew::box_tets (mesh/box_tets.cpp),
             node for node and tet for tet (checked by --check-mesh against a
             dump of the C++ generator).
  energy     psi of MooneyRivlinMuscle with sigma_max = 0
             (energies/models/mooney_rivlin_muscle.cpp, docs/energies.md).
  gravity    E = -sum_i m_i g.x_i on lumped masses (gravity_potential.cpp,
             lumped_mass.hpp) == int rho g z dx for P1 (see gravity_energy).
  Dirichlet  X = 0 clamped; twisted: X = 1 at R(X - c) + c + (0.1, 0, 0).
"""
import argparse
import json
import math
import sys
import time

import numpy as np

# Scene constants (scenes/cantilever-6k.json and its 52k, 206k siblings).
LENGTH, SIDE = 1.0, 0.2           # box [0, 1] x [0, 0.2] x [0, 0.2] m
A_MR, B_MR, K_MR = 1e4, 1e3, 1e5  # Pa; sigma_max = 0: no fiber term
RHO, G = 1000.0, 9.81             # kg/m^3, m/s^2 along -z
TWIST_ANGLE = math.pi / 4         # Eigen::AngleAxisd(M_PI / 4, UnitX)
TWIST_AXIS_POINT = (0.0, SIDE / 2, SIDE / 2)
TWIST_PULL = 0.1                  # m along +x
BOUNDARY_TOLERANCE = 1e-9 * LENGTH  # sinew selects the clamped face within 1e-9 x the mesh size

# Kuhn split of a cell, in sinew's order (box_tets.cpp): for permutation p the
# tet walks from corner (0,0,0) to (1,1,1) one axis at a time; p >= 3 (odd
# permutations) get their last two nodes swapped to be positively oriented.
PERMUTATIONS = ((0, 1, 2), (1, 2, 0), (2, 0, 1), (0, 2, 1), (2, 1, 0), (1, 0, 2))


def log(*args):
    print(*args, file=sys.stderr, flush=True)


def scene_name(cells, twisted):
    # The scene files are named by tets rounded to thousands.
    tets = 6 * 5 * cells ** 3
    return ("twisted-cantilever-" if twisted else "cantilever-") + "%dk" % ((tets + 500) // 1000)


def box_tets_arrays(cells):
    """Nodes (N x 3) and tets (E x 4, int64) exactly as sinew::box_tets(0,
    (1, 0.2, 0.2), 5c, c, c): node i + (nx+1)(j + (ny+1)k) at
    (1 - t) lower + t upper, t = (i/nx, j/ny, k/nz) (the same IEEE operations
    as the C++, so bitwise equal); tets in cell order k, j, i (i fastest), six
    per cell in PERMUTATIONS order."""
    nx, ny, nz = 5 * cells, cells, cells
    lower = np.zeros(3)
    upper = np.array([LENGTH, SIDE, SIDE])
    k, j, i = np.meshgrid(np.arange(nz + 1), np.arange(ny + 1), np.arange(nx + 1), indexing="ij")
    t = np.stack([i.ravel() / nx, j.ravel() / ny, k.ravel() / nz], axis=1)
    nodes = (1.0 - t) * lower + t * upper

    def node_index(c):
        return c[:, 0] + (nx + 1) * (c[:, 1] + (ny + 1) * c[:, 2])

    k, j, i = np.meshgrid(np.arange(nz), np.arange(ny), np.arange(nx), indexing="ij")
    corner0 = np.stack([i.ravel(), j.ravel(), k.ravel()], axis=1)
    tets = np.empty((corner0.shape[0], 6, 4), dtype=np.int64)
    for p, perm in enumerate(PERMUTATIONS):
        corner = corner0.copy()
        tets[:, p, 0] = node_index(corner)
        for step in range(3):
            corner[:, perm[step]] += 1
            tets[:, p, step + 1] = node_index(corner)
        if p >= 3:
            tets[:, p, [2, 3]] = tets[:, p, [3, 2]]
    return nodes, tets.reshape(-1, 4)


def read_cpp_dump(path):
    """The binary written by the helper that calls sinew::box_tets (see
    README.md): int64 N, int64 E, 3N doubles (column per node), 4E int32."""
    with open(path, "rb") as f:
        n, e = np.frombuffer(f.read(16), dtype=np.int64)
        nodes = np.frombuffer(f.read(24 * n), dtype=np.float64).reshape(n, 3)
        tets = np.frombuffer(f.read(16 * e), dtype=np.int32).reshape(e, 4)
    return nodes, tets


def make_dolfin_mesh(df, nodes, tets):
    """dolfin Mesh with vertex v = our node v and cell e = our tet e. dolfin
    sorts the vertices inside each cell (MeshEditor.close(order=True), UFC
    needs it); that changes no tet, only its local numbering."""
    mesh = df.Mesh()
    editor = df.MeshEditor()
    editor.open(mesh, "tetrahedron", 3, 3)
    editor.init_vertices(nodes.shape[0])
    editor.init_cells(tets.shape[0])
    for v, x in enumerate(nodes):
        editor.add_vertex(v, x)
    for e, t in enumerate(tets):
        editor.add_cell(e, t)
    editor.close()
    return mesh


def check_dolfin_mesh(mesh, nodes, tets):
    coords_equal = bool(np.array_equal(mesh.coordinates(), nodes))
    cells_equal = bool(np.array_equal(mesh.cells(), np.sort(tets, axis=1)))
    return coords_equal, cells_equal


def end_motion(X, fraction, path):
    """Displacement of the X = 1 face at load fraction s.
    Final (s = 1): x = R(X - c) + c + (0.1, 0, 0), R = 45 deg about +x.
    path 'angle': the rig parameters scaled, x = R(s 45 deg)(X - c) + c + (s 0.1, 0, 0)
    (the end stays rigid on the way); path 'linear': u = s u_final."""
    cy, cz = TWIST_AXIS_POINT[1], TWIST_AXIS_POINT[2]
    theta = TWIST_ANGLE * (fraction if path == "angle" else 1.0)
    pull = TWIST_PULL * (fraction if path == "angle" else 1.0)
    y, z = X[:, 1] - cy, X[:, 2] - cz
    u = np.stack([np.full(len(X), pull),
                  cy + math.cos(theta) * y - math.sin(theta) * z - X[:, 1],
                  cz + math.sin(theta) * y + math.cos(theta) * z - X[:, 2]], axis=1)
    return u if path == "angle" else fraction * u


class Cantilever:
    """Forms, boundary conditions and the Newton solver of one scene."""

    def __init__(self, df, mesh, nodes, twisted, args):
        self.df = df
        self.nodes = nodes
        self.twisted = twisted
        self.path = args.end_path
        V = df.VectorFunctionSpace(mesh, "P", 1)
        self.V = V
        self.u = df.Function(V)
        v, du = df.TestFunction(V), df.TrialFunction(V)
        # P1 on affine tets: F is constant per tet, so the one-point rule is
        # exact for psi (a function of F) and for the gravity term (linear in
        # x); sinew evaluates psi once per tet times its rest volume.
        dx = df.dx(metadata={"quadrature_degree": 1})
        self.load = df.Constant(0.0)  # load fraction s = k/N (gravity)

        # Mooney-Rivlin part of mooney-rivlin-muscle (mooney_rivlin_muscle.cpp
        # terms(), docs/energies.md "Energy"): C = F^T F, L = ln J,
        # J_cc = e^(-2L/3) (= J^(-2/3)), I1bar = J_cc tr C,
        # I2bar = J_cc^2 (1/2)((tr C)^2 - tr C^2), psi = A I1bar + B I2bar + K/2 L^2.
        # No constant is subtracted: psi(I) = 3A + 3B = 33,000 Pa, so the
        # elastic energy of the rest state is 33,000 x 0.04 m^3 = 1320 J, as
        # in sinew's objective. The inversion threshold c = 0.1 (ln sigma
        # continued linearly below c) is not modelled: it only acts where a
        # singular value of F is below 0.1, which does not happen at these
        # equilibria (reported: "min_singular_value_F", "min_det_F").
        I = df.Identity(3)
        F = I + df.grad(self.u)
        C = F.T * F
        J = df.det(F)
        L = df.ln(J)
        Jcc = df.exp(-2.0 / 3.0 * L)
        trC = df.tr(C)
        psi = (A_MR * Jcc * trC + B_MR * Jcc ** 2 * 0.5 * (trC ** 2 - df.tr(C * C))
               + 0.5 * K_MR * L ** 2)
        # Gravity: sinew's E = -sum_i m_i g.x_i, m_i = sum_{e ni i} rho W_e / 4
        # (lumped), x the current position. For P1 and constant rho g,
        # int rho g z dx = sum_e rho g W_e mean_e(z) = sum_i m_i g z_i exactly,
        # so the nodal loads and the energy (with the same constant: current z,
        # not displacement) are sinew's.
        z = df.SpatialCoordinate(mesh)[2] + self.u[2]
        self.elastic_form = df.Form(psi * dx)
        self.gravity_form = df.Form(RHO * G * z * dx)
        self.volume_form = df.Form(df.Constant(1.0) * dx(domain=mesh))
        potential = psi * dx + self.load * RHO * G * z * dx
        residual = df.derivative(potential, self.u, v)
        jacobian = df.derivative(residual, self.u, du)  # exact Jacobian
        t0 = time.perf_counter()
        # JIT both forms here (cached in ~/.cache/fenics, so that --compile-only
        # warms the cache for the SystemAssembler below and nothing timed compiles).
        self.residual = df.Form(residual)
        df.Form(jacobian)
        self.compile_s = time.perf_counter() - t0

        # Dirichlet sets by node, with sinew's test |X - 0| <= 1e-9,
        # |X - 1| <= 1e-9 (as the scene files select it), mapped to dofs.
        v2d = df.vertex_to_dof_map(V).reshape(-1, 3)  # [vertex, component] -> dof
        self.v2d = v2d
        self.clamped_nodes = np.flatnonzero(np.abs(nodes[:, 0]) <= BOUNDARY_TOLERANCE)
        self.end_nodes = np.flatnonzero(np.abs(nodes[:, 0] - LENGTH) <= BOUNDARY_TOLERANCE)
        fixed = [self.clamped_nodes] + ([self.end_nodes] if twisted else [])
        self.fixed_dofs = np.sort(v2d[np.concatenate(fixed)].ravel()).astype(np.intc)
        self.free = np.ones(V.dim(), dtype=bool)
        self.free[self.fixed_dofs] = False

        # Dirichlet conditions applied symmetrically (rows and columns of the
        # fixed dofs eliminated, the column terms lifted into b), so that
        # the Newton matrix is symmetric: CG and MUMPS's LDL^T apply.
        self.ubar_function = df.Function(V)
        selected = "std::abs(x[0]) <= tol" + (" || std::abs(x[0] - length) <= tol" if twisted else "")
        fixed_boundary = df.CompiledSubDomain(selected, tol=BOUNDARY_TOLERANCE, length=LENGTH)
        bc = df.DirichletBC(V, self.ubar_function, fixed_boundary, method="pointwise")
        bc_dofs = np.sort(np.fromiter(bc.get_boundary_values().keys(), dtype=np.intc))
        if not np.array_equal(bc_dofs, self.fixed_dofs):
            raise RuntimeError("the DirichletBC selects other dofs than sinew's boundary test")
        self.assembler = df.SystemAssembler(jacobian, residual, [bc])  # the forms compiled above (cached)
        self.assembly_s = 0.0
        self.nonfinite = False

        solver = df.NewtonSolver()
        prm = solver.parameters
        self.near_null_space = None
        if args.linear_solver.startswith("mumps"):
            prm["linear_solver"] = "mumps"       # direct LU (or LDL^T) through MUMPS (PETSc)
            prm["lu_solver"]["symmetric"] = args.linear_solver == "mumps-ldlt"
        else:
            self._krylov(df, prm, args)
        prm["convergence_criterion"] = "residual"
        prm["relative_tolerance"] = args.rtol    # ||b||_2 <= rtol ||b_0||_2 (b_0: start of the step)
        prm["absolute_tolerance"] = args.atol    # or ||b||_2 <= atol
        prm["maximum_iterations"] = args.max_newton
        prm["error_on_nonconvergence"] = False
        prm["report"] = args.verbose
        self.solver = solver
        self.problem = self._nonlinear_problem()

    def _krylov(self, df, prm, args):
        """dolfin's Newton with a Krylov solve, `method-preconditioner`, to
        ||b - A x|| <= krylov_rtol ||b|| (from zero, as sinew's CG), and the
        AMG options sinew sets (solvers/linear/petsc_solver.cpp); GAMG also
        gets the six rigid-body modes as its near-null space."""
        method, preconditioner = args.linear_solver.split("-")
        prm["linear_solver"] = method
        prm["preconditioner"] = {"gamg": "petsc_amg", "hypre": "hypre_amg"}[preconditioner]
        krylov = prm["krylov_solver"]
        krylov["relative_tolerance"] = args.krylov_rtol
        krylov["absolute_tolerance"] = 0.0
        krylov["maximum_iterations"] = 10000
        krylov["nonzero_initial_guess"] = False
        krylov["error_on_nonconvergence"] = True  # an unconverged solve fails the attempt
        options = {"gamg": {"pc_gamg_agg_nsmooths": 0, "pc_gamg_threshold": 0.02},
                   "hypre": {"pc_hypre_boomeramg_coarsen_type": "HMIS", "pc_hypre_boomeramg_interp_type": "ext+i",
                             "pc_hypre_boomeramg_P_max": 4, "pc_hypre_boomeramg_agg_nl": 1}}[preconditioner]
        # The residual measured unpreconditioned, as in sinew's CG.
        options["ksp_norm_type" if method == "cg" else "ksp_pc_side"] = "unpreconditioned" if method == "cg" else "right"
        for key, value in options.items():
            df.PETScOptions.set(key, value)
        if preconditioner == "gamg":
            self.near_null_space = rigid_body_modes(df, self.V, self.u)

    def _nonlinear_problem(self):
        df, outer = self.df, self

        class Problem(df.NonlinearProblem):
            def F(self, b, x):
                t0 = time.perf_counter()
                # Dirichlet rows b_i = x_i - ubar_i (0 once u holds ubar), and
                # the fixed columns' contribution lifted into the free rows.
                outer.assembler.assemble(b, x)
                arr = b.get_local()
                outer.assembly_s += time.perf_counter() - t0
                if not np.all(np.isfinite(arr)):
                    # det F <= 0 somewhere (ln J undefined): this attempt fails.
                    outer.nonfinite = True
                    raise FloatingPointError("non-finite residual (inverted element)")

            def J(self, A, x):
                t0 = time.perf_counter()
                outer.assembler.assemble(A)  # fixed rows and columns -> identity
                if outer.near_null_space is not None:
                    df.as_backend_type(A).set_near_nullspace(outer.near_null_space)
                outer.assembly_s += time.perf_counter() - t0

        return Problem()

    def prescribed(self, fraction):
        """ubar: the Dirichlet values of all dofs at load fraction s (only the
        fixed dofs are used): 0 on X = 0, the end motion on X = 1."""
        ubar = np.zeros(self.V.dim())
        if self.twisted:
            u_end = end_motion(self.nodes[self.end_nodes], fraction, self.path)
            ubar[self.v2d[self.end_nodes].ravel()] = u_end.ravel()
        return ubar

    def set_load(self, fraction, jump_boundary=False):
        """Load fraction s: gravity s·g and the prescribed values ubar(s).
        Without jump_boundary, u keeps the previous converged state and the
        boundary moves with the first Newton step: its Dirichlet rows
        b_i = u_i - ubar_i make du_i = ubar_i - u_i, and the interior rows of
        the Jacobian, whose columns on the fixed dofs are kept, move the
        interior with it to first order (an incremental, consistent start).
        With jump_boundary the fixed dofs are set to ubar(s) at once and the
        interior left where it was: near the moved end the elements then
        start strongly distorted or inverted, which is what made the earlier
        script need 16 steps for the twisted cantilever."""
        self.load.assign(fraction)
        self.ubar = self.prescribed(fraction)
        self.ubar_function.vector().set_local(self.ubar)
        self.ubar_function.vector().apply("insert")
        if not jump_boundary:
            return
        vec = self.u.vector()
        arr = vec.get_local()
        arr[self.fixed_dofs] = self.ubar[self.fixed_dofs]
        vec.set_local(arr)
        vec.apply("insert")

    def solve_step(self):
        return self.solver.solve(self.problem, self.u.vector())

    def gradient_inf_norm(self):
        """max |dE/du_i| over the free dofs at the current u and load: sinew's
        ||grad f||_inf (the NLP variables are the free coordinates)."""
        b = self.df.assemble(self.residual)
        return float(np.max(np.abs(b.get_local()[self.free])))

    def nodal_displacement(self):
        """N x 3, row v = node v of sinew's numbering."""
        return self.u.vector().get_local()[self.v2d]

    def energy(self):
        # Total potential at load 1, sinew's constants (psi(I) = 3A + 3B,
        # gravity on the current z).
        return self.df.assemble(self.elastic_form) + self.df.assemble(self.gravity_form)


def rigid_body_modes(df, V, u):
    """The six rigid-body displacement fields of the reference configuration
    (three translations, three rotations about the origin), orthonormalized:
    the near-null space GAMG builds its coarse spaces from (sinew passes
    the same to PETSc, solvers/linear/petsc_solver.cpp)."""
    x = V.tabulate_dof_coordinates().reshape(-1, 3)
    component = np.zeros(V.dim(), dtype=int)
    for i in range(3):
        component[V.sub(i).dofmap().dofs()] = i
    modes = []
    for i in range(3):
        mode = np.zeros(V.dim())
        mode[component == i] = 1.0
        modes.append(mode)
    for i, j in ((0, 1), (1, 2), (2, 0)):  # rotation in the (i, j) plane: (-x_j, x_i)
        mode = np.zeros(V.dim())
        mode[component == i] = -x[component == i, j]
        mode[component == j] = x[component == j, i]
        modes.append(mode)
    vectors = []
    for mode in modes:
        vector = u.vector().copy()
        vector.set_local(mode)
        vector.apply("insert")
        vectors.append(vector)
    basis = df.VectorSpaceBasis(vectors)
    basis.orthonormalize()
    return basis


def deformation_extremes(nodes, tets, u_nodes):
    """min det F and min singular value of F over the tets (F = Ds Dm^-1,
    constant per tet for P1). sinew's inversion threshold acts only where a
    singular value is below 0.1; this shows it is inactive at the solution."""
    X = nodes[tets]
    x = X + u_nodes[tets]
    Dm = np.transpose(X[:, 1:, :] - X[:, :1, :], (0, 2, 1))
    Ds = np.transpose(x[:, 1:, :] - x[:, :1, :], (0, 2, 1))
    F = Ds @ np.linalg.inv(Dm)
    return float(np.linalg.det(F).min()), float(np.linalg.svd(F, compute_uv=False).min())


def error_reason(error):
    """The line of a dolfin error box that says what went wrong ("*** Reason:
    ..."), else the last line of the message."""
    lines = [line.strip() for line in str(error).strip().splitlines() if line.strip()]
    reasons = [line[len("*** Reason:"):].strip() for line in lines if line.startswith("*** Reason:")]
    return reasons[0] if reasons else (lines[-1] if lines else "error")


def run_attempt(scene, steps):
    """Equal load steps s = k/N, k = 1..N, from u = 0; returns (ok, per-step
    Newton iterations, wall seconds, assembly seconds, reason)."""
    scene.u.vector().zero()
    scene.assembly_s = 0.0
    scene.df.timings(scene.df.TimingClear.clear, [scene.df.TimingType.wall])
    scene.nonfinite = False
    iterations = []
    t0 = time.perf_counter()
    for k in range(1, steps + 1):
        scene.set_load(k / steps)
        try:
            its, converged = scene.solve_step()
        except (FloatingPointError, RuntimeError) as error:
            if scene.nonfinite:
                reason = "step %d: non-finite residual (inverted element)" % k
            else:
                reason = "step %d: %s" % (k, error_reason(error))
            iterations.append(None)
            return False, iterations, time.perf_counter() - t0, scene.assembly_s, reason
        iterations.append(int(its))
        if not converged:
            return False, iterations, time.perf_counter() - t0, scene.assembly_s, \
                "step %d: no convergence in %d Newton iterations" % (k, its)
    return True, iterations, time.perf_counter() - t0, scene.assembly_s, ""


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--cells", type=int, choices=(6, 12, 19), required=True,
                        help="c: 5c x c x c hex cells, 6 tets each (6: 6,480 tets, 12: 51,840, 19: 205,770)")
    parser.add_argument("--twisted", action="store_true", help="the twisted-cantilever scene")
    parser.add_argument("--max-steps", type=int, default=64,
                        help="largest number of load steps tried (N = 1, 2, 3, ... up to this)")
    parser.add_argument("--min-steps", type=int, default=1,
                        help="smallest number of load steps tried (to skip attempts already seen to fail)")
    parser.add_argument("--save-displacement", metavar="PATH",
                        help="write the nodal displacement (N x 3, sinew's node order) as .npy")
    parser.add_argument("--linear-solver", default="mumps",
                        choices=("mumps", "mumps-ldlt", "cg-gamg", "cg-hypre", "gmres-gamg", "gmres-hypre"),
                        help="Newton's linear solver: MUMPS LU or LDL^T, or a Krylov method with an AMG preconditioner")
    parser.add_argument("--krylov-rtol", type=float, default=1e-6,
                        help="Krylov solves: relative residual tolerance (l2, unpreconditioned for cg)")
    parser.add_argument("--rtol", type=float, default=1e-8, help="Newton relative residual tolerance (l2)")
    parser.add_argument("--atol", type=float, default=1e-10, help="Newton absolute residual tolerance (l2)")
    parser.add_argument("--max-newton", type=int, default=30, help="Newton iterations per load step")
    parser.add_argument("--end-path", choices=("linear", "angle"), default="linear",
                        help="twisted: how the end motion is scaled by s = k/N (see README)")
    parser.add_argument("--check-mesh", metavar="DUMP",
                        help="compare the numpy mesh with a binary dump of sinew::box_tets and exit")
    parser.add_argument("--compile-only", action="store_true",
                        help="build the mesh and JIT-compile the forms (fills ~/.cache/fenics), then exit")
    parser.add_argument("--verbose", action="store_true", help="dolfin's Newton report on stdout")
    args = parser.parse_args()
    if not 0.0 < args.krylov_rtol < 1.0:
        parser.error("--krylov-rtol must be in (0, 1), got %g" % args.krylov_rtol)

    nodes, tets = box_tets_arrays(args.cells)
    if args.check_mesh:
        cpp_nodes, cpp_tets = read_cpp_dump(args.check_mesh)
        result = {"cells": args.cells, "nodes": len(nodes), "tets": len(tets),
                  "nodes_bitwise_equal": bool(cpp_nodes.shape == nodes.shape and
                                              np.array_equal(cpp_nodes.view(np.uint64), nodes.view(np.uint64))),
                  "tets_equal": bool(cpp_tets.shape == tets.shape and np.array_equal(cpp_tets, tets))}
        print(json.dumps(result))
        return 0 if result["nodes_bitwise_equal"] and result["tets_equal"] else 1

    import dolfin as df
    df.set_log_level(df.LogLevel.INFO if args.verbose else df.LogLevel.WARNING)
    name = scene_name(args.cells, args.twisted)

    t0 = time.perf_counter()
    mesh = make_dolfin_mesh(df, nodes, tets)
    mesh_s = time.perf_counter() - t0
    coords_equal, cells_equal = check_dolfin_mesh(mesh, nodes, tets)
    if not (coords_equal and cells_equal):
        log("dolfin mesh differs from box_tets: coordinates equal %s, cells equal %s" % (coords_equal, cells_equal))
        return 2
    scene = Cantilever(df, mesh, nodes, args.twisted, args)
    volume = df.assemble(scene.volume_form)
    log("%s: %d tets, %d nodes, %d dofs (%d fixed); mesh %.2f s, forms %.2f s (JIT; ~0 when cached)"
        % (name, len(tets), len(nodes), scene.V.dim(), len(scene.fixed_dofs), mesh_s, scene.compile_s))

    # ||grad f(x0)||_inf as sinew measures it: full load, prescribed values
    # applied, free nodes at rest.
    scene.set_load(1.0, jump_boundary=True)
    grad0 = scene.gradient_inf_norm()
    energy0 = scene.energy()

    if args.compile_only:
        return 0

    failed_s, failed = 0.0, []

    def attempt(n):
        nonlocal failed_s
        result = run_attempt(scene, n)
        ok, its, wall_n, assembly_n, reason_n = result
        log("N = %d: %s, %.2f s (assembly %.2f s), Newton iterations per step %s%s"
            % (n, "converged" if ok else "FAILED", wall_n, assembly_n, its, "" if ok else " (%s)" % reason_n))
        if not ok:
            failed_s += wall_n
            failed.append({"load_steps": n, "wall_s": wall_n, "reason": reason_n})
        return result

    # The fewest equal steps with which dolfin's Newton converges: N = 1, 2,
    # 3, … until one converges. Every N is tried, because convergence is not
    # monotone in N (6k straight beam: N = 15-18 and 20-23 converge, 19 and
    # 24 invert an element in step 2 or 3), so doubling and bisection can
    # settle on more steps than needed. Most failing attempts stop in their
    # first steps; some fail only in their last (straight 206k: N = 17, 19),
    # and --min-steps lets a long scan resume past those already seen.
    steps = max(1, args.min_steps)
    best = attempt(steps)
    while not best[0]:
        if steps + 1 > args.max_steps:
            print(json.dumps({"scene": name, "tets": len(tets), "load_steps": None, "converged": False,
                              "failed_attempts_s": failed_s, "failed_attempts": failed}))
            return 3
        steps += 1
        best = attempt(steps)
    ok, iterations, wall, assembly, reason = best

    # dolfin's own timer of the linear solves of the successful attempt
    # (MUMPS analysis + factorization + solve, or the Krylov solves with their
    # preconditioner setups, through PETSc).
    timer = "LU solver" if args.linear_solver.startswith("mumps") else "PETSc Krylov solver"
    linear_timing = scene.df.timing(timer, scene.df.TimingClear.keep)
    u_nodes = scene.nodal_displacement()
    if args.save_displacement:
        np.save(args.save_displacement, u_nodes)
    tip = scene.u(df.Point(LENGTH, SIDE / 2, SIDE / 2))
    mid = scene.u(df.Point(LENGTH / 2, SIDE / 2, SIDE / 2))
    min_det, min_sigma = deformation_extremes(nodes, tets, u_nodes)
    grad = scene.gradient_inf_norm()
    import petsc4py.PETSc as PETSc
    print(json.dumps({
        "scene": name,
        "tets": len(tets),
        "load_steps": steps,
        "newton_iterations": int(sum(iterations)),
        "newton_iterations_per_step": iterations,
        "wall_s": wall,
        "assembly_s": assembly,
        "linear_solver": args.linear_solver,
        "linear_solve_s": linear_timing[1],
        "failed_attempts_s": failed_s,
        "failed_attempts": failed,
        "energy": scene.energy(),
        "energy_at_rest": energy0,
        "max_displacement": float(np.max(np.linalg.norm(u_nodes, axis=1))),
        "tip_z": float(tip[2]),
        "mid_z": float(mid[2]),
        "min_det_F": min_det,
        "min_singular_value_F": min_sigma,
        "grad_inf_rel": grad / grad0,
        "volume": volume,
        "mesh_s": mesh_s,
        "form_compile_s": scene.compile_s,
        "end_path": args.end_path if args.twisted else None,
        "rtol": args.rtol,
        "krylov_rtol": None if args.linear_solver.startswith("mumps") else args.krylov_rtol,
        "atol": args.atol,
        "dolfin": df.__version__,
        "petsc": ".".join(map(str, PETSc.Sys.getVersion())),
    }))
    return 0


if __name__ == "__main__":
    sys.exit(main())
