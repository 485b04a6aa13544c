#!/usr/bin/env bash
# Installs what softtune needs on a Debian 12 machine: the Debian packages (apt-get, as root) and the
# page's npm packages (npm ci). Safe to run again: it only installs what is missing.
set -euo pipefail
cd "$(dirname "$0")/.."

# One list for the whole project; each entry says which part needs it.
packages=(
  cmake g++ make pkg-config          # build
  libeigen3-dev                      # core math
  libfmt-dev                         # core and up: messages formatted whole (warnings, field rules)
  nlohmann-json3-dev                 # server: JSON codec
  libgtest-dev libbenchmark-dev      # tests, benchmarks
  libbox2d-dev                       # scene/ and engines/box2d_v2_4: Box2D 2.4
  libode-dev                         # engines/ode: ODE 0.16 conformance
  libmujoco-dev                      # engines/mujoco, tests/engines/mujoco: MuJoCo 2.2.2
  libosmesa6-dev libpng-dev          # render: off-screen frames, PNG
  libcpp-httplib-dev                 # server: HTTP
  libssl-dev                         # render: SHA-256 of preview names (OpenSSL libcrypto, EVP)
  chromium                           # browser tests
  wrk                                # bench: HTTP load
  clang-14 libclang-rt-14-dev python3  # security: libFuzzer harnesses, attack suite
  valgrind                           # tests: uninitialised reads in the Box2D tests (memcheck)
  libbullet-dev                      # engines/bullet, tests/engines/bullet: Bullet 3.24
  libwebp-dev libgif-dev             # render: preview clips (WebPAnimEncoder, giflib)
  libfreetype-dev libfontconfig-dev fonts-dejavu-core  # render: anti-aliased preview text (DejaVu Sans)
  libxml2-dev                        # tests/app: the check's JUnit XML validated against its XSD, parsed back
  libchipmunk-dev                    # engines/chipmunk, tests/engines/chipmunk: Chipmunk 7.0.3
  godot3-server                      # tests/engines/godot, tests/web: Godot 3.2.3 headless (2-D and 3-D physics, GDScript)
  dpkg-dev                           # packaging: dpkg-shlibdeps fills the Debian package's Depends (cpack)
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
# Node.js and npm (the web page's packages, browser tests): the base image may ship them outside Debian's
# packages (nodesource bundles npm), where Debian's npm package conflicts; install Debian's only if absent.
command -v node >/dev/null 2>&1 || missing+=(nodejs)
command -v npm >/dev/null 2>&1 || missing+=(npm)

if ((${#missing[@]})); then
  if [[ $(id -u) -eq 0 ]]; then
    echo "setup: installing ${missing[*]}"
    export DEBIAN_FRONTEND=noninteractive
    apt-get update -qq
    apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
  else
    echo "setup: missing Debian packages: ${missing[*]}" >&2
    echo "setup: run as root, or: sudo apt-get install ${missing[*]}" >&2
    exit 1
  fi
fi

if [[ -f package.json ]] && { [[ ! -d node_modules ]] || [[ package-lock.json -nt node_modules ]]; }; then
  echo "setup: npm ci"
  npm ci --no-audit --no-fund --loglevel=error
  touch node_modules
fi
