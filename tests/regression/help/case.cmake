# --help shows cgcm's usage and parameters, not Kokkos' options.
cgcm_app_check(ARGS --help EXIT 0 STDOUT "^usage: cgcm DECK.xml.*Geometry" REJECT_STDOUT "Kokkos command line arguments")
