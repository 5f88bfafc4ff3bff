#!/usr/bin/env bash
# Installs every Debian package NoveltyMaps needs to build, test and run.
# Idempotent: packages already present are skipped; `apt-get update` runs at most once
# per invocation and only when something is missing. Never prompts.
set -euo pipefail

PACKAGES=(
  build-essential cmake pkg-config git ninja-build clang-format clang libclang-rt-dev
  libmrpt-dev mrpt-apps
  libopencv-dev libopencv-contrib-dev
  libeigen3-dev libceres-dev liboctomap-dev libopengv-dev
  libode-dev libembree-dev
  libgtest-dev libgmock-dev libbenchmark-dev
  libtclap-dev zlib1g-dev libzstd-dev libpng-dev
  g++-aarch64-linux-gnu qemu-user  # scripts/cross_aarch64.sh: the kernels built and tested for ARM
)

missing=()
for p in "${PACKAGES[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "setup: all ${#PACKAGES[@]} packages present" >&2
  exit 0
fi

SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
echo "setup: installing ${#missing[@]} packages: ${missing[*]}" >&2
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
echo "setup: done" >&2
