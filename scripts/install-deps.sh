#!/usr/bin/env bash
# Installs cgtmo's build and test dependencies from Debian 12 packages (apt-get only).
# Idempotent: packages already present are skipped, so a second run costs a few seconds.
set -euo pipefail

packages=(
  build-essential cmake pkg-config ninja-build
  libopenimageio-dev openimageio-tools
  libopencolorio-dev opencolorio-tools
  libopenexr-dev libimath-dev python3-imath
  libcli11-dev nlohmann-json3-dev
  liblcms2-dev                  # ICC profiles of display-encoded outputs
  libgtest-dev libgmock-dev libbenchmark-dev
  libeigen3-dev libtbb-dev
  libopencv-dev  # OpenImageIO's CMake config names /usr/include/opencv4
  libopencv-contrib-dev  # benchmark-only: the ximgproc peers of bench/cgtmo-bench
  pybind11-dev python3-dev python3-numpy python3-matplotlib
  python3-pyopencolorio python3-openimageio
  blender hyperfine
  clang-14 libclang-rt-14-dev   # sanitizer and libFuzzer builds (scripts/test-hardened.sh)
  slurm-wlm munge               # the Slurm farm test (tests/slurm)
  strace                        # the fault tests inject a SIGKILL at the rename (tests/faults)
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#packages[@]} packages present"
  exit 0
fi

echo "install-deps: installing ${#missing[@]} packages: ${missing[*]}"
SUDO=""
[ "$(id -u)" -eq 0 ] || SUDO="sudo"
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
echo "install-deps: done"
