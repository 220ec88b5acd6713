# Locking: a thin strip in bending with quadratic cells. A cantilever of length
# L = 100, thickness t = 1 (3D: a 1 x 1 section), clamped at x = 0, its tip
# edge moved by u = 1 = L/100 across the strip (Geometry/Block/Load = bend), two
# cells through the thickness at aspect ratio 10:1. The tip stiffness P/u
# against Euler-Bernoulli, 3 E' I / L^3 with I = t^3/12 per unit depth and the
# plane-strain modulus E' = E/(1 - nu^2) in 2D (2.747253e-7), E and I = 1/12 in
# 3D (2.5e-7). Tolerance 1 %: the accuracy a thin body needs of at most two quadratic cells
# through the thickness. Measured: Quad9 +0.39 %, Quad8 +0.52 %, Hex27 +0.58 %,
# Tet10 +0.89 %. The continuum itself is within 0.1 % of Euler-Bernoulli here
# (Quad9 4 x 400: +0.02 %, Hex27 2 x 4 x 100: +0.11 %: shear, t^2/L^2 ~ 1e-4,
# and the clamp), geometric nonlinearity at u = L/100 moves P/u by 5e-5, and
# the default Residual Tolerance (1e-10 E t) bounds the error of P ~ 2.7e-7 to
# about 4e-4; the rest is the discretisation. Linear cells on the same meshes
# lock (doc/validation.md): Quad4 9.8 x, Hex8 10.7 x, Tet4 28.6 x too stiff.
# The expected stiffness and the overrides of each cell type; its run is <case>_run_<cell>, its check <case>_<cell>.
set(strip2d 2.747252747e-7)
set(strip3d 2.5e-7)
foreach(cell quad9 quad8 hex27 tet10)
  if(cell STREQUAL "quad9")
    set(args "")
    set(expected ${strip2d})
  elseif(cell STREQUAL "quad8")
    set(args Geometry/Serendipity=true)
    set(expected ${strip2d})
  elseif(cell STREQUAL "hex27")
    set(args Problem/Formulation=3D "Geometry/Block/Cells Y=1")
    set(expected ${strip3d})
  else()
    set(args Problem/Formulation=3D "Geometry/Block/Cells Y=1" Geometry/Block/Element=tet4)
    set(expected ${strip3d})
  endif()
  set(sanitize "")
  if(cell STREQUAL "quad9")
    set(sanitize SANITIZE)
  endif()
  cgcm_run(AS run_${cell} ARGS ${args} ${sanitize})
  cgcm_check(AS ${cell} FIXTURES ${name}_run_${cell} ${sanitize}
             COMMAND ${check} stiffness ${run}_run_${cell}/load_curve.csv --from 0 --to 1 --expected ${expected}
                     --tolerance 0.01)
endforeach()
