# The README's two commands. Each bootstraps a fresh Debian bookworm machine:
# installs missing packages, configures, builds, then runs.
BUILD_DIR ?= build
JOBS      ?= 2
DECK      ?= inputs/sphere-on-half-space.xml
OUTPUT    ?= output/demo

.PHONY: demo test build configure deps clean bench figures mesh-convergence paper jkr-study jkr-end pulloff-map cylinder-map punch-study peel-study branch-points stability-check stability-map sphere-3d method-study sanitize fuzz peers

deps:
	@bash scripts/install-deps.sh

configure: deps
	@cmake -S . -B $(BUILD_DIR) -DCMAKE_BUILD_TYPE=Release > $(BUILD_DIR).configure.log 2>&1 \
	  || (cat $(BUILD_DIR).configure.log; exit 1)

build: configure
	@cmake --build $(BUILD_DIR) -j$(JOBS)

demo: build
	$(BUILD_DIR)/bin/cgcm $(DECK) Output/Directory=$(OUTPUT)
	/usr/bin/python3 tools/plot_load_curves.py --output $(OUTPUT)/load_curve.png $(OUTPUT)/load_curve.csv

test: build
	cd $(BUILD_DIR) && ctest --output-on-failure -j$(JOBS)

# The unit tests and a CI-sized subset of the regressions (ctest label
# "sanitize") in a separate build with AddressSanitizer + UndefinedBehavior-
# Sanitizer. Leak detection is off: OpenMPI's and its plugins' allocations
# at exit are reported as leaks and cannot be told apart from ours. Only the
# programs those tests run are built (the target cgcm_sanitize_targets,
# tests/CMakeLists.txt): not the benchmarks nor cgcm-analytic.
SANITIZE_DIR ?= build-sanitize
sanitize: deps
	@cmake -S . -B $(SANITIZE_DIR) -DCMAKE_BUILD_TYPE=Release -DCGCM_SANITIZE=ON > $(SANITIZE_DIR).configure.log 2>&1 \
	  || (cat $(SANITIZE_DIR).configure.log; exit 1)
	@cmake --build $(SANITIZE_DIR) -j$(JOBS) --target cgcm_sanitize_targets
	cd $(SANITIZE_DIR) && ASAN_OPTIONS=detect_leaks=0:abort_on_error=0 \
	  UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 ctest --output-on-failure -j$(JOBS) -L "unit|sanitize"

# 10 000 mutated inputs through cgcm (tests/fuzz/fuzz_inputs.py; 26
# minutes on 2 cores): no signal, no hang, a message for every refusal.
FUZZ_COUNT ?= 10000
fuzz: build
	/usr/bin/python3 tests/fuzz/fuzz_inputs.py --cgcm $(BUILD_DIR)/bin/cgcm --source-dir . \
	  --workdir output/fuzz --count $(FUZZ_COUNT) --seed 11 --full-runs 100 --run-limit 120 --jobs $(JOBS)

bench: build
	@bash bench/run-all.sh $(BUILD_DIR)

# cgcm against dolfinx (Debian's python3-dolfinx, installed here if missing) on
# the same Neo-Hookean block, 108k and 311k unknowns, 1 and 2 ranks; about 5
# minutes. The table is in doc/performance.md.
peers: build
	@bash scripts/install-deps.sh --peers
	/usr/bin/python3 bench/peers/compare_dolfinx.py --bench $(BUILD_DIR)/bin/bench_peer_block --repeats 3

# Every figure of doc/validation.md and its tables (tools/make_figures.sh;
# the long studies below are run when their tables are missing under output/).
figures: build
	@bash tools/make_figures.sh $(BUILD_DIR)

# Mesh convergence of the paper's key numbers (Figs. 9 and 11 decks, mesh levels
# 0-2; tools/mesh_convergence.py): output/validation/mesh-convergence/{table,orders}.csv.
# About 25 minutes; a level already completed is not run again. Level 3 of the
# Fig. 9 deck (21 minutes): make mesh-convergence MESH_LEVELS=3 MESH_DECKS=gammaW-200;
# of the Fig. 11 deck (about an hour): MESH_LEVELS=3 MESH_DECKS=gammaW-20.
MESH_LEVELS ?= 0 1 2
MESH_DECKS ?= gammaW-200 gammaW-20
mesh-convergence: build
	/usr/bin/python3 tools/mesh_convergence.py --build $(BUILD_DIR) --levels $(MESH_LEVELS) --decks $(MESH_DECKS)

# The paper's Fig. 5 and Fig. 6 studies (inputs/paper), plotted into doc/figures.
paper: build
	@bash tools/run_paper_figures.sh $(BUILD_DIR)

# The JKR end of the pull-off force: lambda = 3 on finer meshes and at two
# gammaL, against the Lennard-Jones sphere reference (output/validation/jkr-study).
jkr-study: build
	@bash tools/run_jkr_study.sh $(BUILD_DIR)

# The JKR end at small contacts: gammaL = 2000, Tabor mu = JKR_END_MU; Method 3
# with both surface densities at finite and small strain, Method 1 (cutoff
# 20 r0) restarted near the minimum, against the Lennard-Jones sphere
# (tools/jkr_end_study.py): output/validation/jkr-end, and the plot into
# doc/figures. mu = 2, 3, 5 take about 1.5 hours on 2 cores (Method 1 at
# mu = 5: 33 min); JKR_END_MU="2 3 5 8" adds mu = 8 (each Method 3 run
# 42 min, Method 1 several hours).
JKR_END_MU ?= 2 3 5
jkr-end: build
	/usr/bin/python3 tools/jkr_end_study.py --build $(BUILD_DIR) --output output/validation/jkr-end --jobs $(JOBS) \
	  --mu $(JKR_END_MU)
	cp output/validation/jkr-end/jkr_end.png doc/figures/jkr-end.png

# Pull-off force over Tabor mu 0.05 .. 5 at gammaL = 50 and 200, finite and
# small strain on the same meshes (tools/pulloff_map.py): output/pulloff-map,
# and the plot into doc/figures. Finished runs are reused. Cases needing a
# graded mesh finer than PULLOFF_MAX_LEVEL (mu = 5) run on the band mesh
# (meshes/sphere-on-half-space-band.geo).
PULLOFF_MAX_LEVEL ?= 2
pulloff-map: build
	/usr/bin/python3 tools/pulloff_map.py --build $(BUILD_DIR) --output output/pulloff-map --jobs $(JOBS) \
	  --max-level $(PULLOFF_MAX_LEVEL)
	cp output/pulloff-map/pulloff_map.png doc/figures/pulloff-map.png

# The cylinder on the half-space in plane strain: its load-control pull-off over
# the Maugis-Dugdale parameter of the cylinder, lambda = 0.1 .. 5, finite and
# small strain, elastic and rigid half-space, against the M-D cylinder of Baney
# & Hui and Barquins' JKR end (tools/cylinder_map.py): output/cylinder-map; and
# the JKR end (lambda = 5) at gammaL = 200, 2000, 8000, where sigma_max/E* falls
# from 0.39 to 0.06: output/cylinder-map-jkr. The plot goes into doc/figures.
# Finished runs are reused.
cylinder-map: build
	/usr/bin/python3 tools/cylinder_map.py --build $(BUILD_DIR) --output output/cylinder-map --jobs $(JOBS)
	/usr/bin/python3 tools/cylinder_map.py --build $(BUILD_DIR) --output output/cylinder-map-jkr --jobs $(JOBS) \
	  --lambda 5 --gammaL 200 2000 8000 --half-space elastic --kinematics finite
	cp output/cylinder-map/cylinder_map.png doc/figures/cylinder-map.png

# The rigid flat punch (inputs/flat-punch.xml) over its radius in critical
# sizes 0.05 .. 100: from the strength limit pi a^2 sigma_max to Kendall's
# sqrt(8 pi a^3 E* w), finite strain (tools/punch_study.py):
# output/punch-study, and the plot into doc/figures. Finished runs are reused.
# From 20 a_cr on the detachment is one jump across the face: the runs allow
# it 4000 relaxation iterations (the default 400 stop it).
punch-study: build
	/usr/bin/python3 tools/punch_study.py --build $(BUILD_DIR) --output output/punch-study --jobs $(JOBS)
	cp output/punch-study/punch_study.png doc/figures/punch-study.png

# A strip peeled from a rigid substrate (inputs/peel.xml) at 15 .. 170 degrees
# for w/(E' h) = 1e-3 and 1e-2, plane strain, finite strain, against the
# energy balance of the strip held at its far end and Kendall's law, and three
# angles with the current-area surface density (tools/peel_study.py):
# output/peel-study, and the plot into doc/figures. Finished runs are reused.
peel-study: build
	/usr/bin/python3 tools/peel_study.py --build $(BUILD_DIR) --output output/peel-study --jobs $(JOBS)
	cp output/peel-study/peel_study.png doc/figures/peel-study.png

# Branch points: the tip lowered into a groove (inputs/tip-over-groove.xml: the
# tangent's eigenvalues, the symmetric path's two branch points and the
# asymmetric branch between them, about 30 s), plotted into doc/figures; and
# the two stability criteria (eigenvalues, parity of folds) on every deck of
# inputs/ (tools/stability_check.py: output/stability-check/table.csv; about
# an hour with JOBS=2).
branch-points: build
	$(BUILD_DIR)/bin/cgcm inputs/tip-over-groove.xml Output/Directory=output/tip-over-groove "Output/Print Steps=false"
	/usr/bin/python3 tools/plot_branches.py output/tip-over-groove --output doc/figures/branch-points.png
stability-check: build
	/usr/bin/python3 tools/stability_check.py --build $(BUILD_DIR) --output output/stability-check --jobs $(JOBS)

# The critical gammaW of the jump-to-contact for gammaL = 10 .. 200 (arc-length
# approaches, bisection with the fold detector): output/stability-map, and
# the plot into doc/figures.
stability-map: build
	/usr/bin/python3 tools/stability_map.py --build $(BUILD_DIR) --output output/stability-map
	cp output/stability-map/stability_map.png doc/figures/stability-map.png

# The 3D quarter sphere on half-space on the mesh that meets 2 % against the
# axisymmetric default deck (P_min over the path and dP/du on [0.05, 0.06]):
# 14k dofs, about 3 minutes on 2 ranks (doc/validation.md).
SPHERE3D_OUT ?= output/3d/sphere-on-half-space-14k
sphere-3d: build
	mpirun --allow-run-as-root --oversubscribe --mca mpi_yield_when_idle 1 -np 2 \
	  $(BUILD_DIR)/bin/cgcm inputs/3d/sphere-on-half-space.xml Output/Directory=$(SPHERE3D_OUT) \
	  "Output/Print Steps=false" "Geometry/Mesh Numbers/lcSphere=0.1" "Geometry/Mesh Numbers/lcFar=0.8" \
	  "Geometry/Mesh Numbers/zone=0.5"
	/usr/bin/python3 tests/tools/check_load_curve.py pulloff $(SPHERE3D_OUT)/load_curve.csv \
	  --expected=-5.6355e-4 --tolerance 0.02
	/usr/bin/python3 tests/tools/check_load_curve.py stiffness $(SPHERE3D_OUT)/load_curve.csv \
	  --from 0.05 --to 0.06 --expected 0.2616 --tolerance 0.02

# Method 1 (volume pairs) against Method 3 on the benchmark: gammaL = 50, 200,
# 20 with cells of 1.25 r0 at the surfaces, Method 1 again on a contact zone
# half as wide and on the next mesh level (every cell halved); gammaL = 5, 2 (whole bodies within 10 r0) with a 5 r0 cutoff on the
# approach to P_min, and gammaL = 50 the same for the cutoff's effect
# (output/validation/method-study/table.csv; doc/validation.md; about an hour).
method-study: build
	@bash tools/run_method_study.sh $(BUILD_DIR) 50 200 20
	@ZONE_FACTOR=12.5 METHODS="volume pair" bash tools/run_method_study.sh $(BUILD_DIR) 200 50 20
	@LEVEL=1 METHODS="volume pair" bash tools/run_method_study.sh $(BUILD_DIR) 200 50
	@CUTOFF=5 APPROACH=-1,0.5 bash tools/run_method_study.sh $(BUILD_DIR) 50 5 2
	/usr/bin/python3 tools/plot_method_study.py output/validation/method-study --output doc/figures/method1-vs-method3.png

clean:
	rm -rf $(BUILD_DIR) $(BUILD_DIR).configure.log
