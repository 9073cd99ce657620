# Compiling and linking against Pinocchio's C++ library, the libpinocchio wheel that `make deps` installs
# into the project's .venv (Tools/deps/requirements.txt): headers and shared libraries under its
# cmeel.prefix, linked with an rpath there so nothing needs LD_LIBRARY_PATH. The definitions are the
# ones its CMake targets export (lib/cmake/pinocchio/pinocchioTargets.cmake); Eigen is Debian's.
# EIGEN_MALLOC_ALREADY_ALIGNED=1: Eigen allocates as in the library's own build (glibc's malloc is
# aligned enough); under ASan Eigen would otherwise switch to its own aligned allocator and free what
# the library allocated with the wrong one.
PIN_PREFIX := $(firstword $(wildcard $(TOP)/.venv/lib/python3*/site-packages/cmeel.prefix))
ifeq ($(PIN_PREFIX),)
$(error Pinocchio is not installed in $(TOP)/.venv: run `make deps`)
endif
PIN_CXXFLAGS := -isystem $(PIN_PREFIX)/include -isystem /usr/include/eigen3 -DEIGEN_MALLOC_ALREADY_ALIGNED=1 \
  -DBOOST_MPL_LIMIT_LIST_SIZE=30 -DBOOST_MPL_LIMIT_VECTOR_SIZE=30 -DBOOST_MPL_CFG_NO_PREPROCESSED_HEADERS \
  -DBOOST_FUSION_INVOKE_MAX_ARITY=12 -DPINOCCHIO_ENABLE_TEMPLATE_INSTANTIATION -DPINOCCHIO_WITH_URDFDOM \
  -DPINOCCHIO_URDFDOM_HEADERS_MAJOR_VERSION=3 -DPINOCCHIO_URDFDOM_HEADERS_MINOR_VERSION=0 \
  -DPINOCCHIO_URDFDOM_HEADERS_PATCH_VERSION=0
PIN_LIBS := -L$(PIN_PREFIX)/lib -lpinocchio_parsers -lpinocchio_default -Wl,-rpath,$(PIN_PREFIX)/lib
