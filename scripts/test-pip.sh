#!/usr/bin/env bash
# The Python user's path (docs/python.md): a venv with Debian's packages,
# `pip install --no-build-isolation .` with no network, `import aapat`; the
# installed type stubs are the module's (python/make_stubs.py --check). The
# test script runs it after the release build, whose configured folder the
# install reuses (AAPAT_CMAKE_BUILD_DIR); a user without it builds build/pip.
set -euo pipefail
cd "$(dirname "$0")/.."
venv=$(mktemp -d)
trap 'rm -rf "$venv"' EXIT
/usr/bin/python3 -m venv --system-site-packages "$venv"
AAPAT_CMAKE_BUILD_DIR=${AAPAT_CMAKE_BUILD_DIR:-build/release} \
  "$venv/bin/pip" install --no-build-isolation --no-index --quiet .
site=$("$venv/bin/python" -c "import sysconfig; print(sysconfig.get_paths()['purelib'])")
test -f "$site/aapat-stubs/__init__.pyi" || { echo "no type stubs installed"; exit 1; }
# Outside the source tree, so that the installed module is the one imported.
(cd "$venv" && "$venv/bin/python" - <<'PY'
import aapat
assert aapat.__file__.startswith(__import__("sys").prefix), aapat.__file__
assert round(aapat.eval("flipquad", objective="laine-aila"), 4) == 0.3643  # Laine-Aila Table 2
print("pip install .: aapat", aapat.__version__, "from", aapat.__file__)
PY
)
(cd "$venv" && "$venv/bin/python" "$OLDPWD/python/make_stubs.py" --check "$site/aapat-stubs/__init__.pyi")
echo "1 passed, 0 failed"
