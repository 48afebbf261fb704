# Sanitizer run-time options for the sanitizer build (build-sanitize, -DRC_SANITIZE=ON): sourced by
# scripts/test, scripts/fuzz and fuzz/run_inputs.sh; source it yourself before running ctest or a
# test binary there by hand. docs/reliability.md, "Sanitizers", says why each option is set.
_rc_sanitizer_dir="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"

# SystemC runs every SC_THREAD on its own coroutine stack (QuickThreads) and tells ASan about each
# switch (__sanitizer_start_switch_fiber), but a fake stack for use-after-return detection cannot
# follow a thread that is switched away in the middle of a call: keep it off. Leaks are checked at
# exit, with SystemC's own (its kernel objects live until exit by design) suppressed in lsan.supp.
export ASAN_OPTIONS="detect_stack_use_after_return=0:detect_leaks=1:check_initialization_order=1:strict_init_order=1:detect_odr_violation=2:abort_on_error=0:halt_on_error=1:print_summary=1"
export LSAN_OPTIONS="suppressions=$_rc_sanitizer_dir/lsan.supp:print_suppressions=0"
# -fno-sanitize-recover=all already makes every UBSan report fatal; the stack says where.
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1:print_summary=1"
unset _rc_sanitizer_dir
