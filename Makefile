# fivax -- five-axis postprocessor in Tcl. Targets: test, demo, bench, fuzz.
TCLSH ?= tclsh
DEMO_MACHINE ?= machines/hh-tilt45.tcl
DEMO_CL ?= tests/data/demo-5ax.cls

.PHONY: all deps test demo bench fuzz clean

all: test

# Installs tcllib (Debian package) when Tcl cannot load it.
# (tclsh reading a script from stdin exits 0 on errors: exit 1 explicitly.)
HAVE_DEPS = echo 'exit [catch {package require cmdline; package require tcltest 2.5}]' | $(TCLSH)

deps:
	@$(HAVE_DEPS) || { echo "installing tcllib"; \
	    (apt-get install -y tcllib || (apt-get update && apt-get install -y tcllib)) >/dev/null; }
	@$(HAVE_DEPS) || { echo "tcllib is missing and could not be installed"; exit 1; }

test: deps
	$(TCLSH) tests/all.tcl

demo: deps
	@mkdir -p out
	$(TCLSH) tools/replay.tcl -machine $(DEMO_MACHINE) -o out/demo.nc $(DEMO_CL)
	@echo "NC program written to out/demo.nc"

# Speed figures on a generated 200k-point file, beside tools/bench-baseline.txt
# (BENCH_ARGS: e.g. -points 20000, -noreplay, -save).
bench: deps
	$(TCLSH) tools/bench.tcl $(BENCH_ARGS)

# Mutated CL files, machine files and command lines through tools/replay.tcl
# (FUZZ_CASES cases, default 10000; FUZZ_ARGS: e.g. -seed 2 -jobs 4 -keep DIR).
# Fails on a new failure; known issues are reported and counted apart.
FUZZ_CASES ?= 10000
fuzz: deps
	$(TCLSH) tools/fuzz.tcl -cases $(FUZZ_CASES) $(FUZZ_ARGS)

clean:
	rm -rf out tests/tmp
