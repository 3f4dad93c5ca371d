#!/usr/bin/env bash
# Installs cnlmc from nothing on Debian/Ubuntu: system libraries (Mesa llvmpipe for OpenGL on
# the CPU, glslang, neovim for the editor test) when run as root, then a virtual environment.
set -euo pipefail
cd "$(dirname "$0")/.."
export DEBIAN_FRONTEND=noninteractive
if command -v apt-get >/dev/null 2>&1 && [ "$(id -u)" = 0 ]; then
  apt-get update -qq
  apt-get install -y -qq --no-install-recommends \
    libegl1 libgl1 libegl-mesa0 libgl1-mesa-dri libatomic1 glslang-tools spirv-tools neovim libllvm19 \
    xvfb python3-tk libtk8.6 libtcl8.6 >/dev/null
  # speech (cnlmc listen, issue #18): PortAudio for the microphone; espeak-ng and sox make the test utterances
  apt-get install -y -qq --no-install-recommends libportaudio2 espeak-ng sox >/dev/null
  # the studio's browser tests (cnlmc serve, #17): Debian's Chromium draws WebGL2 on the CPU (SwiftShader);
  # Playwright drives it (no browser download)
  apt-get install -y -qq --no-install-recommends chromium >/dev/null
fi
python3 -m venv .venv
.venv/bin/python -m pip install -q -U pip
.venv/bin/python -m pip install -q -e '.[all]'
# Node tools the tests run (tools/js/package-lock.json): the Khronos glTF-Validator.
if ! command -v npm >/dev/null 2>&1 && command -v apt-get >/dev/null 2>&1 && [ "$(id -u)" = 0 ]; then
  apt-get install -y -qq --no-install-recommends nodejs npm >/dev/null
fi
if command -v npm >/dev/null 2>&1; then
  (cd tools/js && npm ci --no-audit --no-fund --loglevel=error)
fi
