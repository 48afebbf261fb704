#!/usr/bin/env bash
# The installed package works for a user's own platform (issue 26; README, "Use it as a library"):
# `cmake --install` of this build into a temporary prefix, then examples/board-platform configured,
# built and run against that prefix twice, once through find_package(rc2000tlm) and once through
# pkg-config, in temporary build folders, with the installed configs (RC2000SIM_CONFIGS). The example
# checks its own result bits and times and exits non-zero on a mismatch. Also: the example fails
# (exit 2, naming the folder) when the configs are not where it is told; the installed rc2000sim
# runs; and a library-only configure (tests, apps and benchmarks off) in a clean folder succeeds
# without looking for GTest, CLI11 or Google Benchmark. Prints "SKIP: <reason>" and exits 77 when
# a tool it needs is missing. Seconds: the example is one source.
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
         lib/pkgconfig/rc2000tlm.pc share/rc2000tlm/configs/devices/xc2v6000.json; do
  [ -f "$prefix/$f" ] || fail "not installed: $f"
done
# No header is left out: every header of a library folder is in the installed set.
for d in io scenes pipeline tlm board host_sw/radiosity host_sw/visibility host_sw/driver host_sw/energy \
         host_sw/platform host_sw/studies; do
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

if [ -x "$prefix/bin/rc2000sim" ]; then
  "$prefix/bin/rc2000sim" --help > /dev/null || fail "installed rc2000sim --help"
fi

# Library-only configure: only what the libraries use (README lists it).
cmake -S "$root" -B "$work/library-only" -DRC_BUILD_TESTS=OFF -DRC_BUILD_APPS=OFF -DRC_BUILD_BENCH=OFF \
  > "$work/library-only.log" 2>&1 || { cat "$work/library-only.log" >&2; fail "library-only configure"; }
for pkg in GTest CLI11 benchmark; do
  ! grep -q "^${pkg}_DIR:" "$work/library-only/CMakeCache.txt" || fail "library-only configure looked for $pkg"
done
echo "PASS: installed package, example via find_package and pkg-config, library-only configure"
