# The branch points of tests/regression/branch_point on two ranks (deck.xml is a
# link to its deck): the same rows, branch points, branches and eigenvalue
# counts as on one rank (1e-7: MUMPS's factorisations differ in round-off
# between the rank counts; the located points are solver-tolerance roots).
cgcm_run(AS np2 RANKS 2)
cgcm_check(AS np1_vs_np2 FIXTURES regression_branch_point ${name}_np2
           COMMAND ${compare_csv} ${outputs}/regression/regression_branch_point/load_curve.csv ${run}_np2/load_curve.csv
                   --columns u,P,fold,branch_point,branch,stable,negative_eigenvalues --rel 1e-7 --abs 1e-10)
