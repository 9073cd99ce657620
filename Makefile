# hrp: humanoid robot platform.
#   make        build every native part (runs `make deps` first if something is missing)
#   make deps   install what Debian must provide (idempotent)
#   make test   run every test; ends with one line "N passed, N failed"
#   make check  the fast tier for the edit-test loop (lint, specs, C/C++ tests, fast scenarios; < 3 min)
#   make league MATCHES=20 HALF=60   seeded 2v2 matches on Ray, with team play vs without: a table
#   make soak   1 hour of play in the sim, memory/fd/shm growth per process (SOAK_SECONDS=600: 10 minutes)
#   make soak-seeds  the 10-minute soak on five seeds: the lone robot's falls per minute
#   make sanitize  the C/C++ tests and DCM scenarios under ASan+UBSan (SANITIZE=thread: TSan)
#   make clean  remove build/ (and the sanitizer builds)

# SANITIZE=address,undefined (or thread) builds every native part instrumented into its own folder,
# build-address-undefined/ (build-thread/), and leaves build/ alone: `make sanitize` runs the tests.
comma := ,
ifeq ($(SANITIZE),)
BUILD := $(CURDIR)/build
else
BUILD := $(CURDIR)/build-$(subst $(comma),-,$(SANITIZE))
endif
export BUILD SANITIZE
# Every folder with a Makefile under Modules/, Platforms/ (and a platform's emulator/), Run/ and Tools/
# is a native part.
NATIVE_DIRS := $(sort $(dir $(wildcard Modules/*/Makefile Platforms/*/Makefile Platforms/*/emulator/Makefile \
                                       Run/*/Makefile Tools/*/Makefile)))
DEPS_STAMP := $(BUILD)/.deps-ok

# Each dependency file (.d, from -MMD) names first the source its target was built from: an absolute
# path, or one relative to its part's folder (the sub-make's). After a pull that moved a source, that
# old path has no rule and make would stop, so a .d naming a source found in no part is dropped before
# anything is built (its target is rebuilt from its new place); the others stay, so a changed header
# rebuilds what includes it.
STALE_DEPS := $(shell find $(BUILD) -name '*.d' -exec awk -v dirs='$(NATIVE_DIRS)' ' \
  function exists(f) { if ((getline tmp < f) < 0) return 0; close(f); return 1 } \
  function found(f,   k, nd, d) { if (f ~ /^\//) return exists(f); \
    nd = split(dirs, d, " "); for (k = 1; k <= nd; k++) if (exists(d[k] f)) return 1; return 0 } \
  FNR == 1 { want = 1; seen = 0 } \
  want { line = $$0; \
    if (!seen) { i = index(line, ":"); if (!i) next; line = substr(line, i + 1); seen = 1 } \
    gsub(/\\/, " ", line); n = split(line, w, " "); \
    if (n > 0) { want = 0; if (!found(w[1])) print FILENAME } }' {} + 2>/dev/null)
ifneq ($(STALE_DEPS),)
$(shell rm -f $(STALE_DEPS))
endif
# An object without its .d (built before, or its .d dropped above) cannot know which headers it read:
# it is rebuilt.
UNTRACKED_OBJS := $(shell find $(BUILD)/obj -name '*.o' 2>/dev/null | while read -r o; do \
  [ -f "$${o%.o}.d" ] || echo "$$o"; done)
ifneq ($(UNTRACKED_OBJS),)
$(shell rm -f $(UNTRACKED_OBJS))
endif

# C and C++ tests live beside the code they test, in that part's tests/ folder (Modules/<m>/tests/,
# Platforms/<p>/tests/, Run/recorder/tests/), built by its Makefile into build/tests/, where
# Tests/run_all.sh runs every program; the libFuzzer targets sit there too. Tests/ holds the Lua specs,
# the scenario scripts (*_test.sh, fuzz runs included) and their fixtures.

.PHONY: all deps test check clean bench sim match match4 league sanitize soak soak-seeds $(NATIVE_DIRS)

all: $(DEPS_STAMP) $(NATIVE_DIRS)

# Modules/shm first: others link against it. The DCMs stand on Modules/dcm, the OP's on the Dynamixel
# protocol and device table, the Hubo's on the CAN protocol; each emulator on its DCM's libraries.
$(filter-out Modules/shm/,$(NATIVE_DIRS)): Modules/shm/
$(filter Platforms/%,$(NATIVE_DIRS)): Modules/dcm/
Modules/op_devices/ Modules/hubo_can/: Modules/dcm/
Platforms/OP/ Platforms/OP/emulator/: Modules/dynamixel/ Modules/op_devices/
Platforms/Hubo/ Platforms/Hubo/emulator/: Modules/hubo_can/
# the robot description parser: linked by the kinematics and the sim
Modules/kinematics/ Platforms/Sim/: Modules/description/
# the rigid-body model: the sim's test of ODE's joint torques against it
Platforms/Sim/: Modules/dynamics/
# the recorder and the Replay DCM: MCAP files of shm blocks
Run/recorder/: Modules/dcm/ Modules/mcap/ Modules/shmlog/
Modules/wbc/: Modules/dynamics/
Platforms/Replay/: Modules/mcap/ Modules/shmlog/
# the LUT tool and the pipeline benchmark: the vision pipeline's library
Tools/lut/ Tools/bench/: Modules/imageproc/

$(NATIVE_DIRS): $(DEPS_STAMP)
	@$(MAKE) --no-print-directory -C $@ all

deps:
	@Tools/deps/install_deps.sh
	@mkdir -p $(BUILD) && touch $(DEPS_STAMP)

# Only re-checked when the dependency list changes or on a new clone.
$(DEPS_STAMP): Tools/deps/install_deps.sh Tools/deps/requirements.txt
	@Tools/deps/install_deps.sh
	@mkdir -p $(BUILD) && touch $@

test: all
	@Tests/run_all.sh

# The scenarios in the fast tier say so in their header ("# tier: check"); TESTS=regex narrows either.
check: all
	@TIER=check Tests/run_all.sh

# One robot in the simulator, a status line per second until Ctrl-C (Run/main.lua --sim), and the live
# view in a browser (./run_view: it prints the URL, http://127.0.0.1:8080/; VIEW_PORT= another port).
VIEW_PORT ?= 8080
sim: all
	@./run_main --sim --view $(VIEW_PORT)

# A whole match in the sim, refereed (Tools/match/referee.lua): 2v2 (match4: 4v4), 2 x HALF s (default 300),
# e.g. `make match HALF=60`; prints the result, the real-time factor and the CPU per process.
HALF ?= 300
SEED ?= 1
match: all
	@Tools/match/match.sh 2 $(HALF) $(SEED)

match4: all
	@Tools/match/match.sh 4 $(HALF) $(SEED)

# The league (Tools/match/league.py): MATCHES seeded 2v2 matches (2 x HALF s) as Ray tasks, our team with team play
# against the same robots alone; a table of the results. RAY_ADDRESS=host:port: on that Ray cluster.
MATCHES ?= 20
league: all
	@.venv/bin/python Tools/match/league.py --matches $(MATCHES) --half $(HALF) --seed $(SEED) \
	  $(if $(RAY_ADDRESS),--address $(RAY_ADDRESS))

bench: all
	@Tools/bench/run_all.sh

# One robot playing in the sim (lockstep, camera on) for SOAK_SECONDS of robot time (1 hour; 600: the
# 10-minute version), the sim seeded with SEED, a new game every 3 minutes: memory, fds and shm segments per
# process, the fall census. soak-seeds: the 10-minute soak on seeds 1-5 and the falls per minute over all.
SOAK_SECONDS ?= 3600
soak: all
	@SOAK_SEED=$(SEED) Tests/soak/soak.sh $(SOAK_SECONDS)

soak-seeds: all
	@Tools/bench/soak_seeds.sh 600

# The C/C++ tests and the DCM scenarios under ASan+UBSan (SANITIZE=thread: TSan), Tests/sanitize.sh.
sanitize:
	@SANITIZE=$(or $(SANITIZE),address$(comma)undefined) Tests/sanitize.sh

clean:
	rm -rf $(BUILD) $(wildcard $(CURDIR)/build-*)
