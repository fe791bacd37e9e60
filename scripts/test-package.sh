#!/usr/bin/env bash
# The Debian package, as CI checks it: cpack -G DEB in the build folder, install it with dpkg,
# run the installed `cgtmo apply` on a bundled scene and `import cgtmo` in Debian's python3, then
# remove it (also when a check fails). Needs root (or sudo without a password) for dpkg; with
# neither it says so and skips the install, having still built the package.
# Usage: scripts/test-package.sh [BUILD_DIR]     (default: build)
set -euo pipefail
cd "$(dirname "$0")/.."
root=$PWD
build=$(cd "${1:-${BUILD_DIR:-build}}" && pwd)
fail() { echo "test-package: FAIL: $*" >&2; exit 1; }

(cd "$build" && cpack -G DEB >cpack.log 2>&1) || { tail -30 "$build/cpack.log"; fail "cpack -G DEB (see $build/cpack.log)"; }
deb=$(ls -t "$build"/cgtmo_*.deb | head -1)
echo "test-package: built $(basename "$deb") ($(du -h "$deb" | cut -f1))"
contents=$(dpkg-deb -c "$deb")
# Here-strings, not `echo | grep -q`: grep -q stops at the first match, and under pipefail the
# echo's SIGPIPE on a listing beyond the pipe's buffer failed the check for a file that was there.
for f in ./usr/bin/cgtmo ./usr/bin/cgtmo-slurm ./usr/include/cgtmo/pipeline/apply_file.h ./usr/share/cgtmo/ocio_config/config.ocio \
         ./usr/share/cgtmo/blender/cgtmo_addon.zip ./usr/share/doc/cgtmo/LICENSE; do
  grep -q " $f\$" <<<"$contents" || fail "$f is not in the package"
done
grep -Eq "/usr/lib/([^/]+/)?cmake/cgtmo/cgtmoConfig.cmake$" <<<"$contents" || fail "the CMake package is not in the package"
grep -q "/usr/lib/python3[^/]*/dist-packages/cgtmo\..*so\$" <<<"$contents" || fail "the Python module is not in the package"
# What find_package(cgtmo) needs besides the package itself is named in its Suggests.
suggests=$(dpkg-deb -f "$deb" Suggests)
for p in libopenimageio-dev libopencolorio-dev libopenexr-dev liblcms2-dev; do
  echo "$suggests" | grep -q "$p" || fail "the package does not suggest $p (Suggests: $suggests)"
done

SUDO=""
if [ "$(id -u)" -ne 0 ]; then
  if command -v sudo >/dev/null && sudo -n true 2>/dev/null; then
    SUDO="sudo -n"
  else
    echo "test-package: SKIPPED installing $(basename "$deb"): not root and no password-less sudo"
    exit 0
  fi
fi
if dpkg-query -W -f='${Status}' cgtmo 2>/dev/null | grep -q "install ok installed"; then
  echo "test-package: note: a cgtmo package is installed already (a run stopped half-way?); it is replaced and removed"
fi
# dpkg waits for no one: when apt or another dpkg holds its lock, try again for up to 2 minutes.
dpkg_retry() {
  local log=$1; shift
  for _ in $(seq 12); do
    if $SUDO dpkg "$@" >"$log" 2>&1; then return 0; fi
    grep -qi "lock" "$log" || return 1
    sleep 10
  done
  return 1
}

work=$(mktemp -d)
installed=0
cleanup() {
  if [ "$installed" = 1 ]; then
    dpkg_retry "$work/remove.log" -r cgtmo || { cat "$work/remove.log"; echo "test-package: FAIL: dpkg -r cgtmo" >&2; }
  fi
  rm -rf "$work"
}
trap cleanup EXIT

dpkg_retry "$work/install.log" -i "$deb" || { installed=1; cat "$work/install.log"; fail "dpkg -i $(basename "$deb")"; }
installed=1
# The installed files only: no build folder on any path, a folder of our own as the working dir.
cd "$work"
env -u PYTHONPATH -u OCIO PATH=/usr/bin:/bin /usr/bin/cgtmo --version
env -u PYTHONPATH -u OCIO PATH=/usr/bin:/bin /usr/bin/cgtmo apply "$root/tests/scenes/cornell/cornell.exr" \
  -o "$work/cornell.png" --op cgtmo -q || fail "the installed cgtmo apply"
[ -s "$work/cornell.png" ] || fail "the installed cgtmo apply wrote nothing"
env -u PYTHONPATH -u OCIO /usr/bin/python3 -c "import cgtmo, sys; assert cgtmo.__file__.startswith('/usr/lib/'), cgtmo.__file__; print('import cgtmo:', cgtmo.__file__)" ||
  fail "import cgtmo in /usr/bin/python3"
dpkg_retry "$work/remove.log" -r cgtmo || { cat "$work/remove.log"; fail "dpkg -r cgtmo"; }
installed=0
[ ! -e /usr/bin/cgtmo ] || fail "/usr/bin/cgtmo is still there after dpkg -r"
echo "test-package: OK (built, installed, ran cgtmo apply and import cgtmo, removed)"
