#!/usr/bin/env bash
# Installs the Debian packages oflab needs, and nothing when they are all present.
# Shared by both README commands and by .ci/run, so all three see the same machine.
# `install-deps.sh --only PACKAGE...` does the same for the packages named (tools/build-web.sh).
set -euo pipefail

packages=(
  cmake g++ make pkg-config
  libvtk9-dev libvtk9-qt-dev qtbase5-dev libqt5opengl5-dev mpi-default-dev libglm-dev
  nlohmann-json3-dev libstb-dev
  libavcodec-dev libavformat-dev libswscale-dev libavutil-dev libgif-dev
  help2man dpkg-dev file
  libgtest-dev libgmock-dev libbenchmark-dev
  python3-dev pybind11-dev python3-numpy python3-pytest
  xvfb xauth libgl1-mesa-dri
  clang-14 clang libclang-rt-14-dev clang-format-14
  pmccabe
)
# OpenCV is an optional benchmark peer; ask for it with OFLAB_WITH_OPENCV=1.
if [[ "${OFLAB_WITH_OPENCV:-0}" == "1" ]]; then packages+=(libopencv-dev); fi
# pixman is another optional benchmark peer; ask for it with OFLAB_WITH_PIXMAN=1.
if [[ "${OFLAB_WITH_PIXMAN:-0}" == "1" ]]; then packages+=(libpixman-1-dev); fi
if [[ "${1:-}" == "--only" ]]; then packages=("${@:2}"); fi

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done
if [[ ${#missing[@]} -eq 0 ]]; then
  exit 0
fi
echo "oflab: installing ${missing[*]}" >&2
sudo_cmd=()
if [[ $(id -u) -ne 0 ]]; then sudo_cmd=(sudo); fi
"${sudo_cmd[@]}" apt-get update -qq
DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
