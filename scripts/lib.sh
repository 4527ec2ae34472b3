# Shared by scripts/run, scripts/test and scripts/bench_*: install what is missing, build when needed.
# Sourced, not executed.

POUND_ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
# Debian packages the project needs (build, tests, plots).
POUND_PACKAGES="gfortran cmake make liblapack-dev libhdf5-dev python3 python3-numpy python3-h5py python3-matplotlib"
# Debian packages of the MPI build only (-DPOUND_MPI=ON: scripts/test's build/mpi); the
# default build needs none of them.
POUND_MPI_PACKAGES="libopenmpi-dev openmpi-bin"
# Scripts that need numpy/h5py/matplotlib run on Debian's interpreter.
POUND_PYTHON=/usr/bin/python3

pound_missing_packages() {
  local p missing=""
  for p in ${1:-$POUND_PACKAGES}; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing="$missing $p"
  done
  echo "$missing"
}

# Install missing Debian packages (once); nothing happens when all are present.
# pound_setup [PACKAGES]: default $POUND_PACKAGES (pound_setup "$POUND_MPI_PACKAGES": MPI).
pound_setup() {
  local missing
  missing="$(pound_missing_packages "${1:-$POUND_PACKAGES}")"
  [ -z "$missing" ] && return 0
  echo "pound: installing Debian packages:$missing" >&2
  local sudo=""
  if [ "$(id -u)" != 0 ]; then
    command -v sudo >/dev/null 2>&1 || { echo "pound: need root (or sudo) to install:$missing" >&2; return 1; }
    sudo=sudo
  fi
  $sudo apt-get update -qq >&2 || return 1
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq $missing >&2 || return 1
}

# shared/ beside the project (records, pFUnit sources); the real pFUnit's cache, one per machine.
POUND_SHARED_DIR="${POUND_SHARED_DIR:-$POUND_ROOT/../shared}"
POUND_PFUNIT_CACHE="${XDG_CACHE_HOME:-${HOME:-/root}/.cache}/pfunit-4.14"

# pound_pfunit: make the real pFUnit 4.14 available if it can be had: a finished install in
# the cache is used as it is; otherwise, when $POUND_SHARED_DIR/pfunit/install.sh exists, it
# is built there once (about 3 minutes; under a lock, so concurrent callers wait for one
# build). Prints the prefix, or nothing (then the tests run under tests/pfunit_lite).
# Status 1 if the build failed.
pound_pfunit() {
  local install="$POUND_SHARED_DIR/pfunit/install.sh" log="$POUND_PFUNIT_CACHE.log"
  if [ ! -f "$POUND_PFUNIT_CACHE/.complete" ]; then
    [ -f "$install" ] || return 0
    echo "pound: building pFUnit 4.14 into $POUND_PFUNIT_CACHE (once per machine), log: $log" >&2
    mkdir -p "$(dirname "$POUND_PFUNIT_CACHE")"
    if command -v flock >/dev/null 2>&1; then
      flock "$POUND_PFUNIT_CACHE.lock" bash "$install" "$POUND_PFUNIT_CACHE" >>"$log" 2>&1
    else
      bash "$install" "$POUND_PFUNIT_CACHE" >>"$log" 2>&1
    fi || {
      tail -20 "$log" >&2
      echo "pound: building pFUnit failed, log: $log" >&2
      return 1
    }
  fi
  echo "$POUND_PFUNIT_CACHE"
}

# The CMake arguments that choose the test runner: the real pFUnit when a finished install is
# in the cache (see pound_pfunit); none otherwise (pfunit_lite).
pound_runner_args() {
  [ -f "$POUND_PFUNIT_CACHE/.complete" ] && echo "-DCMAKE_PREFIX_PATH=$POUND_PFUNIT_CACHE"
  return 0
}

# pound_build TYPE [NAME [CMAKE_ARG...]]: configure (first time only) and build build/<NAME>
# (default: build/<type>) with pound_runner_args and the extra arguments; an up-to-date tree
# is left alone. Every target is built, unless POUND_BUILD_TARGET names one (scripts/run:
# POUND_BUILD_TARGET=pound, the program without the tests); the configuration is the same
# either way, so scripts/run and scripts/test share build/release without reconfiguring it. A build directory configured with other such arguments (e.g. before the real
# pFUnit was installed) is removed and configured afresh, so that no stale cache is reused.
# The tests find shared/ at $POUND_SHARED_DIR (reconfigured when it changes).
pound_build() {
  local type="$1" name="${2:-${1,,}}"
  shift; [ $# -gt 0 ] && shift
  local dir="$POUND_ROOT/build/$name" args
  mapfile -t args < <(pound_runner_args)
  args+=("$@")
  if [ -f "$dir/CMakeCache.txt" ] && [ "$(cat "$dir/pound-cmake-args" 2>/dev/null)" != "${args[*]}" ]; then
    echo "pound: build/$name was configured for another test runner: configuring it afresh" >&2
    rm -rf "$dir"
  fi
  if [ ! -f "$dir/CMakeCache.txt" ]; then
    cmake -S "$POUND_ROOT" -B "$dir" -DCMAKE_BUILD_TYPE="$type" -DPOUND_NATIVE=ON -DPOUND_SHARED_DIR="$POUND_SHARED_DIR" \
      "${args[@]}" >/dev/null || return 1
    echo "${args[*]}" >"$dir/pound-cmake-args"
  elif [ "$(sed -n 's/^POUND_SHARED_DIR:PATH=//p' "$dir/CMakeCache.txt")" != "$POUND_SHARED_DIR" ]; then
    cmake "$dir" -DPOUND_SHARED_DIR="$POUND_SHARED_DIR" >/dev/null || return 1
  fi
  cmake --build "$dir" ${POUND_BUILD_TARGET:+--target "$POUND_BUILD_TARGET"} -j "$(nproc)" -- \
    --no-print-directory >"$dir/build.log" 2>&1 || {
    cat "$dir/build.log" >&2
    echo "pound: build failed ($type), log: $dir/build.log" >&2
    return 1
  }
}

# pound_program_current EXE: status 0 when EXE exists and is newer than every file and folder
# of src/, cmake/ and CMakeLists.txt (a folder's time changes when a file in it is added,
# removed or renamed), i.e. when building it again would change nothing; 1 otherwise. One
# `find`, a few milliseconds: scripts/run's test before it would call cmake.
pound_program_current() {
  local newer
  [ -x "$1" ] || return 1
  newer="$(find "$POUND_ROOT/src" "$POUND_ROOT/cmake" "$POUND_ROOT/CMakeLists.txt" -newer "$1" -print -quit)" \
    || return 1
  [ -z "$newer" ]
}

# pound_program: make build/release/pound current for the scripts that run the program
# (scripts/run, scripts/work_precision, scripts/bench_*): nothing when pound_program_current
# holds; otherwise install what is missing and build the program alone (POUND_BUILD_TARGET=pound;
# the tests are scripts/test's), saying on standard error before the build what it builds and
# after it how long it took.
pound_program() {
  local exe="$POUND_ROOT/build/release/pound" start=$SECONDS
  pound_program_current "$exe" && return 0
  pound_setup || return 1
  if [ -x "$exe" ]; then
    echo "pound: the sources changed since build/release/pound was built: rebuilding it" \
         "(log: build/release/build.log)" >&2
  else
    echo "pound: building the program once into build/release/pound (about a minute on 2 cores," \
         "longer on a busy machine; later calls reuse it at once; log: build/release/build.log)" >&2
  fi
  POUND_BUILD_TARGET=pound pound_build Release || return 1
  echo "pound: built build/release/pound in $((SECONDS - start)) s" >&2
}

# pound_test_runner DIR: the runner of the .pf tests in a configured build directory.
pound_test_runner() {
  sed -n 's/^POUND_TEST_RUNNER:INTERNAL=//p' "$1/CMakeCache.txt" 2>/dev/null
}
