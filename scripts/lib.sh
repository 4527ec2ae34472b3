# Shared by scripts/run, scripts/test and scripts/bench_*: install what is missing, build when needed.
# Sourced, not executed.

POUND_ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
# Debian packages the project needs (build, tests, plots).
POUND_PACKAGES="gfortran cmake make liblapack-dev libhdf5-dev python3 python3-numpy python3-h5py python3-matplotlib"
# Scripts that need numpy/h5py/matplotlib run on Debian's interpreter.
POUND_PYTHON=/usr/bin/python3

pound_missing_packages() {
  local p missing=""
  for p in $POUND_PACKAGES; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing="$missing $p"
  done
  echo "$missing"
}

# Install missing Debian packages (once); nothing happens when all are present.
pound_setup() {
  local missing
  missing="$(pound_missing_packages)"
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

# pound_build TYPE: configure (first time only) and build build/<type>; an up-to-date tree is left alone.
pound_build() {
  local type="$1" dir="$POUND_ROOT/build/${1,,}"
  if [ ! -f "$dir/CMakeCache.txt" ]; then
    cmake -S "$POUND_ROOT" -B "$dir" -DCMAKE_BUILD_TYPE="$type" -DPOUND_NATIVE=ON >/dev/null || return 1
  fi
  cmake --build "$dir" -j "$(nproc)" -- --no-print-directory >"$dir/build.log" 2>&1 || {
    cat "$dir/build.log" >&2
    echo "pound: build failed ($type), log: $dir/build.log" >&2
    return 1
  }
}
