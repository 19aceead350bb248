# sanitizer-env.sh (sourced): how the sanitizer builds run. Any finding
# stops the process with a non-zero exit, so a test that meets one fails.
# Mesa's own leaks (llvmpipe keeps its LLVM JIT state, shader caches and
# thread pools until exit) are suppressed by tests/sanitizers/lsan.supp,
# which names only Mesa's and LLVM's libraries: nothing of ours.
_st_src="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
# intercept_tls_get_addr=0: the GL libraries are loaded with dlopen
# (gl/shared_library.h), so some of Mesa's thread-locals live in dynamic TLS
# blocks that ld.so takes from malloc. clang 14's runtime finds such a block's
# size by guessing glibc's layout from its address (with verbosity=2 it says
# "Can't guess glibc version" once per process here); when the address happens
# to fit the guess it reads a size from the block's neighbour, LeakSanitizer
# scans a range that is not there, and the process dies at exit with "Tracer
# caught signal 11" (google/sanitizers#1322; LLVM 17 asks the allocator
# instead). That failed cli.relief_failures once in CI (2026-12-03) with every
# image correct. Without the interceptor, dynamic TLS is not a root of the
# leak scan: only Mesa's and LLVM's modules have any, and what they allocate is
# suppressed anyway (tests/sanitizers/lsan.supp); shadertwin has no thread-locals.
export ASAN_OPTIONS="abort_on_error=0:halt_on_error=1:detect_leaks=1:strict_string_checks=1:check_initialization_order=1:detect_stack_use_after_return=1:intercept_tls_get_addr=0"
export LSAN_OPTIONS="suppressions=$_st_src/tests/sanitizers/lsan.supp:print_suppressions=0"
export UBSAN_OPTIONS="halt_on_error=1:print_stacktrace=1"
export TSAN_OPTIONS="halt_on_error=1:second_deadlock_stack=1"
# The tests' time limits (tests/cli_test.sh), for code that runs several times slower.
export SHADERTWIN_TIME_SCALE=4
# Tests that measure memory or set ulimit -v skip themselves (shadow memory).
export SHADERTWIN_SANITIZED=1
export ASAN_SYMBOLIZER_PATH="$(command -v llvm-symbolizer || true)"
unset _st_src
