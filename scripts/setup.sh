#!/usr/bin/env bash
# Installs exactly the Debian 12 packages scbt needs to build, test and benchmark.
# Idempotent: packages already present are left alone. Run as root (or with sudo).
set -euo pipefail

packages=(
  cmake g++ make pkg-config dpkg-dev file
  libopencv-dev libopencv-contrib-dev
  libboost-graph-dev libcgal-dev libeigen3-dev
  libcli11-dev
  libgtest-dev libgmock-dev libbenchmark-dev
  clang-format
  clang libclang-rt-14-dev
  pybind11-dev python3-dev python3-numpy python3-pytest python3-opencv
  python3-venv python3-pip python3-setuptools python3-wheel
  xvfb xdotool x11-apps imagemagick
  ros-core-dev libroscpp-dev libsensor-msgs-dev libgeometry-msgs-dev libstd-msgs-dev
  libdiagnostic-msgs-dev
  libcv-bridge-dev libimage-transport-dev libmessage-filters-dev
  python3-rosmaster python3-rospy python3-rostopic python3-rosbag python3-roslaunch rosout
  python3-sensor-msgs python3-geometry-msgs python3-std-msgs nlohmann-json3-dev
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done

if ((${#missing[@]})); then
  echo "scbt setup: installing ${missing[*]}" >&2
  SUDO=""
  [ "$(id -u)" -eq 0 ] || SUDO="sudo"
  export DEBIAN_FRONTEND=noninteractive
  $SUDO apt-get update -qq
  $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
else
  echo "scbt setup: all packages present" >&2
fi
