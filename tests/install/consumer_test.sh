#!/usr/bin/env bash
# The installed tree: `cmake --install` into a fresh prefix, then checks that
#   - the public headers are under include/cgtmo, each one's cgtmo includes installed too, and no
#     internal header is;
#   - a program built with find_package(cgtmo) against that prefix alone tone-maps a scene;
#   - the Python module imports from the prefix, the OCIO config passes ociocheck there, the
#     add-on zip is there.
# Usage: consumer_test.sh BUILD_DIR SOURCE_DIR PYTHON WORK_DIR
set -euo pipefail
build=$1 src=$2 python=$3 work=$4
fail() { echo "consumer_test: FAIL: $*" >&2; exit 1; }

rm -rf "$work"
mkdir -p "$work"
prefix=$work/prefix
cmake --install "$build" --prefix "$prefix" >"$work/install.log" || fail "cmake --install (see $work/install.log)"

inc=$prefix/include/cgtmo
[ -f "$inc/pipeline/apply_file.h" ] || fail "include/cgtmo/pipeline/apply_file.h not installed"
for internal in filters/guide.h bake/bake.h io/temp_files.h util/allocation.h; do
  [ -f "$src/src/cgtmo/$internal" ] || fail "the check names $internal, which the source tree no longer has"
  [ ! -e "$inc/$internal" ] || fail "internal header $internal installed"
done
while IFS= read -r h; do
  while IFS= read -r dep; do
    [ -f "$prefix/include/$dep" ] || fail "installed ${h#$prefix/include/} includes $dep, which is not installed"
  done < <(sed -n 's/^#include "\(cgtmo\/[^"]*\)".*/\1/p' "$h")
done < <(find "$inc" -name '*.h')

# The project version of the build under test: the package and the library must report it.
version=$(sed -n 's/^CMAKE_PROJECT_VERSION:STATIC=//p' "$build/CMakeCache.txt")
[ -n "$version" ] || fail "no CMAKE_PROJECT_VERSION in $build/CMakeCache.txt"
cmake -S "$src/tests/install/consumer" -B "$work/build" -DCMAKE_BUILD_TYPE=Release -DCGTMO_EXPECTED_VERSION="$version" \
  -DCMAKE_PREFIX_PATH="$prefix" -DCMAKE_FIND_USE_PACKAGE_REGISTRY=OFF >"$work/configure.log" 2>&1 ||
  { cat "$work/configure.log"; fail "configuring the consumer against the installed package"; }
grep -q "cgtmo_DIR:PATH=$prefix/" "$work/build/CMakeCache.txt" || fail "find_package(cgtmo) did not find the installed package"
cmake --build "$work/build" >"$work/build.log" 2>&1 || { tail -30 "$work/build.log"; fail "building the consumer"; }
out=$("$work/build/consumer" "$src/tests/scenes/cornell/cornell.exr" "$work/cornell.png" drago) || fail "the consumer failed"
echo "$out"
echo "$out" | grep -q "operators; .* drago -> " || fail "unexpected consumer output"
echo "$out" | grep -q "^cgtmo $version, " || fail "the installed library does not report version $version"
[ -s "$work/cornell.png" ] || fail "the consumer wrote no image"
# Same pixels as the installed CLI.
"$prefix/bin/cgtmo" apply "$src/tests/scenes/cornell/cornell.exr" -o "$work/cornell-cli.png" --op drago -q
"$python" - "$work/cornell.png" "$work/cornell-cli.png" <<'PY' || fail "the consumer's image differs from cgtmo apply's"
import sys, OpenImageIO as oiio
a, b = (oiio.ImageBuf(p) for p in sys.argv[1:3])
sys.exit(0 if oiio.ImageBufAlgo.compare(a, b, 0, 0).nfail == 0 else 1)
PY

site=$(find "$prefix" -name 'cgtmo*.so' -path '*dist-packages*' -printf '%h\n' | head -1)
[ -n "$site" ] || fail "no Python module under a dist-packages folder of the prefix"
(cd "$work" && PYTHONPATH="$site" "$python" -c "import cgtmo, sys; sys.exit(0 if cgtmo.__file__.startswith('$site') else 1)") ||
  fail "import cgtmo from $site"
(cd "$work" && PYTHONPATH="$site" "$python" -c "import cgtmo, sys; sys.exit(0 if cgtmo.__version__ == '$version' else 1)") ||
  fail "the installed Python module does not report version $version"

[ -f "$prefix/share/cgtmo/ocio_config/config.ocio" ] || fail "share/cgtmo/ocio_config/config.ocio not installed"
# The installed program finds the installed config (never ./ocio_config), and the farm scripts are beside it.
"$prefix/bin/cgtmo" bake --help | grep -qF "default: the shipped one, $prefix/share/cgtmo/ocio_config/config.ocio" ||
  fail "the installed cgtmo bake does not default --cgtmo-config to $prefix/share/cgtmo/ocio_config/config.ocio"
for s in cgtmo-slurm cgtmo-slurm-submit cgtmo-slurm-task cgtmo-slurm-report; do
  [ -x "$prefix/bin/$s" ] || fail "bin/$s not installed"
done
if command -v ociocheck >/dev/null; then
  ociocheck --iconfig "$prefix/share/cgtmo/ocio_config/config.ocio" >"$work/ociocheck.log" 2>&1 ||
    { tail -20 "$work/ociocheck.log"; fail "ociocheck on the installed config"; }
fi
ls "$prefix"/share/cgtmo/blender/cgtmo_addon.zip >/dev/null || fail "the add-on zip is not installed"
[ -f "$prefix/share/doc/cgtmo/LICENSE" ] || fail "LICENSE not installed"
echo "consumer_test: OK ($prefix)"
