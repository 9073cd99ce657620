# Shared flags for every native part. Include from a sub-Makefile:  include ../../Modules/common.mk
# Outputs: libraries to $(LIBDIR), programs to $(BINDIR), C/C++ test programs to $(TESTDIR)
# (every executable in $(TESTDIR) is run by `make test` and must print TAP: "ok N - ..." / "not ok N - ...").
TOP      := $(abspath $(dir $(lastword $(MAKEFILE_LIST)))/..)
BUILD    ?= $(TOP)/build
LIBDIR   := $(BUILD)/lib
BINDIR   := $(BUILD)/bin
TESTDIR  := $(BUILD)/tests
GENDIR   := $(BUILD)/gen
OBJDIR    = $(BUILD)/obj/$(notdir $(CURDIR))

CC       := gcc
CXX      := g++
# Sanitizer builds (make SANITIZE=address,undefined or SANITIZE=thread; the top Makefile puts them in
# build-<sanitizers>/): the flags go into CC/CXX themselves, so every compile *and* link line,
# shared libraries included, is instrumented (at the parts' own -O2/-O3); frame pointers keep the
# reports' stack traces whole; UBSan stops at the first finding so a test fails instead of going on.
ifneq ($(SANITIZE),)
SAN_FLAGS := -fsanitize=$(SANITIZE) -fno-omit-frame-pointer
ifneq ($(findstring undefined,$(SANITIZE)),)
SAN_FLAGS += -fno-sanitize-recover=undefined
endif
CC       := gcc $(SAN_FLAGS)
CXX      := g++ $(SAN_FLAGS)
endif
WARN     := -Wall -Wextra -Werror -Wshadow -Wno-unused-parameter
CFLAGS   += -std=c11 -O2 -g -fPIC $(WARN) -D_GNU_SOURCE -I$(TOP)/Modules -I$(GENDIR) -DHRP_ROOT_DEFAULT='"$(TOP)"'
CXXFLAGS += -std=c++17 -O2 -g -fPIC $(WARN) -D_GNU_SOURCE -I$(TOP)/Modules -I$(GENDIR) -DHRP_ROOT_DEFAULT='"$(TOP)"'
# Header dependencies from the compiler (-MMD: a .d file beside each output): a changed header,
# e.g. a struct in Modules/dcm/dcm.h, rebuilds everything that includes it.
CFLAGS   += -MMD -MP
CXXFLAGS += -MMD -MP
# Link against the shm library by path with an rpath, so nothing needs installing.
SHM_LIBS := -L$(LIBDIR) -lhrpshm -Wl,-rpath,$(LIBDIR) -lpthread -lrt -lm
# The DCM library (Modules/dcm; its header dcm.h includes the generated $(GENDIR)/dcm_blocks.h).
DCM_LIBS := -L$(LIBDIR) -lhrpdcm $(SHM_LIBS)

$(shell mkdir -p $(LIBDIR) $(BINDIR) $(TESTDIR) $(GENDIR))
-include $(wildcard $(BUILD)/obj/$(notdir $(CURDIR))/*.d $(TESTDIR)/*.d $(BINDIR)/*.d $(LIBDIR)/*.d)
