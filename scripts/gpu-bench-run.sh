#!/bin/sh
# run.sh of the packed penumbra-gl GPU bench (made by scripts/pack-gpu-bench.sh): the bench's GPU
# mode (bench/gpu.ts) with the Node, headless-gl and Vulkan loader packed beside this script, on a
# bare Linux x86-64 machine with a GPU and a Vulkan driver. Needs no X display and no repository.
#   ./run.sh                                  # every scene, the machine's Vulkan driver
#   ./run.sh --scenes=S1,S3 --frames=50 --warmup=10
#   VK_ICD_FILENAMES=/usr/share/vulkan/icd.d/nvidia_icd.json ./run.sh
#   VK_ICD_FILENAMES=/usr/share/vulkan/icd.d/lvp_icd.x86_64.json ./run.sh   # Mesa's lavapipe (CPU)
# Prints the table (the GL renderer string in its header names the Vulkan device) and writes
# results/gpu-<UTC time>.json here (--out=<file> to write elsewhere).
# PENUMBRA_BUNDLED_LIBS=all uses every packed shared library, not only those the machine lacks.
set -eu
here=$(cd "$(dirname "$0")" && pwd)

export ANGLE_DEFAULT_PLATFORM=vulkan
# The Vulkan path needs no X display: make sure none is used.
unset DISPLAY WAYLAND_DISPLAY || true

# The Vulkan driver: the one given, else the loader's own search of the machine's ICD folders;
# NVIDIA containers sometimes keep theirs under /usr/local/nvidia, outside that search.
if [ -z "${VK_ICD_FILENAMES:-}" ] && [ -z "${VK_DRIVER_FILES:-}" ]; then
  icds=$(ls /etc/vulkan/icd.d/*.json /usr/share/vulkan/icd.d/*.json /usr/local/share/vulkan/icd.d/*.json "${XDG_DATA_HOME:-${HOME:-/nonexistent}/.local/share}"/vulkan/icd.d/*.json 2>/dev/null || true)
  if [ -z "$icds" ]; then
    for icd in /usr/local/nvidia/share/vulkan/icd.d/nvidia_icd.json /usr/local/nvidia/etc/vulkan/icd.d/nvidia_icd.json; do
      if [ -f "$icd" ]; then export VK_ICD_FILENAMES="$icd"; break; fi
    done
  fi
  echo "Vulkan driver: ${VK_ICD_FILENAMES:-the loader's search:} $(echo $icds)" >&2
else
  echo "Vulkan driver: ${VK_ICD_FILENAMES:-$VK_DRIVER_FILES}" >&2
fi

# Shared libraries headless-gl's ANGLE and Node need: the packed copies (lib/) of only those the
# machine lacks, so that its own (newer) libstdc++ stays in use where it has one.
have_lib() {
  for dir in /lib/x86_64-linux-gnu /usr/lib/x86_64-linux-gnu /lib64 /usr/lib64 /lib /usr/lib; do
    [ -e "$dir/$1" ] && return 0
  done
  { ldconfig -p 2>/dev/null || /sbin/ldconfig -p 2>/dev/null; } | grep -q "^[[:space:]]*$1 "
}
libs=$(mktemp -d "${TMPDIR:-/tmp}/penumbra-gpu-libs.XXXXXX")
trap 'rm -rf "$libs"' EXIT
for lib in "$here"/lib/*; do
  name=$(basename "$lib")
  if [ "${PENUMBRA_BUNDLED_LIBS:-}" = all ] || ! have_lib "$name"; then
    ln -s "$lib" "$libs/$name"
    echo "using the packed $name" >&2
  fi
done
export LD_LIBRARY_PATH="$libs${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"

mkdir -p "$here/results"
"$here/bin/node" "$here/bench/gpu.mjs" --out="$here/results/gpu-$(date -u +%Y%m%dT%H%M%SZ).json" "$@"
