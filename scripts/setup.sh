#!/usr/bin/env bash
# Installs the Debian 12 packages Penumbra builds against. Idempotent: only missing packages
# are installed. Needs root (or sudo); nothing else is downloaded at build time.
set -euo pipefail

packages=(
  build-essential cmake ninja-build pkg-config
  libglfw3-dev libglm-dev libtinygltf-dev libimgui-dev libosmesa6-dev libegl-dev libgl1-mesa-dev
  libegl-mesa0 libspdlog-dev python3-glad libstb-dev nlohmann-json3-dev libembree-dev
  libdraco-dev libmeshoptimizer-dev libgtest-dev libbenchmark-dev libnlopt-dev libgraphviz-dev python3-matplotlib xvfb xauth xdotool clang libclang-rt-14-dev
)

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "setup: all ${#packages[@]} packages already installed"
  exit 0
fi

if [ "$(id -u)" -eq 0 ]; then
  as_root=()
elif command -v sudo >/dev/null 2>&1 && sudo -n true 2>/dev/null; then
  as_root=(sudo)
else
  echo "setup: these packages are missing and installing them needs root: ${missing[*]}" >&2
  echo "setup: run this script as root (or with sudo), or ask an administrator to run:" >&2
  echo "  apt-get install -y ${missing[*]}" >&2
  exit 2
fi

echo "setup: installing ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
"${as_root[@]}" apt-get update -qq
# No --no-upgrade: libosmesa6 needs the Mesa runtime of the same version.
"${as_root[@]}" apt-get install -y -qq "${missing[@]}" >/dev/null
echo "setup: done"
