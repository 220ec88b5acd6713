"""dolfinx's half of the peer comparison (compare_dolfinx.py).

The problem of neo_hookean_block.cpp, solved the same way: the compressible
Neo-Hookean unit cube (W = mu/2 (I1 - 3) - mu ln J + lambda/2 (ln J)^2),
n^3 hex8 (Q1) cells, Y = 1, nu = 0.3, bottom clamped, top pressed down 10 %
(u_z = -0.1, free laterally), 2x2x2 Gauss points (quadrature degree 3),
full Newton from u = 0 (the first iteration is the linear-elastic solution)
until |R|_2 < 1e-9 on the free rows.

Linear solves: PETSc CG + GAMG with the six rigid-body modes as near-null
space, Chebyshev/Jacobi smoothing (as dolfinx's elasticity demo), stopped at
|b - A x| / |b| <= RTOL (unpreconditioned norm, the test Belos applies in
cgcm). Dirichlet rows and columns are eliminated symmetrically (lifting).

    mpirun -np P python3 neo_hookean_block_dolfinx.py N [RTOL]

Prints one JSON line on rank 0, with the same keys as bench_peer_block.
"""
import contextlib
import json
import sys
import time

import numpy as np
import ufl
from dolfinx import fem, la, mesh
from dolfinx.fem.petsc import (apply_lifting, assemble_matrix, assemble_vector, create_matrix, create_vector,
                               set_bc)
from mpi4py import MPI
from petsc4py import PETSc


def rigid_body_modes(V):
    """The six rigid-body modes of the reference configuration, orthonormalised."""
    index_map = V.dofmap.index_map
    bs = V.dofmap.index_map_bs
    x = V.tabulate_dof_coordinates()  # owned and ghost nodes, as the local form
    basis = [la.create_petsc_vector(index_map, bs) for _ in range(6)]
    with contextlib.ExitStack() as stack:
        b = [stack.enter_context(v.localForm()) for v in basis]
        for c in range(3):
            b[c].array[c::3] = 1.0
        b[3].array[0::3], b[3].array[1::3] = -x[:, 1], x[:, 0]
        b[4].array[0::3], b[4].array[2::3] = x[:, 2], -x[:, 0]
        b[5].array[2::3], b[5].array[1::3] = x[:, 1], -x[:, 2]
    la.orthonormalize(basis)
    return PETSc.NullSpace().create(vectors=basis)


def main():
    n = int(sys.argv[1])
    rtol = float(sys.argv[2]) if len(sys.argv) > 2 else 1e-8
    comm = MPI.COMM_WORLD
    press, newton_tolerance = -0.1, 1e-9

    msh = mesh.create_unit_cube(comm, n, n, n, mesh.CellType.hexahedron)
    V = fem.VectorFunctionSpace(msh, ("Lagrange", 1))
    E, nu = 1.0, 0.3
    mu, lam = E / (2 * (1 + nu)), E * nu / ((1 + nu) * (1 - 2 * nu))
    u, v, du = fem.Function(V), ufl.TestFunction(V), ufl.TrialFunction(V)
    F = ufl.Identity(3) + ufl.grad(u)
    J = ufl.det(F)
    psi = mu / 2 * (ufl.tr(F.T * F) - 3) - mu * ufl.ln(J) + lam / 2 * ufl.ln(J) ** 2
    dx = ufl.dx(metadata={"quadrature_degree": 3})  # 2 Gauss points per direction
    residual = ufl.derivative(psi * dx, u, v)
    R, K = fem.form(residual), fem.form(ufl.derivative(residual, u, du))

    fdim = 2
    bottom = mesh.locate_entities_boundary(msh, fdim, lambda x: np.isclose(x[2], 0.0))
    top = mesh.locate_entities_boundary(msh, fdim, lambda x: np.isclose(x[2], 1.0))
    top_z = fem.locate_dofs_topological(V.sub(2), fdim, top)
    bcs = [fem.dirichletbc(np.zeros(3, dtype=PETSc.ScalarType), fem.locate_dofs_topological(V, fdim, bottom), V),
           fem.dirichletbc(PETSc.ScalarType(press), top_z, V.sub(2))]

    A, b = create_matrix(K), create_vector(R)
    A.setNearNullSpace(rigid_body_modes(V))
    ksp = PETSc.KSP().create(comm)
    ksp.setOperators(A)
    ksp.setType("cg")
    ksp.setNormType(PETSc.KSP.NormType.UNPRECONDITIONED)
    ksp.setTolerances(rtol=rtol, atol=0.0, max_it=1000)
    pc = ksp.getPC()
    pc.setType("gamg")
    opts = PETSc.Options()
    opts["mg_levels_ksp_type"] = "chebyshev"
    opts["mg_levels_pc_type"] = "jacobi"
    opts["mg_levels_esteig_ksp_type"] = "cg"
    opts["pc_gamg_coarse_eq_limit"] = 1000
    ksp.setFromOptions()
    dx_vec, r = A.createVecRight(), A.createVecRight()

    t_residual = t_jacobian = t_setup = t_solve = 0.0
    newton = krylov = unconverged_solves = 0
    worst = 0.0
    converged = False
    while newton <= 20:
        comm.barrier()
        t = time.perf_counter()
        with b.localForm() as local:
            local.set(0.0)
        assemble_vector(b, R)
        apply_lifting(b, [K], [bcs], x0=[u.vector], scale=-1.0)
        b.ghostUpdate(addv=PETSc.InsertMode.ADD, mode=PETSc.ScatterMode.REVERSE)
        set_bc(b, bcs, u.vector, -1.0)
        comm.barrier()
        t_residual += time.perf_counter() - t
        if b.norm() < newton_tolerance:
            converged = True
            break
        t = time.perf_counter()
        A.zeroEntries()
        assemble_matrix(A, K, bcs)
        A.assemble()
        comm.barrier()
        t_jacobian += time.perf_counter() - t
        t = time.perf_counter()
        ksp.setUp()
        comm.barrier()
        t_setup += time.perf_counter() - t
        ksp.solve(b, dx_vec)
        comm.barrier()
        t_solve += time.perf_counter() - t
        krylov += ksp.getIterationNumber()
        unconverged_solves += ksp.getConvergedReason() < 0
        A.mult(dx_vec, r)
        r.axpy(-1.0, b)
        worst = max(worst, r.norm() / b.norm())
        u.vector.axpy(-1.0, dx_vec)
        u.x.scatter_forward()
        newton += 1

    # Top reaction: the internal force on the pressed face, before boundary conditions.
    with b.localForm() as local:
        local.set(0.0)
    assemble_vector(b, R)
    b.ghostUpdate(addv=PETSc.InsertMode.ADD, mode=PETSc.ScatterMode.REVERSE)
    owned = V.dofmap.index_map.size_local * V.dofmap.index_map_bs
    reaction = comm.allreduce(float(b.array[top_z[top_z < owned]].sum()))
    cells = msh.topology.index_map(3).size_global
    dofs = V.dofmap.index_map.size_global * V.dofmap.index_map_bs
    if comm.rank == 0:
        print(json.dumps({"code": "dolfinx", "n": n, "cells": cells, "dofs": dofs, "ranks": comm.size,
                          "solver": "PETSc CG + GAMG", "rtol": rtol, "converged": converged, "newton": newton,
                          "krylov": krylov, "unconverged_solves": unconverged_solves,
                          "worst_linear_residual": worst, "reaction": reaction,
                          "residual_s": t_residual, "residual_evaluations": newton + 1, "jacobian_s": t_jacobian,
                          "setup_s": t_setup,
                          "solve_s": t_solve}), flush=True)
    return 0 if converged else 1


if __name__ == "__main__":
    sys.exit(main())
