# Sourced by scripts/run and scripts/test: installs any missing Debian package, then configures and
# builds incrementally into build/. Everything the project needs comes from Debian's archive.
set -euo pipefail
RC_ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
RC_BUILD="${RC_BUILD:-$RC_ROOT/build}"
RC_PACKAGES=(build-essential cmake ninja-build pkg-config libsystemc-dev libglm-dev libgtest-dev
             libbenchmark-dev nlohmann-json3-dev libcli11-dev libpng-dev libembree-dev python3-matplotlib
             libassimp-dev libtomlplusplus-dev)

# Installed by scripts/test only: real models in many formats (tests/scenes/mesh_import_test.cpp), and
# the cluster engines the sweep scripts drive (scripts/sweep-slurm, scripts/sweep-parallel; their tests
# in tests/scripts bring up a private single-node Slurm with its own munged).
RC_TEST_PACKAGES=(assimp-testmodels parallel slurm-wlm munge)

# Installs RC_PACKAGES and any packages given as arguments that are missing.
rc_install_missing() {
  local missing=()
  for p in "${RC_PACKAGES[@]}" "$@"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
  done
  [ ${#missing[@]} -eq 0 ] && return 0
  echo "installing: ${missing[*]}" >&2
  local sudo=""
  [ "$(id -u)" -ne 0 ] && sudo="sudo"
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" >&2
}

rc_build() {
  # CI (CI=true) builds with warnings as errors; a developer's build only shows them.
  local werror=OFF
  [ -n "${CI:-}" ] && werror=ON
  if [ ! -f "$RC_BUILD/build.ninja" ]; then
    cmake -S "$RC_ROOT" -B "$RC_BUILD" -G Ninja -DCMAKE_BUILD_TYPE=Release -DRC_WERROR="$werror" >&2
  fi
  cmake --build "$RC_BUILD" -j "$(nproc)" >&2
}
