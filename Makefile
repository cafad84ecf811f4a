# fivax -- five-axis postprocessor in Tcl. Targets: test, demo, docs, bench, fuzz, matrix.
#
# What each target needs: demo, docs, bench and fuzz run on Tcl 8.6 alone
# (tclsh); test and matrix run the tests, which also need tcllib
# (math::linearalgebra, in the tests' reference rotations) and tdom (they
# read the SVG plots back); tcltest 2.5 comes with Tcl 8.6. lib/ and post/
# use plain Tcl: NX has no tcllib.
TCLSH ?= tclsh
DEMO_MACHINE ?= machines/hh-tilt45.tcl
DEMO_CL ?= tests/data/demo-5ax.cls

.PHONY: all tcl deps test demo docs bench fuzz matrix clean

all: test

# (tclsh reading a script from stdin exits 0 on errors: exit 1 explicitly.)
HAVE_TCL = echo 'exit [catch {package require Tcl 8.6}]' | $(TCLSH) 2>/dev/null
HAVE_DEPS = echo 'exit [catch {package require tcltest 2.5; package require math::linearalgebra; package require tdom}]' | $(TCLSH) 2>/dev/null

tcl:
	@$(HAVE_TCL) || { echo "make: fivax needs Tcl 8.6, and $(TCLSH) is missing or another version: install it (Debian, Ubuntu: apt-get install tcl8.6) or name it (make TCLSH=tclsh8.6)"; exit 1; }

# The tests' packages: as root, installs tcllib and tdom (Debian packages)
# when Tcl cannot load them; else says what to install.
deps: tcl
	@$(HAVE_DEPS) || [ "$$(id -u)" != 0 ] || { echo "installing tcllib tdom"; \
	    (apt-get install -y tcllib tdom || (apt-get update && apt-get install -y tcllib tdom)) >/dev/null 2>&1; }
	@$(HAVE_DEPS) || { echo "make: the tests need tcllib and tdom, which $(TCLSH) cannot load: install them (Debian, Ubuntu: sudo apt-get install tcllib tdom); demo, docs, bench and fuzz need neither"; exit 1; }

test: deps
	$(TCLSH) tests/all.tcl

# Replay, then the verifier on the written file, then the plots.
demo: tcl
	@mkdir -p out
	$(TCLSH) tools/replay.tcl -machine $(DEMO_MACHINE) -o out/demo.nc $(DEMO_CL)
	@echo "NC program written to out/demo.nc"
	$(TCLSH) tools/verify.tcl -machine $(DEMO_MACHINE) -cl $(DEMO_CL) -csv out/demo-verify.csv -svg out/demo out/demo.nc
	$(TCLSH) tools/kinerr.tcl -machine $(DEMO_MACHINE) -d B=0.01 -d C=0.02 -csv out/demo-kinerr.csv -svg out/demo-kinerr.svg out/demo.nc

# The pictures of docs/ (docs/*.svg): the surface paper's path on the
# TTR-TR machine, posted, verified and its rotary-axis error.
docs: tcl
	@mkdir -p out docs
	$(TCLSH) tools/surfpath.tcl -surface paper -D 6 -r 2 -lead 25 -tilt 5 -stepover 5 -step 1 -along v -o out/paper.cls -svg docs/surfpath-paper.svg
	$(TCLSH) tools/replay.tcl -quiet -machine machines/ttr-tr.tcl -o out/paper-ttr.nc out/paper.cls
	$(TCLSH) tools/verify.tcl -machine machines/ttr-tr.tcl -cl out/paper.cls -svg docs/verify-ttr out/paper-ttr.nc
	@rm -f docs/verify-ttr-axes.svg docs/verify-ttr-path.svg
	$(TCLSH) tools/kinerr.tcl -machine machines/ttr-tr.tcl -d B=0.01 -d C=0.02 -svg docs/kinerr-ttr.svg out/paper-ttr.nc

# The safety matrix (tests/matrix.test): every sample and corpus file on
# every machine, dialect, TCP and work-plane setting, posted and read back
# with the dry run. About half an hour.
matrix: deps
	FIVAX_MATRIX=1 $(TCLSH) tests/all.tcl -file matrix.test

# End-to-end speed on generated 50k, 200k and 1M-point files (records/s,
# wall time, peak RSS) beside a minimal loop of ours (BENCH_ARGS: e.g.
# -sizes "20000 100000", -machine machines/tt-ac.tcl). Some minutes.
bench: tcl
	$(TCLSH) tools/bench.tcl $(BENCH_ARGS)

# Mutated CL files, machine files and command lines through tools/replay.tcl
# (FUZZ_CASES cases, default 10000; FUZZ_ARGS: e.g. -seed 2 -jobs 4 -keep DIR).
# Fails when a case fails (the failures and the counts by class are printed).
FUZZ_CASES ?= 10000
fuzz: tcl
	$(TCLSH) tools/fuzz.tcl -cases $(FUZZ_CASES) $(FUZZ_ARGS)

clean:
	rm -rf out tests/tmp
