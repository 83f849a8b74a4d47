#!/usr/bin/env bash
# Sets lightcone up on a Debian 12 machine and runs one job:
#   ./bootstrap.sh demo   install what is missing, build, render and encode the preview showcase
#   ./bootstrap.sh test   install what is missing, build, run every test (ctest)
#   ./bootstrap.sh build  install what is missing and build only
# Installs Debian packages with apt-get (as root, or through sudo) only when
# some are missing; builds in ./build (Release).
set -euo pipefail
cd "$(dirname "$0")"

job="${1:-demo}"
case "$job" in demo | test | build) ;; *)
  echo "usage: $0 [demo|test|build]" >&2
  exit 2
  ;;
esac

packages=(
  build-essential cmake pkg-config
  luajit libluajit-5.1-dev libgsl-dev libopenmpi-dev openmpi-bin
  libavcodec-dev libavformat-dev libavutil-dev libswscale-dev ffmpeg
  libopenimageio-dev openimageio-tools libcli11-dev libfmt-dev libgtest-dev libcairo2-dev
  libmicrohttpd-dev libjs-chart.js zlib1g-dev libdeflate-dev
)
# The end-to-end tests also read results back with tools a minimal Debian
# lacks: python3 (PNG chunks, MP4 atoms, JSON), python3-openimageio and
# python3-numpy (docs/layers.md's EXR reader, run as written) and procps
# (pgrep); the
# cluster test (tests/cluster/slurm.sh) runs a one-node Slurm of its own;
# the monitor's test (tests/e2e/monitor.sh) asks its API with curl and
# drives its page in a real browser, Debian's chromium, through Selenium.
if [ "$job" = test ]; then
  packages+=(python3 python3-openimageio python3-numpy procps slurmctld slurmd slurm-client munge curl chromium
             chromium-driver python3-selenium)
fi
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ "${#missing[@]}" -gt 0 ]; then
  echo "bootstrap: installing ${#missing[@]} Debian packages: ${missing[*]}"
  sudo=()
  if [ "$(id -u)" -ne 0 ]; then
    command -v sudo >/dev/null || { echo "bootstrap: need root or sudo to install: ${missing[*]}" >&2; exit 1; }
    sudo=(sudo)
  fi
  "${sudo[@]}" apt-get update -q
  DEBIAN_FRONTEND=noninteractive "${sudo[@]}" apt-get install -y -q --no-install-recommends "${missing[@]}"
fi

jobs=$(nproc)
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release
case "$job" in
  test)
    started=$SECONDS
    cmake --build build -j "$jobs"
    built=$SECONDS
    # Open MPI refuses root and needs an rsh agent even on one node; the
    # tests that launch mpirun set what they need themselves.  The suite's
    # wall time is the last line, pass or fail (the budget: 20 minutes).
    status=0
    ctest --test-dir build --output-on-failure -j "$jobs" | tee build/ctest.log || status=$?  # pipefail: ctest's
    summary=$(grep -E '^[0-9]+% tests passed' build/ctest.log | tail -n 1)
    echo "bootstrap: ${summary:-ctest gave no summary (exit $status)} in $((SECONDS - built)) s" \
      "(build $((built - started)) s, both $((SECONDS - started)) s)"
    exit "$status"
    ;;
  build)
    cmake --build build -j "$jobs"
    ;;
  demo)
    # The binary alone (the tests are not needed to make the film).
    cmake --build build -j "$jobs" --target lightcone
    ./build/pipeline/lightcone showcase --quality preview --progress 30
    echo "bootstrap: the film is out/showcase/preview/showcase.mp4; per sequence: out/showcase/preview/<shot>.mp4 and <shot>.sheet.png"
    ;;
esac
