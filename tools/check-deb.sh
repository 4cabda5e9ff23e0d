#!/usr/bin/env bash
# Packs the built tree with CPack into a temporary directory and checks the .deb with
# dpkg-deb: its name, the Depends field (VTK, Qt 5, FFmpeg's libraries, giflib), and that
# it holds both programs, the desktop entry, the icon, both man pages, the copyright file,
# the datasets, the CMake package, the Python module and the browser page when they were
# built. Usage:
# bash tools/check-deb.sh [BUILD_DIR].
set -euo pipefail
cd "$(dirname "$0")/.."
build=$(cd "${1:-build}" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
(cd "$build" && cpack -G DEB -B "$work" -D CPACK_OUTPUT_FILE_PREFIX="$work" > "$work/cpack.log" 2>&1) || { cat "$work/cpack.log" >&2; exit 1; }
version=$(sed -n 's/^CMAKE_PROJECT_VERSION:STATIC=//p' "$build/CMakeCache.txt")
deb="$work/oflab_${version}_amd64.deb"
[[ -f "$deb" ]] || { echo "check-deb: no $deb (made: $(ls "$work"))" >&2; exit 1; }

fail=0
depends=$(dpkg-deb -f "$deb" Depends)
echo "Depends: $depends"
for lib in libvtk9 libqt5widgets5 libqt5gui5 libavcodec libavformat libswscale libgif7 libc6; do
  grep -q "$lib" <<< "$depends" || { echo "check-deb: Depends lacks $lib" >&2; fail=1; }
done
contents=$(dpkg-deb -c "$deb")
for f in ./usr/bin/oflab ./usr/bin/oflab-cli ./usr/share/applications/oflab.desktop \
         ./usr/share/icons/hicolor/scalable/apps/oflab.svg ./usr/share/man/man1/oflab.1.gz \
         ./usr/share/man/man1/oflab-cli.1.gz ./usr/share/doc/oflab/copyright \
         ./usr/share/oflab/datasets/scripts/loop.json ./usr/share/oflab/manual/install.md \
         ./usr/include/oflab/flow/flow_field.h; do
  grep -q " $f\$" <<< "$contents" || { echo "check-deb: the package lacks $f" >&2; fail=1; }
done
grep -q "/cmake/oflab/oflabConfig.cmake\$" <<< "$contents" ||
  { echo "check-deb: the package lacks oflabConfig.cmake" >&2; fail=1; }
# The Python module, when it was built (python/CMakeLists.txt; manual/python.md): the package
# in the interpreter's folder, and Depends naming the interpreter and numpy.
pydir=$(sed -n 's/^OFLAB_INSTALL_PYTHONDIR:[A-Z]*=//p' "$build/CMakeCache.txt")
if [[ -n "$pydir" ]]; then
  for f in __init__.py __init__.pyi py.typed; do
    grep -q " ./usr/$pydir/oflab/$f\$" <<< "$contents" ||
      { echo "check-deb: the package lacks ./usr/$pydir/oflab/$f" >&2; fail=1; }
  done
  grep -q " ./usr/$pydir/oflab/_oflab\..*\.so\$" <<< "$contents" ||
    { echo "check-deb: the package lacks the module ./usr/$pydir/oflab/_oflab*.so" >&2; fail=1; }
  grep -q "python3-numpy" <<< "$depends" || { echo "check-deb: Depends lacks python3-numpy" >&2; fail=1; }
fi
# The browser page, when tools/build-web.sh built it before the package (manual/web.md).
page=$(sed -n 's/^OFLAB_WEB_PAGE:[A-Z]*=//p' "$build/CMakeCache.txt")
if [[ -n "$page" && -f "$page" ]]; then
  grep -q " ./usr/share/oflab/web/oflab-web.html\$" <<< "$contents" ||
    { echo "check-deb: the package lacks ./usr/share/oflab/web/oflab-web.html" >&2; fail=1; }
fi
# The man pages carry the programs' --help.
dpkg-deb -x "$deb" "$work/root"
zcat "$work/root/usr/share/man/man1/oflab-cli.1.gz" | grep -q "experiments" ||
  { echo "check-deb: oflab-cli.1 does not list the commands" >&2; fail=1; }
# The packaged Python module imports and plays a shipped script from the packaged datasets.
if [[ -n "$pydir" ]]; then
  python=$(sed -n 's/^OFLAB_PYTHON_EXECUTABLE:[A-Z]*=//p' "$build/CMakeCache.txt")
  (cd / && PYTHONPATH="$work/root/usr/$pydir" OFLAB_DATASETS="$work/root/usr/share/oflab/datasets" \
    "${python:-python3}" -c "import oflab; assert oflab.__file__.startswith('$work'), oflab.__file__
assert oflab.run('rotation', 'perspective', frames=4, repeat_timing=1).summary['frames'] == 4") ||
    { echo "check-deb: the packaged Python module does not run" >&2; fail=1; }
fi
if command -v desktop-file-validate > /dev/null; then
  desktop-file-validate "$work/root/usr/share/applications/oflab.desktop" || fail=1
fi
[[ $fail -eq 0 ]] && echo "check-deb: $(basename "$deb") ($(du -h "$deb" | cut -f1)) is complete"
exit $fail
