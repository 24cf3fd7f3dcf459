# Thin wrapper around CMake.  See README.md.
#   make build      gcc build in build/ (-Werror)
#   make build-clang  clang build in build-clang/ (-Werror)
#   make build-asan ASan+UBSan build in build-asan/
#   make test       all three builds, then tests/run_all.sh (package test and the
#                   Python package's pytest included)
#   make demo       the paper's numerical section (out/paper), the
#                   "why trigspline" page (out/why), the Python gallery (out/gallery)
#                   and the charts gallery (out/charts)
#   make web        the WebAssembly modules (SIMD128 and scalar) and the explorer page (out/web)
#   make test-web   Node and headless-Chromium tests of out/web, out/why and out/charts
#   make test-web-stack-full  stacked-area crossings on 1e5 random data sets
#   make bench      benchmark against GSL and the build decisions -> bench/RESULTS.md
#   make bench-python  the Python package against SciPy (also run by make bench)
#   make bench-web  the WebAssembly sorted batch (SIMD128 and scalar module) against the
#                   native portable kernel, with goal and verdict (also run by make bench)
#   make accuracy   convergence study -> docs/accuracy.md, docs/accuracy.svg
#   make valgrind   memcheck of the test programs
#   make tsan       ThreadSanitizer build of the threads and core tests
#   make coverage   line and branch coverage of the library (gcovr)
#   make test-r     the R package (bindings/r): R CMD build, install, smoke test and
#                   R CMD check --as-cran (tests included)
#   make test-constraints  the constraint records' property test, 10^6 problems
#   make test-surface-grids  surfaces between random gridded fields, 2 x 20000 problems
#   make fuzz       the libFuzzer harnesses, FUZZ_SECONDS each (corpus replay is in make test)
#   make dist       every package into dist/ (tools/dist/CHANNEL.sh build): Python wheel and
#                   sdist, musl tarball, Debian packages, the conda recipe checked, ...
#   make test-dist  make dist, then each package installed in a clean place and smoke-tested
#                   (tools/dist/CHANNEL.sh test); a summary table: channel, artifact, size, result
#   make test-musl  every C test program built with musl-gcc and run
# Each target installs the Debian packages it needs (apt-get) when missing.
# The compiler of a build directory is fixed when it is first configured
# (CC=gcc or CC=clang below); `make clean` starts over.
.PHONY: all build configure-build demo-tools build-asan build-clang test demo bench accuracy valgrind clean \
  python-deps bench-python r-deps test-r

JOBS ?= 2
CMAKE ?= cmake

all: build

# $(call need,COMMAND:PACKAGE ...): apt-get install the packages whose
# command is missing (one apt-get run for all of them).
define need
	@missing=""; for p in $(1); do command -v "$${p%%:*}" >/dev/null 2>&1 || \
	  missing="$$missing $${p#*:}"; done; \
	if [ -n "$$missing" ]; then echo "installing:$$missing"; \
	  apt-get update && DEBIAN_FRONTEND=noninteractive apt-get install -y $$missing; fi
endef
# $(call need_file,FILE,PACKAGE)
define need_file
	@test -e $(1) || { apt-get update && DEBIAN_FRONTEND=noninteractive apt-get install -y $(2); }
endef

BUILD_TOOLS := cmake:cmake gcc:gcc cc:gcc python3:python3
# PNG/PDF plots of the command (rsvg-convert) and their checks in tests/tools/test_realworld.py
PLOT_TEST_TOOLS := rsvg-convert:librsvg2-bin pdfinfo:poppler-utils pdftoppm:poppler-utils
TEST_TOOLS := valgrind:valgrind pkg-config:pkg-config readelf:binutils musl-gcc:musl-tools
# libc.a: the package test links a -static program
STATIC_LIBC := /usr/lib/$(shell gcc -print-multiarch 2>/dev/null || echo x86_64-linux-gnu)/libc.a

build: configure-build
	$(CMAKE) --build build -j $(JOBS)

# build/ configured once for both `build` and the demo's two programs.
configure-build:
	$(call need,$(BUILD_TOOLS))
	CC=gcc $(CMAKE) -S . -B build -DCMAKE_BUILD_TYPE=RelWithDebInfo \
	  -DTS_WERROR=ON >/dev/null

# What the demo pages run: the command and the GSL comparison program, not
# the test programs.
demo-tools: why-deps configure-build
	$(CMAKE) --build build -j $(JOBS) --target trigspline_cli gsl_eval

build-clang:
	$(call need,$(BUILD_TOOLS) clang:clang)
	CC=clang $(CMAKE) -S . -B build-clang -DCMAKE_BUILD_TYPE=RelWithDebInfo \
	  -DTS_WERROR=ON >/dev/null
	$(CMAKE) --build build-clang -j $(JOBS)

build-asan:
	$(call need,$(BUILD_TOOLS))
	CC=gcc $(CMAKE) -S . -B build-asan -DCMAKE_BUILD_TYPE=Debug \
	  -DTS_SANITIZE=ON >/dev/null
	$(CMAKE) --build build-asan -j $(JOBS)

test: why-deps python-deps r-deps build build-asan build-clang
	$(call need,$(TEST_TOOLS))
	$(call need,$(PLOT_TEST_TOOLS))
	$(call need_file,$(STATIC_LIBC),libc6-dev)
	$(call need_file,/usr/lib/python3/dist-packages/scipy/__init__.py,python3-scipy)
	tests/run_all.sh build build-asan build-clang

# Every program is checked (a failing one does not stop the others); the
# tests whose references need x87 long double detect at run time that
# valgrind computes it in double (th_long_double_wide, tests/th.h).
# test_kernel_bits compares the kernels' bits with a table of native runs;
# valgrind's emulation of FMA flips the sign of some zero results, so it is
# left out here (its memory use is the batch kernels', which test_batch covers).
# VALGRIND_BUILD: the build directory whose programs are checked (the default
# `build` is configured and built first; another one must be built already).
VALGRIND_BUILD ?= build
valgrind: $(if $(filter build,$(VALGRIND_BUILD)),build)
	$(call need,valgrind:valgrind)
	@failed=""; for t in $(VALGRIND_BUILD)/tests/test_*; do \
	  case $$t in *test_property|*test_fast|*test_random_inputs|*test_random_tool_inputs|*test_package|*test_kernel_bits) continue;; esac; \
	  [ -x $$t ] || continue; \
	  if valgrind -q --leak-check=full --errors-for-leak-kinds=all --error-exitcode=9 $$t >$$t.valgrind.log 2>&1; \
	  then echo "valgrind $$t: ok"; \
	  else echo "valgrind $$t: FAILED (log $$t.valgrind.log)"; tail -n 20 $$t.valgrind.log; failed="$$failed $$t"; fi; \
	done; \
	if [ -n "$$failed" ]; then echo "valgrind: FAILED:$$failed"; exit 1; fi; echo "valgrind: clean"

# Speed and memory against GSL, and the measurements behind the build
# decisions of docs/design.md: prints the tables, writes bench/RESULTS.md.
# Built by CMake (TS_BUILD_BENCH; bench/CMakeLists.txt), run by its run_bench target.
bench:
	$(call need,$(BUILD_TOOLS))
	$(call need_file,/usr/include/gsl/gsl_interp.h,libgsl-dev)
	CC=gcc $(CMAKE) -S . -B build-bench -DCMAKE_BUILD_TYPE=Release \
	  -DTS_BUILD_BENCH=ON -DTS_BUILD_TESTS=OFF -DTS_BUILD_EXAMPLES=OFF >/dev/null
	$(CMAKE) --build build-bench -j $(JOBS) --target run_bench
	$(MAKE) --no-print-directory bench-web BENCH_WEB_FLAGS="--out bench/RESULTS.md"
	$(MAKE) --no-print-directory bench-python
	$(call need,/usr/bin/time:time)
	$(CMAKE) --build build-bench -j $(JOBS) --target trigspline_cli
	bench/bench_stream.sh build-bench

# WebAssembly rows (bench/web_bench.mjs, node): the sorted batch of out/web's
# SIMD128 and scalar modules against the native library's portable C kernel
# (bench/web_native.c, built in build-bench as make bench builds it), in one
# run, rounds interleaved; prints the table and the goal rows (make bench
# appends them to bench/RESULTS.md: BENCH_WEB_FLAGS="--out FILE"; --quick:
# 1e5 knots, 1e6 queries).
.PHONY: bench-web
BENCH_WEB_FLAGS ?=
bench-web: web
	$(call need,$(BUILD_TOOLS) node:nodejs)
	$(call need_file,/usr/include/gsl/gsl_interp.h,libgsl-dev)
	CC=gcc $(CMAKE) -S . -B build-bench -DCMAKE_BUILD_TYPE=Release \
	  -DTS_BUILD_BENCH=ON -DTS_BUILD_TESTS=OFF -DTS_BUILD_EXAMPLES=OFF >/dev/null
	$(CMAKE) --build build-bench -j $(JOBS) --target web_native
	node bench/web_bench.mjs $(WEB_OUT) build-bench/bench/web_native $(BENCH_WEB_FLAGS)

# Convergence study (docs/accuracy.md): prints the tables, rewrites the
# results section of docs/accuracy.md and docs/accuracy.svg.  Compares with GSL.
accuracy: build
	$(call need_file,/usr/include/gsl/gsl_interp.h,libgsl-dev)
	$(CC) -std=c11 -O2 -Wall -Wextra -Iinclude -Ibuild/include accuracy/accuracy.c build/libtrigspline.a \
	  -lgsl -lgslcblas -lm -lpthread -o build/accuracy
	./build/accuracy --doc docs/accuracy.md --svg docs/accuracy.svg

# The main job: reproduce the paper's numerical section (Figures 2-7) as one page.
demo: demo-tools
	python3 scripts/paper_demo.py build/trigspline data/paper out/paper
	$(MAKE) --no-print-directory why-demo
	$(MAKE) --no-print-directory gallery
	$(MAKE) --no-print-directory charts-demo

clean:
	rm -rf build build-asan build-clang build-bench build-web build-coverage build-fuzz build-tsan \
	  build-musl bindings/python/build out dist build-r

# ---- Python package (bindings/python) --------------------------------------
# Debian's own interpreter (/usr/bin/python3, not another python3 on PATH)
# with numpy, SciPy, pytest, setuptools, wheel, venv/pip and Python.h.
PYTHON := /usr/bin/python3
PYTHON_PACKAGES := python3 python3-numpy python3-scipy python3-pytest python3-setuptools \
  python3-wheel python3-venv python3-pip python3-dev python3-xarray python3-dask \
  python3-distributed python3-pandas python3-matplotlib python3-netcdf4
python-deps:
	@$(PYTHON) -c 'import numpy, scipy, pytest, setuptools, wheel, ensurepip, xarray, dask, distributed, pandas, matplotlib, netCDF4, os, sys, sysconfig; \
	  sys.exit(not os.path.exists(os.path.join(sysconfig.get_paths()["include"], "Python.h")))' \
	  2>/dev/null || { apt-get update && \
	  DEBIAN_FRONTEND=noninteractive apt-get install -y $(PYTHON_PACKAGES); }

# ---- R package (bindings/r) -------------------------------------------------
# R with its headers and testthat (Debian); the R package's tests run in
# `make test` (bindings/r/tests/run.sh), the whole R CMD check here.
r-deps:
	$(call need_file,/usr/share/doc/r-base-dev,r-base-dev)
	$(call need_file,/usr/lib/R/site-library/testthat/DESCRIPTION,r-cran-testthat)

# tools/dist/r.sh: the source tarball into build-r/, installed into a temporary
# library and smoke-tested, then R CMD check --as-cran on it (the PDF manual
# only where pdflatex is installed: --no-manual otherwise).
test-r: r-deps
	rm -rf build-r
	tools/dist/r.sh build build-r
	R_CHECK=1 tools/dist/r.sh test build-r

# Python rows of the benchmark (bench/bench_python.py): the package installed
# into a fresh venv, against SciPy's PchipInterpolator in the same run.
bench-python: python-deps
	$(call need,$(BUILD_TOOLS))
	CC=gcc $(CMAKE) -S . -B build-bench -DCMAKE_BUILD_TYPE=Release \
	  -DTS_BUILD_TESTS=OFF -DTS_BUILD_EXAMPLES=OFF >/dev/null
	$(CMAKE) --build build-bench -j $(JOBS) --target trigspline_shared
	rm -rf build-bench/python-venv
	$(PYTHON) -m venv --system-site-packages build-bench/python-venv
	env -u PIP_FIND_LINKS PIP_NO_INDEX=1 build-bench/python-venv/bin/pip install -q \
	  --no-build-isolation ./bindings/python
	cd build-bench && python-venv/bin/python ../bench/bench_python.py
	cd build-bench && python-venv/bin/python ../bench/bench_xarray.py
	cd build-bench && python-venv/bin/python ../bench/bench_histo.py 400 && python-venv/bin/python ../bench/bench_histo.py 2000

# The gallery (out/gallery/index.html): figures of trigspline.plot, each with
# the code that made it (scripts/gallery.py, a few seconds).  The package is
# installed into build/gallery-venv once and again only when its sources change.
.PHONY: gallery
GALLERY_VENV := build/gallery-venv
GALLERY_SRC := $(wildcard bindings/python/trigspline/*.py bindings/python/src/*.c src/*.c \
  src/*.h include/*.h) bindings/python/setup.py CMakeLists.txt
$(GALLERY_VENV)/.installed: $(GALLERY_SRC)
	@$(MAKE) --no-print-directory python-deps
	rm -rf $(GALLERY_VENV)
	$(PYTHON) -m venv --system-site-packages $(GALLERY_VENV)
	env -u PIP_FIND_LINKS PIP_NO_INDEX=1 $(GALLERY_VENV)/bin/pip install -q \
	  --no-build-isolation ./bindings/python
	touch $@
gallery: $(GALLERY_VENV)/.installed
	$(GALLERY_VENV)/bin/python scripts/gallery.py out/gallery

# The companion page "why trigspline" (out/why): our curves beside SciPy's and
# GSL's on data/examples/, α guidance and the overshoot report.  Run by `make
# demo`; needs numpy, scipy, matplotlib for /usr/bin/python3 and GSL (gsl_eval).
WHY_DEPS := /usr/include/gsl/gsl_interp.h:libgsl-dev \
  /usr/lib/python3/dist-packages/numpy/__init__.py:python3-numpy \
  /usr/lib/python3/dist-packages/scipy/__init__.py:python3-scipy \
  /usr/lib/python3/dist-packages/matplotlib/__init__.py:python3-matplotlib \
  /usr/bin/python3:python3
.PHONY: why-deps why-demo test-why-page
why-deps:
	@missing=""; for p in $(WHY_DEPS); do test -e "$${p%%:*}" || missing="$$missing $${p#*:}"; done; \
	if [ -n "$$missing" ]; then echo "installing:$$missing"; \
	  apt-get update && DEBIAN_FRONTEND=noninteractive apt-get install -y $$missing; fi

why-demo: why-deps demo-tools
	/usr/bin/python3 scripts/why_demo.py build data/examples out/why

# Browser test of the why page: headless Chromium (Debian) driven by
# playwright-core (npm, tests/browser/package.json); screenshot + pixel check.
# Part of `make test-web`.
test-why-page: why-demo
	$(call need,chromium:chromium node:nodejs npm:npm)
	test -d tests/browser/node_modules/playwright-core || \
	  (cd tests/browser && npm install --no-audit --no-fund --loglevel=error)
	node tests/browser/why_page.mjs out/why/index.html
# ---- Web: the library as WebAssembly and the explorer page (bindings/web) ----
#   make web       out/web: trigspline.mjs (ES module, wasm embedded), trigspline.wasm
#                  (scalar) and trigspline-simd.wasm (SIMD128; the one loaded where the
#                  engine has it), trigspline-cli.mjs (the CLI, for the explorer's exports),
#                  index.html (the explorer), example.html (curve factory), sizes.txt
#   make test-web  Node tests (bit identity of both modules with a native build, every status, no leak,
#                  exports = the CLI's bytes) and the browser test (Chromium driven by
#                  playwright-core); screenshot and timings under out/web-test/;
#                  and the why page's browser test (test-why-page).
# Debian's emscripten (3.1.6); the same src/*.c.  emcc's JS optimizer needs Debian's
# acorn module, which a node not from Debian does not find by itself: NODE_PATH.
# ts_spline_eval_batch_mt is not exported (no threads in the module), so pthreads are not linked.
.PHONY: web test-web
WEB_BUILD := build-web
WEB_OUT := out/web
# -O2, not -Oz: -Oz is 10 KB (gzipped) smaller but its results differ from the
# native build's in the last bits (the geometric-mean slopes), docs/design.md.
WEB_EMCC := NODE_PATH=/usr/share/nodejs emcc -std=c11 -O2 -Iinclude -I$(WEB_BUILD)/include
# trigspline_version.h, generated from CMakeLists.txt's project() as CMake does
WEB_VERSION_H := $(WEB_BUILD)/include/trigspline_version.h
WEB_WARN := -Wall -Wextra -Wpedantic -Wshadow -Wconversion -Wdouble-promotion \
  -Wstrict-prototypes -Wmissing-prototypes -Wformat=2 -Werror
WEB_LIB_SRC := $(wildcard src/*.c)
WEB_CLI_SRC := $(wildcard tools/support/tsu_*.c) $(wildcard tools/cli/*.c)
WEB_FUNCS := ts_version ts_strerror ts_status_name ts_vocab_name ts_vocab_count ts_spline_free ts_spline_intervals ts_spline_x \
  ts_spline_f ts_spline_slopes ts_spline_alpha ts_spline_beta ts_spline_form ts_spline_shape \
  ts_spline_extrapolation ts_spline_a ts_spline_control ts_spline_certified ts_spline_eval_deriv \
  ts_spline_eval_batch ts_spline_eval_mode ts_spline_eval_batch_mode ts_spline_solve \
  ts_spline_find_interval ts_spline_integral ts_slopes_compute ts_spline_error_bound ts_curve_free ts_curve_segments \
  ts_curve_dim ts_curve_closed ts_curve_knots ts_curve_control ts_curve_params ts_curve_eval \
  ts_curve_sample ts_curve_length tsw_spline_new tsw_curve_new tsw_defaults tsw_curve_defaults \
  tsw_report tsw_certify tsw_curve_certify tsw_error_constants tsw_heap_top ts_error_message \
  tsw_message tsw_message_clear tsw_constraints tsw_constraint_report ts_spline_constraints malloc free \
  tsw_disaggregate tsw_histo_defaults tsw_simd
web_comma := ,
web_space := $(web_empty) $(web_empty)
WEB_EXPORTS := $(subst $(web_space),$(web_comma),$(patsubst %,'_%',$(WEB_FUNCS)))

web: $(WEB_OUT)/index.html

$(WEB_VERSION_H): CMakeLists.txt cmake/trigspline_version.h.in scripts/version.py
	python3 scripts/version.py --header $@

# the library: a standalone wasm (imports only its memory), 2 MB initial
# (trigspline.js creates the memory: keep the two in step); twice from the
# same sources: trigspline.wasm (scalar, MVP) and trigspline-simd.wasm
# (-msimd128: the compiler vectorises the batch kernel's loops with 128-bit
# vectors, src/kernels.c); trigspline.js loads the SIMD one where the engine
# validates a SIMD probe.
WEB_LIB_DEPS := $(WEB_LIB_SRC) src/internal.h include/trigspline.h bindings/web/glue.c $(WEB_VERSION_H)
WEB_LIB_LINK := -sSTANDALONE_WASM --no-entry -sIMPORTED_MEMORY -sINITIAL_MEMORY=2MB -sTOTAL_STACK=1MB \
  -sALLOW_MEMORY_GROWTH -sMAXIMUM_MEMORY=2GB -sFILESYSTEM=0 -sEXPORTED_FUNCTIONS="[$(WEB_EXPORTS)]"
$(WEB_BUILD)/trigspline.wasm: $(WEB_LIB_DEPS)
	$(call need,emcc:emscripten node:nodejs)
	@mkdir -p $(WEB_BUILD)
	$(WEB_EMCC) $(WEB_WARN) -Isrc $(WEB_LIB_SRC) bindings/web/glue.c $(WEB_LIB_LINK) -o $@
$(WEB_BUILD)/trigspline-simd.wasm: $(WEB_LIB_DEPS)
	$(call need,emcc:emscripten node:nodejs)
	@mkdir -p $(WEB_BUILD)
	$(WEB_EMCC) -msimd128 $(WEB_WARN) -Isrc $(WEB_LIB_SRC) bindings/web/glue.c $(WEB_LIB_LINK) -o $@

# the command-line tool with an in-memory file system, called by the explorer's exports
$(WEB_BUILD)/trigspline-cli.js: $(WEB_LIB_SRC) $(WEB_CLI_SRC) tools/cli/cli.h tools/support/tsu_io.h \
  tools/support/tsu_plot.h include/trigspline.h $(WEB_VERSION_H)
	$(call need,emcc:emscripten node:nodejs)
	@mkdir -p $(WEB_BUILD)
	$(WEB_EMCC) $(WEB_WARN) -Itools/support -Itools/cli $(WEB_LIB_SRC) $(WEB_CLI_SRC) \
	  -sMODULARIZE -sEXPORT_NAME=createTrigsplineCli -sSINGLE_FILE -sENVIRONMENT=web \
	  -sINVOKE_RUN=0 -sEXIT_RUNTIME=0 -sALLOW_MEMORY_GROWTH -sFORCE_FILESYSTEM \
	  -sEXPORTED_RUNTIME_METHODS='["FS","callMain"]' -o $@

$(WEB_OUT)/index.html: $(WEB_BUILD)/trigspline.wasm $(WEB_BUILD)/trigspline-simd.wasm $(WEB_BUILD)/trigspline-cli.js \
  $(wildcard bindings/web/*.js bindings/web/*.mjs bindings/web/*.mts bindings/web/explorer/*)
	node bindings/web/build.mjs $(WEB_BUILD) $(WEB_OUT)

# Native references for the Node test: the same sources with musl's libm (the
# libm emscripten ships) and the portable batch kernel (no AVX2/FMA clone), so
# wasm and native must agree bit for bit.
$(WEB_BUILD)/reference-musl: $(WEB_LIB_SRC) bindings/web/test/reference.c include/trigspline.h \
  $(WEB_VERSION_H)
	$(call need,musl-gcc:musl-tools)
	@mkdir -p $(WEB_BUILD)
	musl-gcc -std=c11 -O2 -DTS_FAST_PORTABLE $(WEB_WARN) -Iinclude -I$(WEB_BUILD)/include -Isrc $(WEB_LIB_SRC) \
	  bindings/web/test/reference.c -lm -o $@
$(WEB_BUILD)/trigspline-musl: $(WEB_LIB_SRC) $(WEB_CLI_SRC) include/trigspline.h $(WEB_VERSION_H)
	$(call need,musl-gcc:musl-tools)
	@mkdir -p $(WEB_BUILD)
	musl-gcc -std=c11 -O2 -DTS_FAST_PORTABLE $(WEB_WARN) -Iinclude -I$(WEB_BUILD)/include -Isrc -Itools/support \
	  -Itools/cli $(WEB_LIB_SRC) $(WEB_CLI_SRC) -lm -o $@

test-web: web build $(WEB_BUILD)/reference-musl $(WEB_BUILD)/trigspline-musl test-why-page charts-demo
	$(call need,node:nodejs npm:npm)
	$(call need_file,/usr/bin/chromium,chromium)
	$(WEB_NODE_MODULES)
	bindings/web/test/run.sh $(WEB_OUT) $(WEB_BUILD) build out/web-test $(CHARTS_OUT)

# bindings/web's npm packages (package-lock.json): playwright-core drives
# Chromium; d3, chart.js and echarts are what the chart plugins are tested
# against and what the gallery inlines; typescript checks trigspline.d.ts.
WEB_NODE_MODULES = @for p in playwright-core d3 chart.js echarts typescript; do \
	  test -e bindings/web/node_modules/$$p/package.json || { (cd bindings/web && npm ci --no-audit --no-fund) && break; }; done

# The charts gallery (out/charts/index.html, one static page that works from
# file://): d3, Chart.js and ECharts before and after on d3-shape#81's data and
# on real series, with the cost of each crossing.  Part of `make demo`.
.PHONY: charts-demo test-web-stack-full
CHARTS_OUT := out/charts
charts-demo: web
	$(call need,node:nodejs npm:npm)
	$(WEB_NODE_MODULES)
	node bindings/web/gallery/build.mjs $(WEB_OUT) $(CHARTS_OUT)

# The stacked-area crossing measurement on 1e5 random data sets (make test-web
# runs 2000 of them): out/web-test/stack-crossings-full.md.
test-web-stack-full: web
	$(call need,node:nodejs npm:npm)
	$(WEB_NODE_MODULES)
	node bindings/web/test/stack_full.mjs $(WEB_OUT) out/web-test 100000

# ---- rates from bin totals at full size (make test runs 10^4 series) ----
.PHONY: test-histo
test-histo: build
	TS_HISTO_SERIES=200000 build/tests/test_histo

# ---- the constraint records' property test at full size ----
# test_constraints runs 4000 random combined-constraint problems in make
# test; this runs 10^6 (docs/method.md §13; about 15 minutes on one core),
# and 10^5 of its slice with bound splines (§13.7; 1000 in make test).
.PHONY: test-constraints
test-constraints: build
	TS_CON_PROBLEMS=1000000 TS_CON_SPLINE_PROBLEMS=100000 build/tests/test_constraints

# ---- surfaces between gridded fields at full size (make test runs 300 of each
# kind; docs/method.md §11.7) ----
.PHONY: test-surface-grids
test-surface-grids: build
	TS_GRID_PROBLEMS=20000 build/tests/test_surface_grids

# ---- trust at the edges: thread sanitizer, coverage, fuzzing ----
.PHONY: tsan coverage fuzz

# ThreadSanitizer (gcc) build of the threaded batch test and the core test.
tsan:
	$(call need,$(BUILD_TOOLS))
	CC=gcc $(CMAKE) -S . -B build-tsan -DCMAKE_BUILD_TYPE=RelWithDebInfo \
	  -DCMAKE_C_FLAGS=-fsanitize=thread -DTS_BUILD_TOOLS=OFF -DTS_BUILD_EXAMPLES=OFF >/dev/null
	$(CMAKE) --build build-tsan -j $(JOBS) --target test_threads test_core
	TSAN_OPTIONS=halt_on_error=1 build-tsan/tests/test_threads
	TSAN_OPTIONS=halt_on_error=1 build-tsan/tests/test_core

# Line and branch coverage of the library (src/) by the C test programs of
# tests/api, tests/unit and the corpus replays of tests/fuzz (test_fuzz_*),
# gcc --coverage -O0; gcovr prints the per-file line and branch tables and
# writes COVERAGE_BUILD/coverage.json and coverage.html (per-line details).
#  - -DTS_VECTOR_LOOP= (src/internal.h): no target_clones, so each function
#    is counted once (gcov counts every clone, a run executes one of them);
#    -DTS_COVERAGE: the inline functions of src/internal.h are not forced
#    inline, so each is counted once per object, not once per call site
#    (gcovr adds up the objects that compile a file, branch by branch).
#    The run-time variants of kernels.c (ts__fast_batch_isa) are separate
#    functions and stay counted (tests/unit/test_fast.c calls each).
#    tests/isa is not built then (tests/isa/CMakeLists.txt): with no clones
#    it would only run test_core again over the same lines.
#  - --exclude-unreachable-branches: branches gcc adds on lines without a
#    source branch (at -O0); every branch written in src/ is counted.
#  - the tools' own tests (test_io, test_plot, test_random_tool_inputs,
#    test_package) measure tools/, not src/; they are not run.
#  - test_kernel_bits compares the kernels' bits with a table of product
#    builds; here the kernels' inline steps are separate functions
#    (TS_COVERAGE), and a*b + c is contracted into an FMA only within one
#    function, so the AVX2 and AVX-512 variants round differently (499 of
#    3840 values): not run (test_fast covers the same lines with tolerances).
# A failing test program fails the target (after the tables).
COVERAGE_BUILD ?= build-coverage
COVERAGE_GCOVR = gcovr -r . --object-directory $(COVERAGE_BUILD) --filter 'src/' \
  --exclude-unreachable-branches
coverage:
	$(call need,$(BUILD_TOOLS) gcovr:gcovr)
	CC=gcc $(CMAKE) -S . -B $(COVERAGE_BUILD) -DCMAKE_BUILD_TYPE=Debug -DTS_WERROR=ON \
	  -DCMAKE_C_FLAGS="--coverage -fprofile-update=atomic -O0 -DTS_VECTOR_LOOP= -DTS_COVERAGE" \
	  -DTS_BUILD_EXAMPLES=OFF >/dev/null
	$(CMAKE) --build $(COVERAGE_BUILD) -j $(JOBS)
	@if nm -A $(COVERAGE_BUILD)/libtrigspline.a 2>/dev/null | grep -E '\.(avx2|arch_x86_64_v4|default|resolver)$$'; then \
	  echo "coverage: target_clones left in the library (TS_VECTOR_LOOP)"; exit 1; fi
	find $(COVERAGE_BUILD) -name '*.gcda' -delete
	@set -e; failed=""; for t in $(COVERAGE_BUILD)/tests/test_*; do \
	  case $$t in *.log|*test_package*|*test_random_tool_inputs*|*test_io|*test_plot|*test_kernel_bits) continue;; esac; \
	  [ -x $$t ] || continue; echo "coverage: $$t"; \
	  $$t >$$t.log 2>&1 || { tail -n 20 $$t.log; failed="$$failed $$(basename $$t)"; }; done; \
	$(COVERAGE_GCOVR) --json $(COVERAGE_BUILD)/coverage.json \
	  --html-details $(COVERAGE_BUILD)/coverage.html; \
	gcovr -a $(COVERAGE_BUILD)/coverage.json --txt; \
	gcovr -a $(COVERAGE_BUILD)/coverage.json --branches --txt; \
	if [ -n "$$failed" ]; then echo "coverage: FAILED:$$failed (logs: $(COVERAGE_BUILD)/tests/*.log)"; exit 1; fi

# libFuzzer harnesses of tests/fuzz/ (clang, ASan+UBSan), each run for
# FUZZ_SECONDS seconds from its checked-in corpus (new inputs go to
# $(FUZZ_BUILD)/corpus/NAME, not into the repository), with the dictionary
# tests/fuzz/NAME.dict when there is one.  One summary line per harness;
# a harness that fails (crash, failed check, leak, timeout) leaves its input
# in $(FUZZ_BUILD)/artifacts/ and its log, the others still run, and the
# target fails.  `make test` replays the checked-in corpus through the same
# harnesses (test_fuzz_* programs).  FUZZ_FLAGS: more libFuzzer flags.
FUZZ_SECONDS ?= 60
FUZZ_BUILD ?= build-fuzz
FUZZ_FLAGS ?=
# the harnesses to run (default: every tests/fuzz/fuzz_NAME.c), e.g. FUZZ_HARNESSES="spline curve"
FUZZ_HARNESSES ?= $(patsubst tests/fuzz/fuzz_%.c,%,$(wildcard tests/fuzz/fuzz_*.c))
fuzz:
	$(call need,$(BUILD_TOOLS) clang:clang)
	$(call need_file,/usr/lib/llvm-14/lib/clang/14.0.6/lib/linux/libclang_rt.fuzzer-x86_64.a,libclang-rt-14-dev)
	CC=clang $(CMAKE) -S . -B $(FUZZ_BUILD) -DCMAKE_BUILD_TYPE=RelWithDebInfo -DTS_FUZZ=ON \
	  -DCMAKE_C_FLAGS="-fsanitize=fuzzer-no-link,address,undefined -fno-sanitize-recover=all" \
	  -DCMAKE_EXE_LINKER_FLAGS="-fsanitize=address,undefined" -DTS_BUILD_EXAMPLES=OFF >/dev/null
	$(CMAKE) --build $(FUZZ_BUILD) -j $(JOBS) --target fuzzers
	@failed=""; for n in $(FUZZ_HARNESSES); do \
	  b=$(FUZZ_BUILD); mkdir -p $$b/corpus/$$n $$b/artifacts; \
	  dict=""; test -f tests/fuzz/$$n.dict && dict="-dict=tests/fuzz/$$n.dict"; \
	  if TS_FUZZ_STATS=1 $$b/fuzz/fuzz_$$n -max_total_time=$(FUZZ_SECONDS) -timeout=30 -print_final_stats=1 \
	      -artifact_prefix=$$b/artifacts/$$n- $$dict $(FUZZ_FLAGS) \
	      $$b/corpus/$$n tests/fuzz/corpus/$$n >$$b/fuzz_$$n.log 2>&1; then st=ok; \
	  else st=FAILED; failed="$$failed $$n"; tail -n 40 $$b/fuzz_$$n.log; fi; \
	  runs=$$(sed -n 's/^stat::number_of_executed_units: *//p' $$b/fuzz_$$n.log); \
	  stats=$$(sed -n 's/^stats: //p' $$b/fuzz_$$n.log | tail -n 1); \
	  echo "fuzz $$n: $$st, $${runs:-?} runs in $(FUZZ_SECONDS) s, corpus $$(ls $$b/corpus/$$n | wc -l) new + $$(ls tests/fuzz/corpus/$$n | wc -l) checked in$${stats:+ ($$stats)} (log $$b/fuzz_$$n.log)"; \
	done; \
	if [ -n "$$failed" ]; then echo "fuzz: FAILED:$$failed (inputs in $(FUZZ_BUILD)/artifacts/)"; exit 1; fi
# ---- distribution: packages for each channel (tools/dist/) ----
# One script per channel, tools/dist/CHANNEL.sh, with `build DISTDIR` and
# `test DISTDIR` (interface: tools/dist/lib/common.sh); tools/dist/run.py runs
# them in turn and prints the summary.  DIST_CHANNELS="python musl" for some.
.PHONY: dist test-dist test-musl
DIST ?= dist
DIST_CHANNELS ?=
dist:
	$(call need,$(BUILD_TOOLS))
	$(PYTHON) tools/dist/run.py build $(DIST) $(DIST_CHANNELS)

# builds too (the packages of the tree as it is), then installs and tests each
test-dist:
	$(call need,$(BUILD_TOOLS))
	$(PYTHON) tools/dist/run.py all $(DIST) $(DIST_CHANNELS)

# All C test programs on musl (make test runs three of them: tests/test_musl.py),
# except test_package: it checks an installation with the host's glibc tools
# (ldd cannot resolve a musl program; musl's crti adds _init/_fini to the
# exported symbols it compares with trigspline.h).
MUSL_BUILD := build-musl
test-musl:
	$(call need,$(BUILD_TOOLS) musl-gcc:musl-tools)
	CC=musl-gcc $(CMAKE) -S . -B $(MUSL_BUILD) -DCMAKE_BUILD_TYPE=RelWithDebInfo -DTS_WERROR=ON \
	  -DTS_BUILD_EXAMPLES=OFF >/dev/null
	$(CMAKE) --build $(MUSL_BUILD) -j $(JOBS)
	@failed=""; n=0; for t in $(MUSL_BUILD)/tests/test_*; do [ -x $$t ] || continue; \
	  case $$t in *test_package) continue;; esac; n=$$((n+1)); \
	  if $$t >$$t.log 2>&1; then echo "musl $$(basename $$t): $$(tail -n 1 $$t.log)"; \
	  else echo "musl $$(basename $$t): FAILED (log $$t.log)"; tail -n 20 $$t.log; failed="$$failed $$t"; fi; \
	done; if [ -n "$$failed" ]; then echo "test-musl: FAILED:$$failed"; exit 1; fi; echo "test-musl: $$n programs passed"
