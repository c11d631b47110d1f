#!/usr/bin/env bash
# Installs the Debian packages aapat builds, tests and benchmarks with.
set -euo pipefail
packages=(cmake ninja-build g++ pkg-config
  libcli11-dev nlohmann-json3-dev libfmt-dev libpng-dev libgif-dev libtbb-dev libhwy-dev libfftw3-dev libnlopt-dev libvulkan-dev glslang-tools mesa-vulkan-drivers
  libgtest-dev libgmock-dev libbenchmark-dev librapidcheck-dev clang-format
  clang libclang-rt-14-dev  # clang builds the ASan+UBSan preset with the libFuzzer targets
  pybind11-dev python3-dev python3-numpy python3-pytest  # the Python module and its tests
  python3-venv python3-pip python3-setuptools python3-wheel  # pip install . (setup.py drives CMake)
  libassimp-dev assimp-testmodels libjpeg-dev  # model files (io/mesh_file.h), their JPEG textures, and the real models the tests and study render
  chromium python3-pil  # the study report opened in a real browser (scripts/test-report.sh)
  emscripten  # the library as WebAssembly for the explorer page (scripts/build-web.sh)
  libopenmpi-dev openmpi-bin)  # runs across processes and machines (src/cluster, docs/cluster.md)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  sudo_cmd=""
  [ "$(id -u)" -eq 0 ] || sudo_cmd="sudo"
  $sudo_cmd apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo_cmd apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi
