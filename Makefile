# Thin wrapper around CMake.  See README.md.
.PHONY: all build build-asan test demo bench accuracy valgrind clean deps

JOBS ?= 2
CMAKE ?= cmake

all: build

# Debian packages a target needs are installed by the target itself.
deps:
	@command -v cmake >/dev/null && command -v cc >/dev/null && command -v python3 >/dev/null && \
	  command -v valgrind >/dev/null || \
	  { apt-get update && apt-get install -y cmake gcc make python3 valgrind; }

build: deps
	$(CMAKE) -S . -B build -DCMAKE_BUILD_TYPE=RelWithDebInfo >/dev/null
	$(CMAKE) --build build -j $(JOBS)

build-asan: deps
	$(CMAKE) -S . -B build-asan -DCMAKE_BUILD_TYPE=Debug -DTS_SANITIZE=ON >/dev/null
	$(CMAKE) --build build-asan -j $(JOBS)

test: build build-asan
	tests/run_all.sh build build-asan

valgrind: build
	@command -v valgrind >/dev/null || { apt-get update && apt-get install -y valgrind; }
	for t in build/tests/test_*; do \
	  case $$t in *test_property|*test_fast|*test_review_fuzz) continue;; esac; \
	  valgrind -q --leak-check=full --errors-for-leak-kinds=all --error-exitcode=9 $$t >/dev/null || exit 1; \
	done; echo "valgrind: clean"

# Speed and memory against GSL (issue 6): prints a table, writes bench/RESULTS.md.
bench: deps
	@test -f /usr/include/gsl/gsl_interp.h || { apt-get update && apt-get install -y libgsl-dev; }
	$(CMAKE) -S . -B build-bench -DCMAKE_BUILD_TYPE=Release -DTS_WERROR=OFF >/dev/null
	$(CMAKE) --build build-bench -j $(JOBS) --target trigspline
	@$(CMAKE) --build build-bench -j $(JOBS) --target trigspline_cli >/dev/null 2>&1 || \
	  echo "bench: the CLI did not build; its streaming row is skipped"
	$(CC) -O2 -std=c11 -Wall -Wextra -Iinclude bench/bench.c build-bench/libtrigspline.a \
	  -lgsl -lgslcblas -lm -lpthread -o build-bench/bench
	./build-bench/bench --cli build-bench/trigspline --out bench/RESULTS.md

# The main job: reproduce the paper's numerical section (Figures 2-7) as one page.
# Convergence study (issue 7, docs/accuracy.md): prints the tables, rewrites the
# results section of docs/accuracy.md and docs/accuracy.svg.  Compares with GSL.
accuracy: build
	@test -f /usr/include/gsl/gsl_interp.h || { apt-get update && apt-get install -y libgsl-dev; }
	$(CC) -std=c11 -O2 -Wall -Wextra -Iinclude accuracy/accuracy.c build/libtrigspline.a \
	  -lgsl -lgslcblas -lm -lpthread -o build/accuracy
	./build/accuracy --doc docs/accuracy.md --svg docs/accuracy.svg

demo: build
	python3 scripts/paper_demo.py build/trigspline data/paper out/paper

clean:
	rm -rf build build-asan build-bench out
