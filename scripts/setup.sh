#!/usr/bin/env bash
# Installs what a fresh Debian machine lacks to build mowmill: cmake (HiGHS is compiled from
# source by highs-sys) and libclang (bindgen). Installs only what is missing; idempotent.
set -euo pipefail

need=()
command -v cmake >/dev/null 2>&1 || need+=(cmake)
if ! ldconfig -p 2>/dev/null | grep -q 'libclang[-.0-9]*\.so' \
   && ! ls /usr/lib/llvm-*/lib/libclang*.so* >/dev/null 2>&1; then
  need+=(libclang)
fi
command -v cargo >/dev/null 2>&1 || { echo "setup: cargo (Rust toolchain) is required: https://rustup.rs" >&2; exit 2; }

if ((${#need[@]})); then
  sudo=""
  [ "$(id -u)" = 0 ] || sudo="sudo"
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
fi
echo "setup: build prerequisites present" >&2
