#!/usr/bin/env bash
# CI: what a user of the installed scbt gets (docs/install.md). Reuses the Release build/ that
# the README's test command made: installs it into a temporary prefix, checks the public headers
# stand alone there, builds and runs examples/cpp (CMake package and pkg-config, the latter with
# no LD_LIBRARY_PATH) and examples/python against it on a rendered JPEG clip and on a dataset
# sequence, then builds the Debian packages into another folder (cpack -B) and checks their file
# lists and metadata. Any failure fails the run. The dataset (SCBT_DATASET, default
# ../shared/scbt-dataset) must be there when CI is set; elsewhere its run is skipped, saying so.
set -euo pipefail
cd "$(dirname "$0")/.."
build=${SCBT_BUILD:-build}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
prefix=$work/prefix
python=/usr/bin/python3

version=$(sed -n 's/^project(scbt VERSION \([0-9.]*\).*/\1/p' CMakeLists.txt)
[ -n "$version" ] || { echo "ci_install: no project(scbt VERSION ...) in CMakeLists.txt" >&2; exit 1; }

cmake --install "$build" --prefix "$prefix" >/dev/null
echo "ci_install: installed tree:"
(cd "$prefix" && find . -type f -o -type l | sort | grep -v '^./include/scbt/.*/' | sed 's/^/  /')
echo "  ... and $(find "$prefix/include/scbt" -name '*.h' | wc -l) headers under include/scbt/"

# One version everywhere.
cli_version=$("$prefix/bin/scbt" --version)
py_version=$(PYTHONPATH=$prefix/lib/python3/dist-packages $python -c 'import scbt; print(scbt.__version__)')
cmake_version=$(sed -n 's/^set(PACKAGE_VERSION "\(.*\)")/\1/p' "$prefix/lib/cmake/scbt/scbtConfigVersion.cmake")
pc_version=$(PKG_CONFIG_PATH=$prefix/lib/pkgconfig pkg-config --modversion scbt)
echo "ci_install: versions: project $version, '$cli_version', python $py_version, cmake $cmake_version, pkg-config $pc_version"
for v in "scbt $py_version" "scbt $cmake_version" "scbt $pc_version"; do
  [ "$v" = "scbt $version" ] && [ "$cli_version" = "scbt $version" ] || { echo "ci_install: version mismatch" >&2; exit 1; }
done

# Every public header compiles alone against the installed tree (and OpenCV/Eigen, via scbt.pc):
# a public header that includes a private one fails here.
export PKG_CONFIG_PATH=$prefix/lib/pkgconfig
cflags=$(pkg-config --cflags scbt)
(cd "$prefix/include" && find scbt -name '*.h' | sort) |
  xargs -P 2 -I{} sh -c "echo '#include <{}>' | c++ -std=c++17 -fsyntax-only -Wall -Wextra -Werror -x c++ $cflags -"
echo "ci_install: every installed header compiles on its own"

"$python" scripts/render_frames.py "$work/clip" --frames 30 --formats jpg

# examples/cpp through find_package(scbt), and the same source through pkg-config.
cmake -S examples/cpp -B "$work/example-cpp" -DCMAKE_PREFIX_PATH="$prefix" -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$work/example-cpp" >/dev/null
"$work/example-cpp/track_folder" "$work/clip" "$work/clip/init.txt" >"$work/cpp.txt" 2>"$work/cpp.log"
tail -n 1 "$work/cpp.log"
"$python" scripts/check_boundaries.py "$work/cpp.txt" "$work/clip/truth.txt"
c++ -std=c++17 -O1 examples/cpp/track_folder.cc -o "$work/track_folder_pc" $(pkg-config --cflags --libs scbt opencv4)
# As a user runs it: no LD_LIBRARY_PATH (scbt.pc gives the program the prefix's libdir to search).
env -u LD_LIBRARY_PATH "$work/track_folder_pc" "$work/clip" "$work/clip/init.txt" >"$work/pc.txt" 2>/dev/null
cmp "$work/cpp.txt" "$work/pc.txt"
echo "ci_install: examples/cpp built with pkg-config runs as it is and prints the same boundaries"

PYTHONPATH=$prefix/lib/python3/dist-packages "$python" examples/python/track_folder.py \
  "$work/clip" "$work/clip/init.txt" >"$work/python.txt" 2>"$work/python.log"
tail -n 1 "$work/python.log"
"$python" scripts/check_boundaries.py "$work/python.txt" "$work/clip/truth.txt"

# Both examples on the first 60 frames of a dataset sequence (JPEG, as published): the same
# boundaries as `scbt track` gives there.
dataset=${SCBT_DATASET:-../shared/scbt-dataset}
sequence=BookStand
if [ -d "$dataset/OriginalVideosAVI/$sequence" ]; then
  mkdir "$work/$sequence"
  frames=("$(cd "$dataset/OriginalVideosAVI/$sequence" && pwd)"/*.jpg)  # 0001.jpg ... in order
  ln -s "${frames[@]:0:60}" "$work/$sequence/"
  head -n 1 "$dataset/GroundTruthByPolygons/${sequence}_TrackingGroundTruth.txt" >"$work/$sequence.init"
  "$prefix/bin/scbt" track "$work/$sequence" --init "$work/$sequence.init" -o "$work/$sequence.cli" -q
  "$work/example-cpp/track_folder" "$work/$sequence" "$work/$sequence.init" >"$work/$sequence.cpp" 2>/dev/null
  PYTHONPATH=$prefix/lib/python3/dist-packages "$python" examples/python/track_folder.py \
    "$work/$sequence" "$work/$sequence.init" >"$work/$sequence.py" 2>/dev/null
  "$python" - "$work/$sequence".{cli,cpp,py} <<'EOF'
import sys
import numpy as np
cli, cpp, py = ([np.array(line.split()[1:], float) for line in open(p)] for p in sys.argv[1:])
assert len(cli) == len(cpp) == len(py) == 60, (len(cli), len(cpp), len(py))
worst = max(np.abs(a - b).max() if a.shape == b.shape else np.inf
            for a, b in [*zip(cli, cpp), *zip(cli, py)])
assert worst <= 0.01, f"the examples' boundaries differ from scbt track's by up to {worst} px"
EOF
  echo "ci_install: examples/cpp and examples/python on $sequence (60 JPEG frames): scbt track's boundaries"
elif [ -n "${CI:-}" ]; then
  echo "ci_install: no dataset at $dataset (set SCBT_DATASET): CI runs the examples on it" >&2
  exit 1
else
  echo "ci_install: no dataset at $dataset (set SCBT_DATASET): examples not run on a dataset sequence"
fi

# The Debian packages, into a folder of their own (cpack -B): file lists and metadata.
packages=$work/packages
(cd "$build" && cpack -G DEB -B "$packages" >/dev/null)
deb=$packages/scbt_${version}_amd64.deb
[ -f "$deb" ] || { echo "ci_install: $deb not made" >&2; ls "$packages" >&2; exit 1; }
dpkg-deb -I "$deb" | sed 's/^/  /'
dpkg-deb -c "$deb" | awk '{print $6}' >"$work/files"
for f in ./usr/bin/scbt "./usr/lib/libscbt.so.$version" ./usr/lib/libscbt.so \
  ./usr/include/scbt/tracker/tracker.h ./usr/include/scbt/geometry/polygon_io.h \
  ./usr/include/scbt/depth/boundary_3d.h ./usr/include/scbt/version.h \
  ./usr/lib/cmake/scbt/scbtConfig.cmake ./usr/lib/cmake/scbt/scbtConfigVersion.cmake \
  ./usr/lib/cmake/scbt/scbtTargets.cmake ./usr/lib/pkgconfig/scbt.pc \
  ./usr/lib/python3/dist-packages/scbt.pyi; do
  grep -qxF "$f" "$work/files" || { echo "ci_install: $deb lacks $f" >&2; exit 1; }
done
grep -q '^./usr/lib/python3/dist-packages/scbt\.cpython-.*\.so$' "$work/files" ||
  { echo "ci_install: $deb lacks the Python module" >&2; exit 1; }
if grep -E 'include/scbt/(io|app|eval|render|synthetic|reference|peers)/|edlines\.h' "$work/files"; then
  echo "ci_install: $deb ships private headers (above)" >&2
  exit 1
fi
[ "$(dpkg-deb -f "$deb" Version)" = "$version" ] || { echo "ci_install: wrong Version" >&2; exit 1; }
# Under /usr the loader finds libscbt.so: the package's scbt.pc adds no run-time search path.
if dpkg-deb --fsys-tarfile "$deb" | tar -xO ./usr/lib/pkgconfig/scbt.pc | grep -n rpath; then
  echo "ci_install: $deb's scbt.pc sets an rpath (above)" >&2
  exit 1
fi
depends=$(dpkg-deb -f "$deb" Depends)
for lib in libc6 libopencv-core libgmp python3; do
  [[ "$depends" == *"$lib"* ]] || { echo "ci_install: Depends lacks $lib: $depends" >&2; exit 1; }
done
echo "ci_install: $deb: $(wc -l <"$work/files") entries, Depends computed"
ros_deb=$packages/scbt-ros_${version}_amd64.deb
if [ -f "$ros_deb" ]; then
  dpkg-deb -c "$ros_deb" | awk '{print $6}' >"$work/ros-files"
  for f in ./usr/lib/scbt_ros/scbt_node ./usr/share/scbt_ros/package.xml ./usr/share/scbt_ros/launch/scbt.launch; do
    grep -qxF "$f" "$work/ros-files" || { echo "ci_install: $ros_deb lacks $f" >&2; exit 1; }
  done
  ros_depends=$(dpkg-deb -f "$ros_deb" Depends)
  for lib in "scbt (= $version)" libroscpp; do
    [[ "$ros_depends" == *"$lib"* ]] || { echo "ci_install: $ros_deb Depends lacks $lib: $ros_depends" >&2; exit 1; }
  done
  echo "ci_install: $ros_deb: Depends: $ros_depends"
fi
echo "ci_install: OK"
