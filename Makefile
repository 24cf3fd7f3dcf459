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
	$(call need_file,/usr/lib/python3/dist-packages/scipy/__init__.py,python3-scipy)
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
