#!/usr/bin/env bash
# CI: the scbt Python module through pip in a virtual environment (README, docs/install.md).
# A fresh `python3 -m venv --system-site-packages` (numpy and cv2 from Debian), `pip install
# --no-build-isolation .` offline, reusing the CMake build tree (SCBT_BUILD, default build/; only
# its scbt_python target is brought up to date), then: `import scbt` from the venv, its
# __version__ equal to `scbt --version`, examples/python/track_folder.py on a dataset sequence
# (skipped with a message when the dataset is absent and CI is not set), `pip wheel` tagged for
# this interpreter, and `pip uninstall -y scbt` leaving the venv's file list as it was.
set -euo pipefail
cd "$(dirname "$0")/.."
build=$(realpath "${SCBT_BUILD:-build}")
dataset=${SCBT_DATASET:-../shared/scbt-dataset}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
export PYTHONDONTWRITEBYTECODE=1 PIP_NO_INDEX=1 PIP_DISABLE_PIP_VERSION_CHECK=1
start=$SECONDS

/usr/bin/python3 -m venv --system-site-packages "$work/venv"
py=$work/venv/bin/python
(cd "$work/venv" && find . -type f -o -type l | sort) >"$work/before"

SCBT_CMAKE_BUILD_DIR=$build "$py" -m pip install -q --no-build-isolation . >"$work/pip.log" 2>&1 ||
  { cat "$work/pip.log" >&2; echo "ci_venv: pip install failed" >&2; exit 1; }
echo "ci_venv: installed: $(cd "$work/venv" && find . -name 'scbt*' | sort | tr '\n' ' ')"

# The venv's module, not Debian's or the build tree's.
location=$(cd "$work" && "$py" -c 'import scbt; print(scbt.__file__)')
[[ "$location" == "$work/venv/"* ]] || { echo "ci_venv: scbt imported from $location" >&2; exit 1; }
py_version=$(cd "$work" && "$py" -c 'import scbt; print(scbt.__version__)')
cli_version=$("$build/src/scbt/cli/scbt" --version)
[ "$cli_version" = "scbt $py_version" ] ||
  { echo "ci_venv: scbt.__version__ $py_version, CLI '$cli_version'" >&2; exit 1; }
echo "ci_venv: import scbt from the venv, version $py_version = '$cli_version'"

sequence=$dataset/OriginalVideosAVI/Bowl
truth=$dataset/GroundTruthByPolygons/Bowl_TrackingGroundTruth.txt
if [ -d "$sequence" ] && [ -f "$truth" ]; then
  mkdir "$work/bowl"
  for f in $(ls "$sequence" | sort | head -n 60); do ln -s "$(realpath "$sequence/$f")" "$work/bowl/$f"; done
  head -n 60 "$truth" >"$work/truth.txt"
  (cd "$work" && "$py" "$OLDPWD/examples/python/track_folder.py" bowl truth.txt) \
    >"$work/tracked.txt" 2>"$work/tracked.log"
  tail -n 1 "$work/tracked.log"
  /usr/bin/python3 scripts/check_boundaries.py "$work/tracked.txt" "$work/truth.txt" \
    --max-centroid-px 10 --max-area-change 0.25
elif [ -n "${CI:-}" ]; then
  echo "ci_venv: dataset sequence $sequence missing (CI is set)" >&2
  exit 1
else
  echo "ci_venv: SKIPPED the example on a dataset sequence: $sequence not found (set SCBT_DATASET)"
fi

# A wheel tagged for this interpreter and platform: cpXY-cpXY-<platform>.
SCBT_CMAKE_BUILD_DIR=$build "$py" -m pip wheel -q --no-build-isolation --no-deps -w "$work/wheel" . \
  >"$work/wheel.log" 2>&1 || { cat "$work/wheel.log" >&2; echo "ci_venv: pip wheel failed" >&2; exit 1; }
wheel=$(basename "$(ls "$work"/wheel/scbt-*.whl)")
expected=$("$py" -c 'import sys, sysconfig
t = f"cp{sys.version_info[0]}{sys.version_info[1]}"
print(f"{t}-{t}-" + sysconfig.get_platform().replace("-", "_").replace(".", "_"))')
[ "$wheel" = "scbt-$py_version-$expected.whl" ] ||
  { echo "ci_venv: wheel $wheel, expected scbt-$py_version-$expected.whl" >&2; exit 1; }
"$py" - "$work/wheel/$wheel" <<'PY'
import sys, zipfile
names = zipfile.ZipFile(sys.argv[1]).namelist()
assert any(n.startswith("scbt.cpython-") and n.endswith(".so") for n in names), names
assert "scbt.pyi" in names, names
PY
echo "ci_venv: $wheel (module and stub inside)"

"$py" -m pip uninstall -q -y scbt
(cd "$work/venv" && find . -type f -o -type l | sort) >"$work/after"
diff "$work/before" "$work/after" >&2 ||
  { echo "ci_venv: pip uninstall left the files above behind" >&2; exit 1; }
echo "ci_venv: pip uninstall -y scbt left the venv as it was"
echo "ci_venv: OK ($((SECONDS - start)) s)"
