#!/usr/bin/env bash
# Installs the Debian 12 packages halfvec needs. Idempotent: installs only what is missing.
# Uses sudo when not root.
set -euo pipefail
pkgs=(build-essential cmake ninja-build pkg-config
      libglfw3-dev libglm-dev libtinygltf-dev libimgui-dev libstb-dev nlohmann-json3-dev
      libegl-dev libgl-dev libegl-mesa0 libgl1-mesa-dri libgtest-dev libbenchmark-dev libembree-dev
      glslang-tools xvfb x11-apps)
# The fuzzers only (scripts/fuzz.sh sets HV_FUZZ_SETUP=1): clang with libFuzzer and its sanitizer
# runtimes, python3 for the seeds. Not needed by the default build (scripts/sanitize.sh uses GCC's
# sanitizers, which come with build-essential).
if [ "${HV_FUZZ_SETUP:-0}" = 1 ]; then pkgs+=(clang-14 libclang-rt-14-dev python3); fi
missing=()
for p in "${pkgs[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  exit 0
fi
echo "setup: installing ${missing[*]}"
SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
$SUDO apt-get update -qq
DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
