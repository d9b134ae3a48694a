#!/usr/bin/env bash
# Installs sheetform's Debian 12 packages (when missing), then configures and builds it.
#   scripts/setup.sh            solver, tests and post-processing libraries
#   SF_WITH_PARAVIEW=1 ...      also ParaView (pvpython/pvbatch), needed by the ParaView tests
#   SF_BUILD_DIR=dir ...        build folder (default: build)
set -euo pipefail
# The machine's cores. GNU nproc answers OMP_NUM_THREADS when it is set (CI sets it to 1 for
# the tests), which would build and test one job at a time.
sf_cores() { env -u OMP_NUM_THREADS -u OMP_THREAD_LIMIT nproc; }
cd "$(dirname "$0")/.."

packages=(g++ lld cmake ninja-build pkg-config git libeigen3-dev libsuitesparse-dev libhdf5-dev hdf5-tools
          gmsh libgmsh-dev libcli11-dev libtomlplusplus-dev nlohmann-json3-dev libfmt-dev
          libgtest-dev python3-h5py python3-numpy python3-matplotlib python3-tomlkit
          libopenmpi-dev openmpi-bin libmetis-dev libseccomp-dev)
if [ "${SF_WITH_PARAVIEW:-0}" = 1 ]; then
  packages+=(paraview python3-paraview xvfb xauth)
fi

scripts/install_packages.sh "${packages[@]}"

build_dir="${SF_BUILD_DIR:-build}"
echo "== Configuring and building in $build_dir"
# The preset ci (CMakePresets.json: Ninja, Release, tests and benchmarks), in $build_dir.
cmake --preset ci -B "$build_dir" >/dev/null
cmake --build "$build_dir" -j"$(sf_cores)"
echo "== Built $build_dir/sheetform"
