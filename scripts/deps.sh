# Sourced by scripts/run and scripts/test: installs any missing Debian package, then configures and
# builds incrementally into build/. Everything the project needs comes from Debian's archive.
set -euo pipefail
RC_ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
RC_BUILD="${RC_BUILD:-$RC_ROOT/build}"
RC_PACKAGES=(build-essential cmake ninja-build pkg-config libsystemc-dev libglm-dev libgtest-dev
             libbenchmark-dev nlohmann-json3-dev libcli11-dev libpng-dev libembree-dev python3-matplotlib
             libassimp-dev libtomlplusplus-dev pybind11-dev python3-dev)

# Installed by scripts/test only: real models in many formats (tests/scenes/mesh_import_test.cpp),
# the cluster engines the sweep scripts drive (scripts/sweep-slurm, scripts/sweep-parallel; their tests
# in tests/scripts bring up a private single-node Slurm with its own munged), and clang with its
# sanitizer and libFuzzer run-times for the sanitizer build and the fuzzers (docs/reliability.md), and
# numpy for the independent reference solver (tests/reference/radiosity_reference.py).
RC_TEST_PACKAGES=(assimp-testmodels parallel slurm-wlm munge clang libclang-rt-14-dev python3-numpy
                  python3-pandas python3-nbclient python3-nbformat python3-ipykernel verilator yosys)

# Installs RC_PACKAGES and any packages given as arguments that are missing, saying which (on stderr).
rc_install_missing() {
  local missing=() wanted=("${RC_PACKAGES[@]}" "$@")
  for p in "${wanted[@]}"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
  done
  if [ ${#missing[@]} -eq 0 ]; then
    echo "== packages: all ${#wanted[@]} Debian packages present" >&2
    return 0
  fi
  echo "== packages: installing ${#missing[@]} of ${#wanted[@]} from Debian's archive: ${missing[*]}" >&2
  local sudo=""
  [ "$(id -u)" -ne 0 ] && sudo="sudo"
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" >&2
}

# rc_build [TARGET...]: configures build/ the first time, then builds the targets named (default:
# everything), saying how many steps are out of date before ninja counts them off ([k/n] lines).
# scripts/run builds only rc2000sim and the libraries it links; scripts/test builds the rest.
rc_build() {
  # CI (CI=true) builds with warnings as errors; a developer's build only shows them.
  local werror=OFF
  [ -n "${CI:-}" ] && werror=ON
  if [ ! -f "$RC_BUILD/build.ninja" ]; then
    echo "== configure: cmake -S $RC_ROOT -B $RC_BUILD (Ninja, Release)" >&2
    cmake -S "$RC_ROOT" -B "$RC_BUILD" -G Ninja -DCMAKE_BUILD_TYPE=Release -DRC_WERROR="$werror" >&2
  fi
  rc_announce_build "$RC_BUILD" "$@"
  cmake --build "$RC_BUILD" -j "$(nproc)" ${1:+--target "$@"} >&2
}

# rc_announce_build DIR [TARGET...]: one line saying what is about to be built and how many steps it
# takes from nothing (ninja -t commands). The steps out of date are counted off by ninja itself as
# [k/n] lines, also when piped. (A dry run, ninja -n, cannot count them: the folders' globs make it
# stop at "Re-running CMake".)
rc_announce_build() {
  local dir="$1"; shift
  local steps
  steps="$(ninja -C "$dir" -t commands "$@" 2>/dev/null | wc -l)"
  echo "== build: ${*:-every target} in $dir ($steps compile and link steps from nothing; ninja counts off those out of date)" >&2
}

# The sanitizer build (docs/reliability.md): clang, ASan + UBSan, libFuzzer's coverage and the fuzz
# harnesses of fuzz/, at -O1 with line tables (-gline-tables-only: every report's frames keep file
# and line, without the full debug information that made compiling and linking slower). NDEBUG as
# in the Release build: the pipeline's per-operation range asserts would double the test run
# (nlohmann::json's stay, CMakeLists.txt). No benchmarks: nothing runs them under the sanitizers
# (the plain build compiles them, so they cannot rot). No Verilated models: their C++ is generated
# by Verilator, and the co-simulation runs in the plain build (the RTL tests say SKIP here, with the
# reason). One build serves the tests and the fuzzers.
RC_SANITIZE_BUILD="${RC_SANITIZE_BUILD:-$RC_ROOT/build-sanitize}"

# Prints why the sanitizer build cannot be made here and succeeds, or fails (prints nothing) when it
# can: a one-line fuzzer with every sanitizer must compile and link.
rc_sanitize_unavailable() {
  if ! command -v clang++ >/dev/null 2>&1; then
    echo "clang++ is not installed (Debian package clang)"
    return 0
  fi
  local probe
  probe="$(mktemp -d)"
  echo 'extern "C" int LLVMFuzzerTestOneInput(const unsigned char*, unsigned long) { return 0; }' > "$probe/probe.cpp"
  if ! clang++ -fsanitize=fuzzer,address,undefined "$probe/probe.cpp" -o "$probe/probe" >"$probe/log" 2>&1; then
    echo "clang++ cannot link a sanitized libFuzzer program (Debian package libclang-rt-14-dev?): $(head -c 300 "$probe/log")"
    rm -rf "$probe"
    return 0
  fi
  rm -rf "$probe"
  return 1
}

rc_build_sanitize() {
  local werror=OFF
  [ -n "${CI:-}" ] && werror=ON
  if [ ! -f "$RC_SANITIZE_BUILD/build.ninja" ]; then
    echo "== configure: cmake -S $RC_ROOT -B $RC_SANITIZE_BUILD (Ninja, clang, ASan + UBSan, libFuzzer)" >&2
    CC=clang CXX=clang++ cmake -S "$RC_ROOT" -B "$RC_SANITIZE_BUILD" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
      -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -gline-tables-only -DNDEBUG" -DRC_SANITIZE=ON -DRC_FUZZ=ON \
      -DRC_BUILD_BENCH=OFF -DRC_RTL_VERILATE=OFF -DRC_WERROR="$werror" >&2
  fi
  rc_announce_build "$RC_SANITIZE_BUILD" "$@"
  cmake --build "$RC_SANITIZE_BUILD" -j "$(nproc)" ${1:+--target "$@"} >&2
}
