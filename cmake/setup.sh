#!/usr/bin/env bash
# The README's quick start, first command: install the dependencies (Debian
# 12), build in Release into ./build and generate the default tables into
# luts/ from luts/brdflut.toml.
#
# apt-get runs directly as root (a container's root shell, where sudo is
# usually missing) and through sudo otherwise.
set -euo pipefail
cd "$(dirname "$0")/.."

packages=(cmake make g++ libopenexr-dev libimath-dev libtbb-dev libcli11-dev nlohmann-json3-dev libpng-dev
          libgtest-dev libbenchmark-dev clang libclang-rt-14-dev libvulkan-dev mesa-vulkan-drivers glslang-tools)

if [ "$(id -u)" = 0 ]; then
    as_root=()
elif command -v sudo > /dev/null; then
    as_root=(sudo)
else
    echo "cmake/setup.sh: installing the packages needs root: run it as root, or install sudo" >&2
    exit 1
fi
export DEBIAN_FRONTEND=noninteractive
# sudo resets the environment; pass DEBIAN_FRONTEND on explicitly.
"${as_root[@]}" env DEBIAN_FRONTEND=noninteractive apt-get update
"${as_root[@]}" env DEBIAN_FRONTEND=noninteractive apt-get install -y --no-install-recommends "${packages[@]}"

cmake -S . -B build -DCMAKE_BUILD_TYPE=Release
cmake --build build -j2
./build/brdflut generate --config luts/brdflut.toml
