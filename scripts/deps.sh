# Debian packages hoct needs to build, test and run; sourced by scripts/setup and scripts/test.
# ensure_packages installs the missing ones with apt-get (as root, or through sudo).

HOCT_PACKAGES=(
  build-essential cmake ninja-build
  libeigen3-dev libcli11-dev nlohmann-json3-dev libpugixml-dev zlib1g-dev
  libgtest-dev libgmock-dev libcairo2-dev pkg-config
  python3 python3-dev python3-numpy python3-paraview python3-meshio python3-netcdf4 python3-gmsh python3-networkx python3-pytest python3-matplotlib pybind11-dev
  python3-pip python3-venv python3-setuptools python3-wheel time
  # ParaView 5.11 for the plugin and its headless test (python3-paraview replaces python3-vtk9:
  # its vtkmodules serve as the independent VTK reader in the tests).
  paraview-dev libopenmpi-dev openmpi-bin libdouble-conversion-dev liblz4-dev libutfcpp-dev xvfb xauth
  # What ParaView's VTK reader modules (legacy .vtk, XDMF, Exodus II) link to, found with them.
  libnetcdf-dev libhdf5-dev libxml2-dev libboost-dev
  # DOLFINx: the tests read the files it writes (.vtu, .pvtu, XDMF), written by it
  python3-dolfinx
  # mpi4py: the Python module's contour_tree(..., comm=) over MPI, and its test
  python3-mpi4py
)
# Opt-in (about 125 packages, 1.2 GB): deal.II 9.4, for tests/python/test_dealii_files.py, which
# reads the files deal.II writes and is skipped without it.
if [ "${HOCT_WITH_DEALII:-0}" = 1 ]; then
  HOCT_PACKAGES+=(libdeal.ii-dev)
fi

ensure_packages() {
  local missing=()
  local p
  for p in "${HOCT_PACKAGES[@]}"; do
    if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
      missing+=("$p")
    fi
  done
  if [ ${#missing[@]} -eq 0 ]; then
    return 0
  fi
  echo "hoct: installing missing Debian packages: ${missing[*]}"
  local sudo=""
  if [ "$(id -u)" -ne 0 ]; then
    if command -v sudo >/dev/null 2>&1; then
      sudo="sudo"
    else
      echo "hoct: need root (or sudo) to install: ${missing[*]}" >&2
      return 1
    fi
  fi
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
}

# Configure (if needed) and build into $HOCT_BUILD (default: build/), Release, with Ninja.
build_hoct() {
  local root build
  root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
  build="${HOCT_BUILD:-$root/build}"
  if [ ! -f "$build/build.ninja" ]; then
    cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release
  fi
  cmake --build "$build" -j "$(nproc)"
}
