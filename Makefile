# Thin wrapper around CMake.  See README.md.
#   make build      gcc build in build/ (-Werror)
#   make build-clang  clang build in build-clang/ (-Werror)
#   make build-asan ASan+UBSan build in build-asan/
#   make test       all three builds, then tests/run_all.sh (package test included)
#   make demo       the paper's numerical section as one page (out/paper)
#   make bench      benchmark against GSL and the build decisions -> bench/RESULTS.md
#   make accuracy   convergence study -> docs/accuracy.md, docs/accuracy.svg
#   make valgrind   memcheck of the test programs
# Each target installs the Debian packages it needs (apt-get) when missing.
# The compiler of a build directory is fixed when it is first configured
# (CC=gcc or CC=clang below); `make clean` starts over.
.PHONY: all build build-asan build-clang test demo bench accuracy valgrind clean

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
TEST_TOOLS := valgrind:valgrind pkg-config:pkg-config readelf:binutils
# libc.a: the package test links a -static program
STATIC_LIBC := /usr/lib/$(shell gcc -print-multiarch 2>/dev/null || echo x86_64-linux-gnu)/libc.a

build:
	$(call need,$(BUILD_TOOLS))
	CC=gcc $(CMAKE) -S . -B build -DCMAKE_BUILD_TYPE=RelWithDebInfo \
	  -DTS_WERROR=ON >/dev/null
	$(CMAKE) --build build -j $(JOBS)

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

test: build build-asan build-clang
	$(call need,$(TEST_TOOLS))
	$(call need_file,$(STATIC_LIBC),libc6-dev)
	tests/run_all.sh build build-asan build-clang

valgrind: build
	$(call need,valgrind:valgrind)
	for t in build/tests/test_*; do \
	  case $$t in *test_property|*test_fast|*test_random_inputs|*test_random_tool_inputs|*test_package) continue;; esac; \
	  valgrind -q --leak-check=full --errors-for-leak-kinds=all --error-exitcode=9 $$t >/dev/null || exit 1; \
	done; echo "valgrind: clean"

# Speed and memory against GSL, and the measurements behind the build
# decisions of docs/design.md: prints the tables, writes bench/RESULTS.md.
# Built by CMake (TS_BUILD_BENCH; bench/CMakeLists.txt), run by its run_bench target.
bench:
	$(call need,$(BUILD_TOOLS))
	$(call need_file,/usr/include/gsl/gsl_interp.h,libgsl-dev)
	CC=gcc $(CMAKE) -S . -B build-bench -DCMAKE_BUILD_TYPE=Release \
	  -DTS_BUILD_BENCH=ON -DTS_BUILD_TESTS=OFF -DTS_BUILD_EXAMPLES=OFF >/dev/null
	$(CMAKE) --build build-bench -j $(JOBS) --target run_bench

# Convergence study (docs/accuracy.md): prints the tables, rewrites the
# results section of docs/accuracy.md and docs/accuracy.svg.  Compares with GSL.
accuracy: build
	$(call need_file,/usr/include/gsl/gsl_interp.h,libgsl-dev)
	$(CC) -std=c11 -O2 -Wall -Wextra -Iinclude accuracy/accuracy.c build/libtrigspline.a \
	  -lgsl -lgslcblas -lm -lpthread -o build/accuracy
	./build/accuracy --doc docs/accuracy.md --svg docs/accuracy.svg

# The main job: reproduce the paper's numerical section (Figures 2-7) as one page.
demo: build
	python3 scripts/paper_demo.py build/trigspline data/paper out/paper

clean:
	rm -rf build build-asan build-clang build-bench out

# ---- trust at the edges (issue 18): thread sanitizer, coverage, fuzzing ----
.PHONY: tsan coverage fuzz

# ThreadSanitizer (gcc) build of the threaded batch test and the core test.
tsan:
	$(call need,$(BUILD_TOOLS))
	CC=gcc $(CMAKE) -S . -B build-tsan -DCMAKE_BUILD_TYPE=RelWithDebInfo \
	  -DCMAKE_C_FLAGS=-fsanitize=thread -DTS_BUILD_TOOLS=OFF -DTS_BUILD_EXAMPLES=OFF >/dev/null
	$(CMAKE) --build build-tsan -j $(JOBS) --target test_threads test_core
	TSAN_OPTIONS=halt_on_error=1 build-tsan/tests/test_threads
	TSAN_OPTIONS=halt_on_error=1 build-tsan/tests/test_core

# Line and branch coverage of the library (src/) by the C test programs:
# gcc --coverage, the programs of tests/api and tests/unit, then gcovr.
coverage:
	$(call need,$(BUILD_TOOLS) gcovr:gcovr)
	CC=gcc $(CMAKE) -S . -B build-coverage -DCMAKE_BUILD_TYPE=Debug \
	  -DCMAKE_C_FLAGS="--coverage -fprofile-update=atomic -O0" -DTS_BUILD_EXAMPLES=OFF >/dev/null
	$(CMAKE) --build build-coverage -j $(JOBS)
	find build-coverage -name '*.gcda' -delete
	@for t in build-coverage/tests/test_*; do \
	  case $$t in *test_package*|*test_random_tool_inputs*|*test_io*|*test_plot*) continue;; esac; \
	  [ -x $$t ] && { $$t >/dev/null 2>&1 || echo "coverage: $$t failed"; }; done; true
	gcovr -r . --object-directory build-coverage --filter 'src/' --txt
	gcovr -r . --object-directory build-coverage --filter 'src/' --branches --txt

# libFuzzer harnesses of tests/fuzz/ (clang, ASan+UBSan), each run for
# FUZZ_SECONDS seconds from its checked-in corpus (new inputs go to
# build-fuzz/corpus/NAME, not into the repository).  `make test` replays
# the checked-in corpus through the same harnesses (test_fuzz_* programs).
FUZZ_SECONDS ?= 60
fuzz:
	$(call need,$(BUILD_TOOLS) clang:clang)
	$(call need_file,/usr/lib/llvm-14/lib/clang/14.0.6/lib/linux/libclang_rt.fuzzer-x86_64.a,libclang-rt-14-dev)
	CC=clang $(CMAKE) -S . -B build-fuzz -DCMAKE_BUILD_TYPE=RelWithDebInfo -DTS_FUZZ=ON \
	  -DCMAKE_C_FLAGS="-fsanitize=fuzzer-no-link,address,undefined -fno-sanitize-recover=all" \
	  -DCMAKE_EXE_LINKER_FLAGS="-fsanitize=address,undefined" -DTS_BUILD_EXAMPLES=OFF >/dev/null
	$(CMAKE) --build build-fuzz -j $(JOBS) --target fuzzers
	@set -e; for h in tests/fuzz/fuzz_*.c; do n=$$(basename $$h .c); n=$${n#fuzz_}; \
	  mkdir -p build-fuzz/corpus/$$n; echo "fuzz $$n: $(FUZZ_SECONDS) s"; \
	  build-fuzz/fuzz/fuzz_$$n -max_total_time=$(FUZZ_SECONDS) -print_final_stats=1 \
	    build-fuzz/corpus/$$n tests/fuzz/corpus/$$n 2>&1 | tail -n 12; done
