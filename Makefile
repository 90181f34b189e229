# appear.h - build, test, bench and demo.
#   make test    the whole suite: the reference check (tests/check_refs.py),
#                compile matrix (C99/C11/C++11/C++17, gcc and
#                clang, two TUs, tests/check.h alone as C and C++, nvcc if
#                present; the first failure stops it), the robustness sweep under
#                IEEE and -ffast-math builds (tests/robust.c), the libFuzzer
#                drivers 10 s per family (tests/fuzz/), the test suite, and the
#                test suite again under -fsanitize=address,undefined (quick mode)
#   make fuzz    the libFuzzer drivers, FUZZ_TIME seconds per family (default 300)
#   make check   the unit tests alone (compiler and libm only), quick mode: about 37 s + build
#   make check-refs  the citation keys of appear.h against its one REFERENCES list
#   make check-style the header's width (at most 5% of lines over 100 columns, none over 120),
#                and the tests' random draws sequenced (tests/check_sequenced.py)
#   make demo    renders the validation scenes to examples/out/ (EXR + PNG), the spectral
#                ones (metals, prism) by the spectral build, build/trace-spectral
#   make run-check  each subcommand of build/appear-check once, small counts
#   make bench   throughput and speed-against-error tables, CSV in bench/out/
#   make clean
CC       ?= cc
CLANG    ?= clang
WARN      = -Wall -Wextra -Werror
# recursive (=) so that they are read after `deps` has installed the packages
EXR_CFLAGS = $(shell pkg-config --cflags OpenEXR libpng 2>/dev/null)
IMG_LIBS   = $(shell pkg-config --libs OpenEXR libpng 2>/dev/null | tr ' ' '\n' | grep -E '^-L|OpenEXRCore|png' | tr '\n' ' ') -lm
B = build

TEST_SRC  = tests/main.c tests/harness.c tests/battery.c examples/image_io.c examples/tracer.c examples/scenes.c examples/openpbr_presets.c $(sort $(wildcard tests/test_*.c))
BENCH_SRC = bench/main.c bench/bench.c $(sort $(wildcard bench/bench_*.c))
GEN_DEPS  = tests/gen/gen_materials.c tests/gen/materials_data.h
HDRS      = $(GEN_DEPS) appear.h tests/harness.h tests/profiles.h tests/check.h tests/adapters.h tests/battery.h bench/bench.h examples/image_io.h examples/tracer.h examples/openpbr_presets.h

.PHONY: all test check demo bench bench-images clean deps check-compile check-refs check-style run-tests run-tests-log run-sanitized run-robust run-check fuzz run-fuzz
all: $(B)/test_appear $(B)/appear-check

# ---- dependencies: OpenEXR (OpenEXRCore) and libpng for image output ----
deps:
	@if ! pkg-config --exists OpenEXR libpng; then \
	  if [ "$$(id -u)" = 0 ] && command -v apt-get >/dev/null; then \
	    echo "installing libopenexr-dev libpng-dev (apt-get)"; \
	    (apt-get update -qq && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq libopenexr-dev libpng-dev pkg-config) >/dev/null || exit 1; \
	  else \
	    echo "error: OpenEXR and libpng development files are missing: apt-get install libopenexr-dev libpng-dev pkg-config"; exit 1; \
	  fi; \
	fi

$(B):
	@mkdir -p $(B)

$(B)/suites.h: $(wildcard tests/test_*.c) | $(B)
	@grep -ho '^void suite_[a-z0-9_]*' $(sort $(wildcard tests/test_*.c)) | awk '!seen[$$0]++' | \
	  sed 's/^void \(.*\)/X(\1)/' > $@

$(B)/benches.h: $(wildcard bench/bench_*.c) | $(B)
	@grep -ho '^void bench_[a-z0-9_]*' $(sort $(wildcard bench/bench_*.c)) | awk '!seen[$$0]++' | sed 's/^void \(.*\)/X(\1)/' > $@

$(B)/test_appear: $(TEST_SRC) $(HDRS) examples/appear_check.c $(B)/suites.h | deps
	$(CC) -std=c99 -O2 -g $(WARN) -I$(B) $(EXR_CFLAGS) $(TEST_SRC) -o $@ $(IMG_LIBS)

# ---- make check: the unit tests alone, compiler and libm only (no OpenEXR, no
# tracer, no appear-check), quick mode: under a minute. make test is the whole suite.
# Built with APPEAR_NO_DEPRECATED: the tests use the current names only.
UNIT_TESTS = $(filter-out tests/test_tracer.c tests/test_check.c,$(sort $(wildcard tests/test_*.c)))
$(B)/unit/suites.h: $(UNIT_TESTS) | $(B)
	@mkdir -p $(B)/unit && grep -ho '^void suite_[a-z0-9_]*' $(UNIT_TESTS) | awk '!seen[$$0]++' | \
	  sed 's/^void \(.*\)/X(\1)/' > $@
$(B)/test_unit: tests/main.c tests/harness.c tests/battery.c $(UNIT_TESTS) appear.h tests/harness.h tests/check.h tests/adapters.h tests/battery.h tests/profiles.h $(B)/unit/suites.h $(GEN_DEPS)
	$(CC) -std=c99 -O2 $(WARN) -DH_NO_IMAGES -DAPPEAR_NO_DEPRECATED -I$(B)/unit tests/main.c tests/harness.c tests/battery.c $(UNIT_TESTS) -o $@ -lm
check: $(B)/test_unit
	APPEAR_TEST_QUICK=1 ./$(B)/test_unit

$(B)/test_sanitized: $(TEST_SRC) $(HDRS) examples/appear_check.c $(B)/suites.h | deps
	$(CC) -std=c99 -O1 -g -fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer $(WARN) -I$(B) $(EXR_CFLAGS) $(TEST_SRC) -o $@ $(IMG_LIBS)

# ---- the header compiles everywhere a renderer may put it ----
TU = tests/compile/tu1.c tests/compile/tu2.c
# tests/check.h on its own: its header example with CHECK_IMPLEMENTATION in one TU, a second
# TU with the declarations alone (one definition of each function, C and C++ alike)
TU_CHECK = tests/compile/tu_check.c tests/compile/tu_check2.c
# the warning set renderers build with: clean, -Werror
STRICT_C   = -Wconversion -Wdouble-promotion -Wshadow -Wcast-qual -Wundef -Wstrict-prototypes -Wmissing-prototypes -Wfloat-equal
STRICT_CXX = -Wconversion -Wdouble-promotion -Wshadow -Wcast-qual -Wundef -Wfloat-equal -Wold-style-cast -Wzero-as-null-pointer-constant
# every part's switch, read from the header (a banner's "Switch: APPEAR_NO_X" with its
# "#define APPEAR_HAS_X 1"): a new part joins the all-off build and the parts check by itself
NO_PARTS := $(shell sh tests/compile/parts.sh appear.h)
check-compile: | $(B)
	@set -e; \
	for cc in "$(CC) -std=c99 -pedantic" "$(CC) -std=c11 -pedantic" "$(CLANG) -std=c99 -pedantic" "$(CLANG) -std=c11 -pedantic" \
	          "$(CC) -std=c99 -pedantic $(NO_PARTS)" "$(CC) -std=c99 -pedantic -DAPPEAR_NO_FLAKES" \
	          "$(CC) -std=c99 -pedantic -DAPPEAR_NO_PHASE_EXTRA" "$(CC) -std=c99 -pedantic -DAPPEAR_USE_LIBM" "$(CC) -std=c99 -O3 -ffast-math" "$(CLANG) -std=c99 -O3 -ffast-math" \
	          "$(CC) -std=c99 -pedantic -DAPPEAR_DEBUG" "$(CC) -std=c99 -O2 $(STRICT_C)" "$(CLANG) -std=c99 -O2 $(STRICT_C)"; do \
	  if command -v $${cc%% *} >/dev/null; then \
	    { $$cc $(WARN) -x c $(TU) -o $(B)/tu_c -lm && $(B)/tu_c && echo "compile ok: $$cc"; } || \
	      { echo "compile FAILED: $$cc"; exit 1; }; \
	  else echo "compile skipped (not installed): $$cc"; fi; \
	done; \
	for cxx in "g++ -std=c++11" "g++ -std=c++17" "clang++ -std=c++11" "clang++ -std=c++17" \
	           "g++ -std=c++11 -DAPPEAR_DEBUG" "g++ -std=c++17 -O2 $(STRICT_CXX)" "clang++ -std=c++17 -O2 $(STRICT_CXX)"; do \
	  if command -v $${cxx%% *} >/dev/null; then \
	    { $$cxx $(WARN) -x c++ $(TU) -o $(B)/tu_cxx && $(B)/tu_cxx && echo "compile ok: $$cxx"; } || \
	      { echo "compile FAILED: $$cxx"; exit 1; }; \
	  else echo "compile skipped (not installed): $$cxx"; fi; \
	done; \
	for cc in "$(CC) -std=c99 -pedantic -x c" "$(CLANG) -std=c99 -pedantic -x c" \
	          "g++ -std=c++11 -x c++" "clang++ -std=c++11 -x c++" "g++ -std=c++17 -O2 -x c++"; do \
	  if command -v $${cc%% *} >/dev/null; then \
	    { $$cc $(WARN) $(TU_CHECK) -o $(B)/tu_check -lm && $(B)/tu_check && \
	      echo "compile ok: tests/check.h, $$cc"; } || { echo "compile FAILED: tests/check.h, $$cc"; exit 1; }; \
	  else echo "compile skipped (not installed): $$cc"; fi; \
	done; \
	sh tests/compile/parts.sh appear.h $(CC) -std=c99 -pedantic $(WARN); \
	if command -v $(CLANG) >/dev/null; then sh tests/compile/parts.sh appear.h $(CLANG) -std=c99 -pedantic $(WARN); fi; \
	$(CC) -std=c99 -O0 $(WARN) -c tests/compile/tu_lambert.c -o $(B)/tu_lambert.o; \
	sz=$$(size $(B)/tu_lambert.o | awk 'NR == 2 {print $$1 + $$2}'); \
	if [ "$$sz" -gt 16384 ]; then echo "a Lambert-only object at -O0 has $$sz bytes: unused tables emitted?"; exit 1; fi; \
	echo "compile ok: Lambert-only object at -O0, $$sz bytes (no tables)"; \
	if command -v nvcc >/dev/null; then \
	  { nvcc -x cu -std=c++17 -Werror all-warnings -c tests/compile/tu1.c -o $(B)/tu1_cu.o && echo "compile ok: nvcc -x cu"; } || \
	    { echo "compile FAILED: nvcc -x cu"; exit 1; }; \
	  tests/gpu/footprint.sh $(B)/gpu; \
	else echo "compile skipped (not installed): nvcc"; fi

# ---- the robustness contract under the flags renderers build with ----
# tests/robust.c (compiler and libm only): every public function on adversarial
# inputs, checked on the bits; IEEE and -O3 -ffast-math (FTZ/DAZ on) with gcc
# and clang. ROBUST_N inputs per group (a fuzz-length run: ROBUST_N=5000000).
ROBUST_N ?= 200000
ROBUST_BUILDS = "$(CC) -O2" "$(CC) -O3 -ffast-math" "$(CLANG) -O3 -ffast-math" "$(CLANG) -O2 -ffinite-math-only"
run-robust: | $(B)
	@set -e; i=0; for cc in $(ROBUST_BUILDS); do i=$$((i + 1)); \
	  if command -v $${cc%% *} >/dev/null; then \
	    $$cc -std=c99 $(WARN) tests/robust.c -o $(B)/robust_$$i -lm; \
	    ./$(B)/robust_$$i $(ROBUST_N) > $(B)/robust_$$i.log || { cat $(B)/robust_$$i.log; echo "robust failed: $$cc"; exit 1; }; \
	    echo "$$(tail -1 $(B)/robust_$$i.log) [$$cc]"; \
	  else echo "robust skipped (not installed): $$cc"; fi; \
	done

# ---- libFuzzer over the same contract (tests/fuzz/fuzz.c): one binary, a family per run ----
#   make fuzz                 each family FUZZ_TIME seconds (default 300), corpus
#                             tests/fuzz/corpus/<family> (read) + $(B)/fuzz_out/<family> (new units)
#   make fuzz FUZZ_FAMILIES=ward FUZZ_TIME=3600
#   make run-fuzz             (in make test) each family 6 s from the committed corpus
# A finding aborts with the contract's message; libFuzzer saves the input as
# $(B)/fuzz_out/<family>-crash-<sha1>: replay with
#   APPEAR_FUZZ_FAMILY=<family> ./$(B)/fuzz $(B)/fuzz_out/<family>-crash-<sha1>
FUZZ_FAMILIES ?= core lambert eon sheen phase ward microfacet_blocks microfacet_models media media_chromatic flakes batch generic extremes layered materials openpbr
FUZZ_TIME ?= 300
FUZZ_FLAGS = -std=c99 -O1 -g -fsanitize=fuzzer,address,undefined -fno-sanitize-recover=all $(WARN)
$(B)/fuzz: tests/fuzz/fuzz.c tests/robust.c appear.h | $(B)
	$(CLANG) $(FUZZ_FLAGS) tests/fuzz/fuzz.c -o $@ -lm
fuzz: $(B)/fuzz
	@set -e; mkdir -p $(B)/fuzz_out; for f in $(FUZZ_FAMILIES); do mkdir -p $(B)/fuzz_out/$$f tests/fuzz/corpus/$$f; \
	  APPEAR_FUZZ_FAMILY=$$f ./$(B)/fuzz $(B)/fuzz_out/$$f tests/fuzz/corpus/$$f -max_total_time=$(FUZZ_TIME) \
	    -print_final_stats=1 -artifact_prefix=$(B)/fuzz_out/$$f- > $(B)/fuzz_out/$$f.log 2>&1 || \
	    { tail -30 $(B)/fuzz_out/$$f.log; echo "fuzz $$f: FINDING (input saved as $(B)/fuzz_out/$$f-crash-*)"; exit 1; }; \
	  echo "fuzz $$f: $$(grep -o 'Done [0-9]* runs in [0-9]* second' $(B)/fuzz_out/$$f.log), nothing found"; done
run-fuzz: | $(B)
	@if command -v $(CLANG) >/dev/null && echo 'int LLVMFuzzerTestOneInput(const char *d, unsigned long n){(void)d;(void)n;return 0;}' | \
	  $(CLANG) -fsanitize=fuzzer -x c - -o $(B)/fuzz_probe 2>/dev/null; then \
	  $(MAKE) --no-print-directory fuzz FUZZ_TIME=$${FUZZ_TIME_CI:-6}; \
	else echo "fuzz skipped: $(CLANG) without -fsanitize=fuzzer"; fi

run-tests: $(B)/test_appear
	./$(B)/test_appear

run-sanitized: $(B)/test_sanitized
	@APPEAR_TEST_QUICK=1 ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1 ./$(B)/test_sanitized > $(B)/sanitized.log 2>&1; \
	  rc=$$?; tail -3 $(B)/sanitized.log; grep -E '^FAIL|runtime error|ERROR: AddressSanitizer' $(B)/sanitized.log | head -20; \
	  if [ $$rc -ne 0 ]; then echo "sanitized test run failed (rc=$$rc, log: $(B)/sanitized.log)"; exit 1; fi

# ---- the one reference list: every [Key] cited in appear.h is defined once
# in its REFERENCES block and every entry is cited (tests/check_refs.py) ----
check-refs:
	@if command -v python3 >/dev/null; then python3 tests/check_refs.py appear.h; \
	else echo "check-refs skipped: python3 not installed"; fi

# the header's width: at most 5% of its lines over 100 columns, none over 120
# (.clang-format holds the style; tests/check_style.sh counts)
# and the tests' random draws in a fixed order: no two in one call's arguments
# or one operator's operands (C leaves that order unspecified; tests/check_sequenced.py)
check-style:
	@sh tests/check_style.sh appear.h
	@if command -v python3 >/dev/null; then python3 tests/check_sequenced.py; \
	else echo "check_sequenced skipped: python3 not installed"; fi

# The closing line of `make test` is the suite's own "N passed, M failed". The parts are
# independent (each builds its own binaries in $(B)): they run two at a time (CI machines
# have 2 cores), each part's output kept together (-O); the whole suite's log is
# $(B)/tests.log, its failures and closing line printed last.
TEST_PARTS = run-tests-log run-sanitized check-refs check-style check-compile run-robust run-fuzz run-check
test: deps
	@$(MAKE) --no-print-directory -j2 -O $(TEST_PARTS) || { rc=$$?; \
	  if [ -f $(B)/tests.log ]; then grep -E '^FAIL' $(B)/tests.log | head -20; tail -1 $(B)/tests.log; fi; exit $$rc; }
	@grep -E '^FAIL' $(B)/tests.log | head -20; tail -1 $(B)/tests.log
run-tests-log: $(B)/test_appear
	@./$(B)/test_appear > $(B)/tests.log 2>&1; rc=$$?; grep -E '^measure' $(B)/tests.log | tail -5; \
	  if [ $$rc -ne 0 ]; then echo "test suite failed (rc=$$rc, log: $(B)/tests.log)"; exit 1; fi

# ---- bench: timed builds, callgrind counts, one joined report, plots ----
# Timed: gcc -O2, gcc -O3 -march=native -fno-math-errno, clang -O3 -march=native
# -fno-math-errno (CSV bench/out/bench_<build>.csv). Instruction counts: callgrind
# (valgrind 3.19 cannot run AVX-512, so on -O2 and on gcc -O3 -fno-math-errno without
# -march=native), quick mode, all benches but media (CSV callgrind_<build>.csv + dumps).
# bench/report.py joins everything into bench/out/report.md + bench_all.csv + plot data;
# bench/plots.gp draws bench/out/*.png; `make bench-images` refreshes bench/images/.
BENCH_CG := $(shell test -f /usr/include/valgrind/callgrind.h && echo -DBENCH_CALLGRIND)
BENCH_CG_SET = core special ward microfacet flakes batch multiscatter media_homog
$(B)/bench_O2: $(BENCH_SRC) appear.h bench/bench.h $(B)/benches.h
	$(CC) -std=c99 -O2 $(WARN) -I$(B) -DBENCH_BUILD='"O2"' $(BENCH_CG) $(BENCH_SRC) -o $@ -lm
$(B)/bench_O3: $(BENCH_SRC) appear.h bench/bench.h $(B)/benches.h
	$(CC) -std=c99 -O3 -fno-math-errno $(WARN) -I$(B) -DBENCH_BUILD='"O3"' $(BENCH_CG) $(BENCH_SRC) -o $@ -lm
$(B)/bench_O3native: $(BENCH_SRC) appear.h bench/bench.h $(B)/benches.h
	$(CC) -std=c99 -O3 -march=native -fno-math-errno $(WARN) -I$(B) -DBENCH_BUILD='"O3native"' $(BENCH_SRC) -o $@ -lm
$(B)/bench_clang_O3native: $(BENCH_SRC) appear.h bench/bench.h $(B)/benches.h
	$(CLANG) -std=c99 -O3 -march=native -fno-math-errno $(WARN) -I$(B) -DBENCH_BUILD='"clang_O3native"' $(BENCH_SRC) -o $@ -lm
BENCH_BINS = $(B)/bench_O2 $(B)/bench_O3 $(B)/bench_O3native $(shell command -v $(CLANG) >/dev/null && echo $(B)/bench_clang_O3native)
bench: $(BENCH_BINS)
	@mkdir -p bench/out && rm -f bench/out/bench_*.csv bench/out/callgrind_*.csv bench/out/*.png
	@for b in O2 O3native clang_O3native; do [ -x $(B)/bench_$$b ] || continue; \
	  echo "== timing $$b (raw table: bench/out/raw_$$b.txt)"; ./$(B)/bench_$$b > bench/out/raw_$$b.txt || exit 1; done
	@if command -v valgrind >/dev/null && [ -n "$(BENCH_CG)" ]; then \
	  for b in O2 O3; do echo "== callgrind $$b, quick mode, all but media (log: bench/out/callgrind_$$b.log)"; \
	    rm -rf bench/out/cg_$$b && mkdir -p bench/out/cg_$$b && \
	    APPEAR_BENCH_QUICK=1 valgrind --tool=callgrind --instr-atstart=no --callgrind-out-file=bench/out/cg_$$b/cg.out \
	      ./$(B)/bench_$$b $(BENCH_CG_SET) > bench/out/callgrind_$$b.log 2>&1 || exit 1; done; \
	else echo "== valgrind or <valgrind/callgrind.h> missing: no instruction counts"; fi
	@python3 bench/report.py
	@if command -v gnuplot >/dev/null; then gnuplot bench/plots.gp && echo "== plots: bench/out/*.png"; \
	else echo "== gnuplot missing (apt-get install gnuplot-nox): plots skipped"; fi
# small copies of the plots for the README (run after make bench)
bench-images:
	@mkdir -p bench/images && for f in bench/out/*.png; do cp $$f bench/images/; done; ls -l bench/images

# ---- demo: the validation scenes ----
TRACE_SRC = examples/trace.c examples/tracer.c examples/scenes.c examples/image_io.c examples/openpbr_presets.c
TRACE_HDRS = examples/tracer.h examples/image_io.h examples/cie_data.h examples/openpbr_presets.h appear.h
$(B)/trace: $(TRACE_SRC) $(TRACE_HDRS) | deps $(B)
	$(CC) -std=c99 -O2 -fno-math-errno $(WARN) $(EXR_CFLAGS) $(TRACE_SRC) -o $@ -pthread $(IMG_LIBS)
# the spectral build of the same sources: hero-wavelength sampling, 4 wavelengths a path (the width
# appear.h suggests), renders the spectral scenes (metals, prism) by default
$(B)/trace-spectral: $(TRACE_SRC) $(TRACE_HDRS) | deps $(B)
	$(CC) -std=c99 -O2 -fno-math-errno $(WARN) -DAPPEAR_SPECTRUM_SAMPLES=4 -DTRACER_SPECTRAL=1 \
	  $(EXR_CFLAGS) $(TRACE_SRC) -o $@ -pthread $(IMG_LIBS)
# the default scene set in about a minute on two cores (42 s measured, 20 s of it the layered pair,
# under load; the OpenPBR pair, openpbr and openpbr_furnace, adds 4.4 s, 6.2 s under load: 61 s
# measured then); larger: ./build/trace --scale 2 --spp 1024. Then the spectral scenes by the
# spectral build (metals and prism, each spectral and RGB: 8-11 s)
demo: $(B)/trace $(B)/trace-spectral $(B)/appear-check
	./$(B)/trace --out examples/out
	./$(B)/trace-spectral --out examples/out

# ---- appear-check: checks and timings of any model from the command line ----
# Built with the flags the README recommends for renderers, so that `bench` shows the
# vectorised batch figure; the program prints them (--version, --help, bench). tests/check.h's
# code is compiled in examples/appear_check.c (CHECK_IMPLEMENTATION).
CHECK_SRC    = examples/appear_check.c examples/image_io.c
CHECK_CFLAGS = -std=c99 -O3 -march=native -fno-math-errno
$(B)/appear-check: $(CHECK_SRC) tests/check.h tests/adapters.h examples/image_io.h appear.h | deps $(B)
	$(CC) $(CHECK_CFLAGS) $(WARN) -DAPPEAR_CHECK_CFLAGS='"$(CC) $(CHECK_CFLAGS)"' $(EXR_CFLAGS) \
	  $(CHECK_SRC) -o $@ $(IMG_LIBS)
# every subcommand once with small counts (a few seconds in all); fails on a nonzero exit
RUN_CHECK = \
	"furnace dielectric --dist ggx --alpha 0.3 --eta 1.5 --samples 20000" \
	"furnace conductor-ms --alpha 1 --eta 0 --k 0 --theta 0,60 --samples 5000" \
	"reciprocity dielectric --alpha 0.3 --eta 1.5 --samples 4000" \
	"reciprocity conductor --dist beckmann --alpha 0.1,0.4 --eta 0.2 --k 3.9 --samples 4000" \
	"chi2 hg --g 0.95 --theta 30 --samples 50000 --exr $(B)/check_chi2.exr --png $(B)/check_chi2.png" \
	"chi2 dielectric --alpha 0.3 --samples 50000" \
	"consistency ward --variant duer --alpha 0.1,0.2 --samples 5000" \
	"lobe ward --variant duer --alpha 0.1,0.2 --theta 60 --size 64 --png $(B)/check_lobe.png --exr $(B)/check_lobe.exr" \
	"lobe hg --g 0.7 --size 32 --csv" \
	"bench dielectric --alpha 0.3 --samples 100000" \
	"bench dielectric-ms --dist ggx --alpha 1 --eta 1.33 --samples 5000" \
	"transmittance --kind all --profile bump --tightness 0.5 --samples 4000" \
	"furnace conductor-f0 --f0 0.9,0.6,0.3 --theta 0,60 --samples 5000" \
	"chi2 conductor --f0 0.8 --alpha 0.4 --samples 20000" \
	"furnace eon --sigma 1 --albedo 1 --theta 0,60,89 --samples 20000" \
	"chi2 eon --sigma 0.7 --eon-sampling cosine --samples 20000" \
	"furnace sheen --alpha 0.5 --albedo 1 --theta 0,60 --samples 5000" \
	"transmittance --chromatic --profile bump --samples 2000" \
	"transmittance --chromatic --majorant per-channel --channels 0.5,1,2 --samples 2000" \
	"transmittance --free-flight --sigma-t 2 --length 1 --samples 20000" \
	"furnace mie --diameter 20 --theta 0 --samples 20000" \
	"furnace layered --alpha 0 --albedo 1 --theta 0,60 --samples 5000"
run-check: $(B)/appear-check
	@set -e; for a in $(RUN_CHECK); do echo "== appear-check $$a"; ./$(B)/appear-check $$a > $(B)/run-check.log 2>&1 || { cat $(B)/run-check.log; echo "run-check failed: appear-check $$a"; exit 1; }; tail -n 3 $(B)/run-check.log; done
	@for a in "furnace nosuchmodel" "furnace conductor --alpha -1" "furnace conductor --alpha" "furnace conductor --bogus 1" "chi2 hg --g x" \
	  "transmittance --free-flight --d 1" "transmittance --free-flight --sigma 1" "furnace mie --d 10" "furnace mie --length 1"; do \
	  ./$(B)/appear-check $$a >/dev/null 2>$(B)/run-check.err; rc=$$?; \
	  if [ $$rc -ne 2 ]; then echo "run-check: appear-check $$a exited $$rc, expected 2"; exit 1; fi; echo "bad input (exit 2): $$(cat $(B)/run-check.err)"; done

clean:
	rm -rf $(B) tests/out bench/out examples/out
