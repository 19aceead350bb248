# sanitizer-env.sh (sourced): how the sanitizer builds run. Any finding
# stops the process with a non-zero exit, so a test that meets one fails.
# Mesa's own leaks (llvmpipe keeps its LLVM JIT state, shader caches and
# thread pools until exit) are suppressed by tests/sanitizers/lsan.supp,
# which names only Mesa's and LLVM's libraries: nothing of ours.
_st_src="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
export ASAN_OPTIONS="abort_on_error=0:halt_on_error=1:detect_leaks=1:strict_string_checks=1:check_initialization_order=1:detect_stack_use_after_return=1"
export LSAN_OPTIONS="suppressions=$_st_src/tests/sanitizers/lsan.supp:print_suppressions=0"
export UBSAN_OPTIONS="halt_on_error=1:print_stacktrace=1"
export TSAN_OPTIONS="halt_on_error=1:second_deadlock_stack=1"
# The tests' time limits (tests/cli_test.sh), for code that runs several times slower.
export SHADERTWIN_TIME_SCALE=4
# Tests that measure memory or set ulimit -v skip themselves (shadow memory).
export SHADERTWIN_SANITIZED=1
export ASAN_SYMBOLIZER_PATH="$(command -v llvm-symbolizer || true)"
unset _st_src
