# Thin wrapper over CMake. `make run` and `make test` do all the set-up
# (scripts/install-deps.sh installs missing Debian packages first).
BUILD      ?= build
BUILD_SAN  ?= build-sanitize
BUILD_TSAN ?= build-tsan
JOBS       ?= $(shell nproc 2>/dev/null || echo 2)
CMAKE_ARGS ?=
MECHD_ARGS ?=
PREFIX     ?= /usr/local
DESTDIR    ?=

.PHONY: all deps configure run test test-sanitize test-tsan bench fuzz load docker-test clean install static-eval dist grader-image

# Builds and test runs keep their whole output in a log under the build tree
# and print a summary: a line per failure, CTest's closing lines on success
# (scripts/quiet.sh). `make VERBOSE=1 ...` prints everything as it runs.
ifeq ($(VERBOSE),1)
QC =
QB =
QT =
else
QC = $(CURDIR)/scripts/quiet.sh configure $(abspath $(1))/configure.log
QB = $(CURDIR)/scripts/quiet.sh build $(abspath $(1))/build.log
QT = $(CURDIR)/scripts/quiet.sh test $(abspath $(1))/test.log
endif

all: configure
	@$(call QB,$(BUILD)) cmake --build $(BUILD) -j $(JOBS)

deps:
	@./scripts/install-deps.sh

configure: deps
	@test -f $(BUILD)/CMakeCache.txt || $(call QC,$(BUILD)) cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=RelWithDebInfo $(CMAKE_ARGS)

run: all
	./$(BUILD)/mechd $(MECHD_ARGS)

test: all
	@cd $(BUILD) && $(call QT,$(BUILD)) ctest --no-tests=error --output-on-failure -j $(JOBS)

test-sanitize: deps
	@test -f $(BUILD_SAN)/CMakeCache.txt || $(call QC,$(BUILD_SAN)) cmake -S . -B $(BUILD_SAN) -DCMAKE_BUILD_TYPE=Debug -DMECHD_SANITIZE=ON $(CMAKE_ARGS)
	@$(call QB,$(BUILD_SAN)) cmake --build $(BUILD_SAN) -j $(JOBS)
	@cd $(BUILD_SAN) && $(call QT,$(BUILD_SAN)) ctest --no-tests=error --output-on-failure -j $(JOBS)

# ThreadSanitizer: mechd built with -fsanitize=thread, and the integration
# tests (workers, queue, suspend/resume, hang-up watcher, shutdown) run against
# it as tsan/* (label tsan); any TSan report fails the test (see
# tests/integration/run_tsan.sh). Only mechd is built. About 1 minute.
test-tsan: deps
	@test -f $(BUILD_TSAN)/CMakeCache.txt || $(call QC,$(BUILD_TSAN)) cmake -S . -B $(BUILD_TSAN) -DCMAKE_BUILD_TYPE=RelWithDebInfo -DMECHD_TSAN=ON $(CMAKE_ARGS)
	@$(call QB,$(BUILD_TSAN)) cmake --build $(BUILD_TSAN) -j $(JOBS) --target mechd
	@./$(BUILD_TSAN)/mechd --version >/dev/null || { echo "test-tsan: the TSan mechd does not start" \
	  "(an ifunc/target_clones resolver instrumented by TSan? guard it with __SANITIZE_THREAD__)" >&2; exit 1; }
	@cd $(BUILD_TSAN) && $(call QT,$(BUILD_TSAN)) ctest --no-tests=error --output-on-failure -j $(JOBS) -L tsan

# Benchmarks print figures and same-run ratios; never part of `make test`.
# The work-precision plot needs gnuplot and the SciPy baseline (Debian packages).
bench: all
	./scripts/install-deps.sh --bench
	@mkdir -p $(BUILD)/bench-out
	@for b in $(BUILD)/bench_*; do [ -x "$$b" ] && "$$b" $(BUILD)/bench-out || exit 1; done

# libFuzzer harnesses (tests/fuzz/) built with clang, each run FUZZ_SECONDS.
FUZZ_SECONDS ?= 60
fuzz: deps
	./tests/fuzz/run.sh $(BUILD) $(FUZZ_SECONDS)

# Load scenarios (tests/load/): ~3 min, 127.0.0.1 only; print figures and
# fail only on errors, lost answers or leaks, never on timing.
load: all
	./scripts/install-deps.sh --bench
	tests/load/run.sh $(BUILD)/mechd

# The container set-up end to end (needs root): docker/test.sh, 4-11 min.
docker-test:
	sh docker/test.sh

# Install mechd, mechd-eval (and mechd-eval-static), the docs, the front end,
# the curl scripts and the Python client's files under $(DESTDIR)$(PREFIX):
#   make install PREFIX=/opt/mechd DESTDIR=/tmp/stage
# (an installed mechd serves PREFIX/share/mechd/web by default).
install: all
	DESTDIR="$(DESTDIR)" cmake --install $(BUILD) --prefix "$(PREFIX)"

# The self-contained offline evaluator for grader containers: one static
# executable (no shared library at all), $(BUILD)/mechd-eval-static.
static-eval: configure
	cmake --build $(BUILD) -j $(JOBS) --target mechd-eval-static
	@if ldd $(BUILD)/mechd-eval-static >/dev/null 2>&1; then \
	  echo "static-eval: $(BUILD)/mechd-eval-static is not static" >&2; exit 1; fi
	@echo "$(BUILD)/mechd-eval-static: static, needs no shared library (copy it into the grader image)"

clean:
	rm -rf $(BUILD) $(BUILD_SAN) $(BUILD_TSAN)

# Artefacts that install without building, into dist/ (scripts/make_dist.py): the
# Python client as a pure wheel (standard library build, any Python >= 3.8), the
# static evaluator as a tarball with its licence notices and a .sha256, SHA256SUMS.
dist: static-eval
	/usr/bin/python3 scripts/make_dist.py --build $(BUILD) --out dist

# The PrairieLearn external-grader image (needs docker): the `grader` stage of
# docker/Dockerfile as mechd-grader, then docker/grader-pl.Dockerfile as
# mechd-pl-grader. Publish: docker tag mechd-pl-grader USER/mechd-pl-grader:V && docker push ...
grader-image:
	docker build -f docker/Dockerfile --target grader -t mechd-grader .
	docker build -f docker/grader-pl.Dockerfile -t mechd-pl-grader .
