#!/usr/bin/env bash
# Installs the Debian 12 packages raylab builds, tests and runs with. Needs root (or sudo).
# Skips apt entirely when everything is already there.
set -euo pipefail

packages=(
    build-essential cmake pkg-config git clang-format clang libclang-rt-14-dev
    libglm-dev libassimp-dev libpng-dev nlohmann-json3-dev libopenexr-dev
    libgtest-dev libgmock-dev libembree-dev
    libglfw3-dev libimgui-dev python3-glad libgl-dev
    libseccomp-dev strace
    xvfb xauth xdotool x11-utils libgl1-mesa-dri openbox
    slurm-wlm munge
)

missing=()
for p in "${packages[@]}"; do
    if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q 'install ok installed'; then
        missing+=("$p")
    fi
done
if [ ${#missing[@]} -eq 0 ]; then
    exit 0
fi
echo "raylab: installing ${missing[*]}" >&2
sudo_cmd=()
if [ "$(id -u)" -ne 0 ]; then
    sudo_cmd=(sudo)
fi
export DEBIAN_FRONTEND=noninteractive
"${sudo_cmd[@]}" apt-get update -q
"${sudo_cmd[@]}" apt-get install -y -q --no-install-recommends "${missing[@]}"
