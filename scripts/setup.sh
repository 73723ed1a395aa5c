#!/usr/bin/env bash
# Installs what a fresh Debian machine lacks to build mowmill: cmake (HiGHS is compiled from
# source by highs-sys) and libclang (bindgen). Installs only what is missing; idempotent.
#
# libclang is detected as bindgen (clang-sys) loads it: a file named libclang.so,
# libclang-*.so, libclang.so.* or libclang-*.so.* in the linker cache or an LLVM lib folder.
# libclang-cpp.so.* is a different library (Clang's C++ API) and does not count.
#
# Testing hooks: SETUP_LIB_DIRS (space-separated folders searched instead of the linker cache
# and /usr/lib/llvm-*/lib) and SETUP_DRY_RUN=1 (print what would be installed, install
# nothing) let scripts/test-setup.sh check the detection against a fake library tree.
set -euo pipefail

# True when $1 is a file name bindgen would load as libclang.
is_libclang() {
  case "$1" in
    libclang-cpp*) return 1 ;;
    libclang.so | libclang-*.so | libclang.so.* | libclang-*.so.*) return 0 ;;
    *) return 1 ;;
  esac
}

# Prints the first libclang found, or nothing.
find_libclang() {
  local dirs f
  if [ -n "${SETUP_LIB_DIRS:-}" ]; then
    dirs="$SETUP_LIB_DIRS"
  else
    # The linker cache first, then LLVM's own folders (not always in the cache).
    while read -r f; do
      if is_libclang "$f"; then echo "$f (linker cache)"; return; fi
    done < <(ldconfig -p 2>/dev/null | awk '{print $1}')
    dirs=$(ls -d /usr/lib/llvm-*/lib /usr/lib/x86_64-linux-gnu /usr/lib/aarch64-linux-gnu 2>/dev/null || true)
  fi
  for d in $dirs; do
    for f in "$d"/libclang*; do
      [ -e "$f" ] || continue
      if is_libclang "$(basename "$f")"; then echo "$f"; return; fi
    done
  done
}

need=()
if command -v cmake >/dev/null 2>&1 && [ -z "${SETUP_LIB_DIRS:-}" ]; then
  echo "setup: found cmake: $(command -v cmake)" >&2
else
  [ -n "${SETUP_LIB_DIRS:-}" ] || need+=(cmake)
fi
found=$(find_libclang)
if [ -n "$found" ]; then
  echo "setup: found libclang: $found" >&2
else
  echo "setup: no libclang (bindgen needs libclang.so or libclang-*.so*; libclang-cpp is not it)" >&2
  need+=(libclang)
fi
command -v cargo >/dev/null 2>&1 || { echo "setup: cargo (Rust toolchain) is required: https://rustup.rs" >&2; exit 2; }

if ((${#need[@]})); then
  sudo=""
  [ "$(id -u)" = 0 ] || sudo="sudo"
  if [ "${SETUP_DRY_RUN:-0}" = 1 ]; then
    echo "setup: would install ${need[*]}"
    exit 0
  fi
  echo "setup: installing ${need[*]}" >&2
  $sudo apt-get update -qq
  pkgs=()
  for p in "${need[@]}"; do
    if [ "$p" = libclang ]; then
      # libclang1-14 on Debian 12; libclang-dev elsewhere.
      if apt-cache show libclang1-14 >/dev/null 2>&1; then pkgs+=(libclang1-14); else pkgs+=(libclang-dev); fi
    else
      pkgs+=("$p")
    fi
  done
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${pkgs[@]}"
  echo "setup: installed ${pkgs[*]}" >&2
elif [ "${SETUP_DRY_RUN:-0}" = 1 ]; then
  echo "setup: would install nothing"
  exit 0
fi
echo "setup: build prerequisites present" >&2
