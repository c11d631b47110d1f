#!/usr/bin/env bash
# Installs the release build into build/install and builds the example in
# examples/ against it twice, with find_package(aapat) and with pkg-config,
# then runs both, and imports the installed Python module: the check that the
# installed package is usable on its own.
set -euo pipefail
cd "$(dirname "$0")/.."
prefix=$PWD/build/install
rm -rf "$prefix" build/example
cmake --install build/release --prefix "$prefix" >/dev/null
cmake -S examples -B build/example -G Ninja -DCMAKE_PREFIX_PATH="$prefix" >/dev/null
cmake --build build/example >/dev/null
echo "== example (find_package)"
build/example/evaluate_and_optimize
echo "== example (pkg-config)"
PKG_CONFIG_PATH=$(dirname "$(find "$prefix" -name aapat.pc | head -1)")
export PKG_CONFIG_PATH
# shellcheck disable=SC2046
g++ -O2 examples/evaluate_and_optimize.cpp $(pkg-config --cflags --libs aapat) \
  -o build/example/evaluate_and_optimize_pc
build/example/evaluate_and_optimize_pc >/dev/null && echo "pkg-config build runs and finds the optimum"
echo "== Python module (installed)"
PYTHONPATH=$(dirname "$(find "$prefix" -name 'aapat.cpython-*.so' | head -1)") /usr/bin/python3 -c \
  'import aapat; e = aapat.eval("rgss", objective="laine-aila"); assert abs(e - 0.439) < 0.001, e; print("import aapat:", aapat.__version__, "rgss E2 (laine-aila)", round(e, 4))'
