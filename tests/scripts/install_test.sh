#!/usr/bin/env bash
# The installed package works for a user's own platform (issue 26; README, "Use it as a library"):
# `cmake --install` of this build into a temporary prefix, then examples/board-platform configured,
# built and run against that prefix twice, once through find_package(rc2000tlm) and once through
# pkg-config, in temporary build folders, with the installed configs (RC2000SIM_CONFIGS). Its three
# programs run under the example's own ctest: board_platform (the whole board, its own initiator),
# bank_bus (a PCI bus and a bank, no board) and board_timing_test (exact sc_time assertions with the
# installed timing test kit, one test per process); each checks its own data and times and exits
# non-zero on a mismatch. Also: the example fails (exit 2, naming the folder) when the configs are
# not where it is told; the installed rc2000sim, moved to another prefix, finds its own configs and
# plot scripts there (not the source tree's); and a library-only configure (tests, apps and
# benchmarks off) in a clean folder succeeds without looking for GTest, CLI11 or Google Benchmark. Prints "SKIP: <reason>" and exits 77 when
# a tool it needs is missing. About 80 s on 2 busy cores: three small programs built twice, a small sweep.
# usage: install_test.sh BUILD_DIR REPO_ROOT
set -euo pipefail
build="$1"
root="$2"
fail() { echo "FAIL: $*" >&2; exit 1; }
for tool in cmake pkg-config c++; do
  command -v "$tool" > /dev/null || { echo "SKIP: $tool not found"; exit 77; }
done
work="$(mktemp -d "${TMPDIR:-/tmp}/install-test.XXXXXX")"
trap 'rm -rf "$work"' EXIT
export SYSTEMC_DISABLE_COPYRIGHT_MESSAGE=1
prefix="$work/prefix"
configs="$prefix/share/rc2000tlm/configs"

cmake --install "$build" --prefix "$prefix" > "$work/install.log" || { cat "$work/install.log" >&2; fail "cmake --install"; }
for f in include/rc2000tlm/board/rc2000.h include/rc2000tlm/host_sw/radiosity/radiosity.h lib/librc_board.a \
         lib/cmake/rc2000tlm/rc2000tlmConfig.cmake lib/cmake/rc2000tlm/rc2000tlmConfigVersion.cmake \
         lib/pkgconfig/rc2000tlm.pc share/rc2000tlm/configs/devices/xc2v6000.json \
         include/rc2000tlm/testkit/scripted_host.h lib/librc_testkit.a lib/librc_testkit_main.a lib/librc_testkit_tlm.a \
         lib/cmake/rc2000tlm/rc2000tlmTestkitTargets.cmake lib/pkgconfig/rc2000tlm-testkit.pc; do
  [ -f "$prefix/$f" ] || fail "not installed: $f"
done
# No header is left out: every header of a library folder is in the installed set.
for d in io profiles scenes pipeline tlm board host_sw/radiosity host_sw/visibility host_sw/driver host_sw/energy \
         host_sw/platform host_sw/outputs host_sw/studies testkit testkit/tlm; do
  for h in "$root/$d"/*.h; do
    [ -f "$prefix/include/rc2000tlm/$d/$(basename "$h")" ] || fail "header not installed: $d/$(basename "$h")"
  done
done

# The example is built as this build's libraries were: the same compiler, and in the sanitizer build
# (RC_SANITIZE: scripts/test) the sanitizers, whose run-times the program must link (they also hold
# the coverage callbacks of the libraries RC_FUZZ instruments, as for the project's own tests).
cached() { sed -n "s/^$1:[A-Z]*=//p" "$build/CMakeCache.txt"; }
example_args=(-DCMAKE_CXX_COMPILER="$(cached CMAKE_CXX_COMPILER)")
flags="-Wall -Wextra -Wshadow -Werror"  # the example is held to the project's warnings
link_flags=""
if [ "$(cached RC_SANITIZE)" = ON ]; then
  flags="$flags -fsanitize=address,undefined -fno-sanitize-recover=all"
  link_flags="-fsanitize=address,undefined -fno-sanitize-recover=all"
fi
example_args+=(-DCMAKE_CXX_FLAGS="$flags" -DCMAKE_EXE_LINKER_FLAGS="$link_flags")

# build_and_run NAME CMAKE-ARGS...: configures, builds and runs the example in $work/NAME.
build_and_run() {
  local name="$1"; shift
  cmake -S "$root/examples/board-platform" -B "$work/$name" -DCMAKE_BUILD_TYPE=Release "${example_args[@]}" "$@" \
    > "$work/$name.log" 2>&1 || { cat "$work/$name.log" >&2; fail "$name: configure"; }
  cmake --build "$work/$name" >> "$work/$name.log" 2>&1 || { cat "$work/$name.log" >&2; fail "$name: build"; }
  RC2000SIM_CONFIGS="$configs" "$work/$name/board_platform" > "$work/$name.out" 2>&1 ||
    { cat "$work/$name.out" >&2; fail "$name: the example failed its checks"; }
  grep -q "blocked 1010" "$work/$name.out" || { cat "$work/$name.out" >&2; fail "$name: no result line"; }
  echo "$name: $(grep blocked "$work/$name.out")"
  # Every program of the example, the timing tests one per process (at least two of them).
  RC2000SIM_CONFIGS="$configs" ctest --test-dir "$work/$name" --output-on-failure > "$work/$name.ctest" 2>&1 ||
    { cat "$work/$name.ctest" >&2; fail "$name: the example's ctest"; }
  grep -q "100% tests passed, 0 tests failed out of [4-9]" "$work/$name.ctest" ||
    { cat "$work/$name.ctest" >&2; fail "$name: fewer tests than the example's programs"; }
  echo "$name: $(grep "tests passed" "$work/$name.ctest")"
}
build_and_run find-package -DCMAKE_PREFIX_PATH="$prefix"
PKG_CONFIG_PATH="$prefix/lib/pkgconfig" build_and_run pkg-config -DUSE_PKG_CONFIG=ON
# Both link the same libraries and simulate the same platform: the same output.
cmp -s "$work/find-package.out" "$work/pkg-config.out" || fail "find_package and pkg-config builds differ"

# Configs not where they are said to be: an error naming the folder, not a silent success.
rc=0
RC2000SIM_CONFIGS="$work/no-configs" "$work/find-package/board_platform" > "$work/missing.out" 2>&1 || rc=$?
[ "$rc" -eq 2 ] || { cat "$work/missing.out" >&2; fail "missing configs: exit $rc, not 2"; }
grep -qF "$work/no-configs/devices/xc2v6000.json" "$work/missing.out" || { cat "$work/missing.out" >&2; fail "missing configs: path not named"; }

# The installed rc2000sim uses its own prefix, wherever it was moved: its configs (a profile removed
# from a moved copy is named there) and its plot scripts (a sweep draws its plots). No
# RC2000SIM_CONFIGS: the source tree, still present, must not be what it reads.
if [ -x "$prefix/bin/rc2000sim" ]; then
  "$prefix/bin/rc2000sim" --help > /dev/null || fail "installed rc2000sim --help"
  moved="$work/moved-prefix"
  cp -a "$prefix" "$moved"
  (
    unset RC2000SIM_CONFIGS
    "$moved/bin/rc2000sim" sweep --faces 70 --face-levels 0 --patch-levels 1 --steps 5 --devices xc2v6000 \
      --lanes 1,2 --banks 6 --quiet --out "$work/installed-sweep" > "$work/installed-sweep.out" 2>&1 ||
      { cat "$work/installed-sweep.out" >&2; fail "installed rc2000sim sweep"; }
    ls "$work/installed-sweep"/*.png > /dev/null 2>&1 || { cat "$work/installed-sweep.out" >&2; fail "installed rc2000sim drew no plots"; }
    rm "$moved/share/rc2000tlm/configs/devices/xc2v6000.json"
    if "$moved/bin/rc2000sim" run --impl board --steps 1 --patch-levels 0 --quiet --out "$work/no-profile" \
         > "$work/no-profile.out" 2>&1; then
      fail "the moved rc2000sim ran without its prefix's xc2v6000 profile (it read another folder)"
    fi
    grep -qF "$moved/share/rc2000tlm/configs/devices/xc2v6000.json" "$work/no-profile.out" ||
      { cat "$work/no-profile.out" >&2; fail "the moved rc2000sim did not look in its own prefix"; }
  )
  echo "installed rc2000sim: its own prefix's configs and plot scripts"
fi

# Library-only configure: only what the libraries use (README lists it).
cmake -S "$root" -B "$work/library-only" -DRC_BUILD_TESTS=OFF -DRC_BUILD_APPS=OFF -DRC_BUILD_BENCH=OFF \
  > "$work/library-only.log" 2>&1 || { cat "$work/library-only.log" >&2; fail "library-only configure"; }
for pkg in GTest CLI11 benchmark pybind11; do
  ! grep -q "^${pkg}_DIR:" "$work/library-only/CMakeCache.txt" || fail "library-only configure looked for $pkg"
done
echo "PASS: installed package, examples and timing tests via find_package and pkg-config, installed rc2000sim, library-only configure"
