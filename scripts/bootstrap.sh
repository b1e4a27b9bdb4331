#!/usr/bin/env bash
# Installs the Debian packages that building and testing libubii needs.
# Idempotent: packages already present are not fetched again, so CI may call it on every run.
set -euo pipefail

packages=(
  build-essential cmake pkg-config git
  nanopb libnanopb-dev protobuf-compiler python3-protobuf libprotobuf-dev
  libzmq3-dev libwebsockets-dev
  googletest libgtest-dev libgmock-dev libbenchmark-dev
  clang libclang-rt-14-dev clang-format
  libcli11-dev nlohmann-json3-dev
  iproute2 util-linux
  gcc-arm-linux-gnueabihf libc6-dev-armhf-cross qemu-user
  libtesseract-dev tesseract-ocr-eng tesseract-ocr libopencv-dev python3-onnx fonts-dejavu-core
)

missing=()
for pkg in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$pkg" 2>/dev/null | grep -q "install ok installed" || missing+=("$pkg")
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "bootstrap: all ${#packages[@]} packages present"
  exit 0
fi

sudo_cmd=()
[ "$(id -u)" -eq 0 ] || sudo_cmd=(sudo)
echo "bootstrap: installing ${missing[*]}"
"${sudo_cmd[@]}" apt-get update -qq
DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
