#!/usr/bin/env bash
# Packs the bench's GPU mode (bench/gpu.ts: new and baseline renderer on Vulkan through headless-gl)
# into one tarball that runs on a bare Linux x86-64 machine with a GPU and a Vulkan driver, with no
# repository, npm or X display there:
#   bin/node                  this machine's Node (stripped when `strip` is here)
#   bench/gpu.mjs             the GPU mode, both renderers bundled in (the baseline built from --baseline)
#   node_modules/gl           headless-gl's JavaScript and native build, libvulkan.so.1 beside libGLESv2.so
#   node_modules/{bindings,file-uri-to-path,bit-twiddle}   its runtime dependencies
#   lib/                      the shared libraries ANGLE, headless-gl and Node link (not glibc's): run.sh
#                             uses a copy only where the machine lacks the library
#   run.sh, BUILD-INFO        scripts/gpu-bench-run.sh; what was packed
# Usage: scripts/pack-gpu-bench.sh [--baseline=<ref> | --no-baseline] [--out=<file.tar.gz>]
# (npm run pack:gpu-bench -- …). Default out: bench/.build/penumbra-gpu-bench.tar.gz.
# On the GPU machine: tar xzf penumbra-gpu-bench.tar.gz && penumbra-gpu-bench/run.sh
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"

out="$root/bench/.build/penumbra-gpu-bench.tar.gz"
build_args=()
for arg in "$@"; do
  case "$arg" in
    --out=*) out=$(realpath -m "${arg#--out=}") ;;
    --baseline=*|--no-baseline) build_args+=("$arg") ;;
    *) echo "pack-gpu-bench: unknown argument $arg" >&2; exit 2 ;;
  esac
done
[ "$(uname -m)" = x86_64 ] || { echo "pack-gpu-bench: packs this machine's x86-64 binaries; run it on x86-64" >&2; exit 1; }

release=node_modules/gl/build/Release
[ -f "$release/webgl.node" ] || { echo "pack-gpu-bench: no headless-gl build at $release: run npm ci first" >&2; exit 1; }

# Everything but the tarball is made in bench/.build (ignored).
node bench/run.mjs --gpu --build-only "${build_args[@]}"

stage_root="$root/bench/.build/gpu-pack"
stage="$stage_root/penumbra-gpu-bench"
rm -rf "$stage_root"
mkdir -p "$stage"/{bin,bench,lib,node_modules/gl/build/Release}

cp bench/.build/gpu.mjs "$stage/bench/"
cp scripts/gpu-bench-run.sh "$stage/run.sh"
chmod +x "$stage/run.sh"

node_bin=$(readlink -f "$(command -v node)")
cp "$node_bin" "$stage/bin/node"
if command -v strip >/dev/null; then strip "$stage/bin/node"; fi

# headless-gl: its JavaScript, package.json (read for its version) and native build.
for file in package.json index.js LICENSES LICENSE README.md; do
  if [ -e "node_modules/gl/$file" ]; then cp -r "node_modules/gl/$file" "$stage/node_modules/gl/"; fi
done
mkdir -p "$stage/node_modules/gl/src"
cp -r node_modules/gl/src/javascript "$stage/node_modules/gl/src/"
cp "$release"/webgl.node "$release"/libEGL.so "$release"/libGLESv2.so "$stage/node_modules/gl/build/Release/"
for dep in bindings file-uri-to-path bit-twiddle; do
  cp -r "node_modules/$dep" "$stage/node_modules/"
done

# The Vulkan loader beside libGLESv2.so: ANGLE loads it from its own folder only.
vulkan=""
for candidate in "$release/libvulkan.so.1" /usr/lib/x86_64-linux-gnu/libvulkan.so.1 /usr/lib64/libvulkan.so.1 /lib/x86_64-linux-gnu/libvulkan.so.1; do
  if [ -e "$candidate" ]; then vulkan=$candidate; break; fi
done
[ -n "$vulkan" ] || { echo "pack-gpu-bench: no libvulkan.so.1: install the Vulkan loader (as root: apt-get install -y libvulkan1)" >&2; exit 1; }
cp -L "$vulkan" "$stage/node_modules/gl/build/Release/libvulkan.so.1"

# The shared libraries they link, but glibc's own (every Linux has those, and they must match).
for binary in "$stage/bin/node" "$stage"/node_modules/gl/build/Release/*; do
  ldd "$binary" | awk '$2 == "=>" && $3 ~ /^\// { print $1, $3 }'
done | sort -u | while read -r name path; do
  case "$name" in
    libc.so.*|libm.so.*|libdl.so.*|libpthread.so.*|librt.so.*|ld-linux*|libresolv.so.*) ;;
    *) cp -L "$path" "$stage/lib/$name" ;;
  esac
done

commit=$(git rev-parse HEAD)
dirty=$(git status --porcelain -- src shaders bench | head -1)
{
  echo "penumbra-gl GPU bench, packed $(date -u +%Y-%m-%dT%H:%M:%SZ)"
  echo "working tree: $commit${dirty:+ (with uncommitted changes in src/, shaders/ or bench/)}"
  echo "baseline: $(node -p "const b = require('./bench/.build/build-info.json').baseline; b ? b.ref + ' = ' + b.commit : 'none'")"
  echo "node: $("$stage/bin/node" --version); headless-gl: $(node -p "require('./node_modules/gl/package.json').version")"
  echo "libvulkan.so.1 from $vulkan ($(readlink -f "$vulkan"))"
  echo "lib/: $(ls "$stage/lib" | tr '\n' ' ')"
} > "$stage/BUILD-INFO"

mkdir -p "$(dirname "$out")"
tar -C "$stage_root" -czf "$out" penumbra-gpu-bench
echo "packed $out ($(du -h "$out" | cut -f1)):" >&2
du -sh "$stage"/* "$stage"/node_modules/gl/build/Release/* | sort -h >&2
echo "on the GPU machine: tar xzf $(basename "$out") && penumbra-gpu-bench/run.sh [--scenes=S1,S3 --frames=50]" >&2
