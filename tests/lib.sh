# lib.sh: what the command-line and sdk test scripts share (sourced; the
# expect_* helpers write into `work`, the scratch folder the script, or
# sdk_setup, makes).

fail() { echo "FAIL: $*" >&2; exit 1; }

# python3 as tests/CMakeLists.txt resolved it (the interpreter, not a shim).
if [ -n "${SHADERTWIN_PYTHON:-}" ]; then python3() { "$SHADERTWIN_PYTHON" "$@"; }; fi

# expect_refused WHAT EXPECTED COMMAND...: the command, given --out on an
# empty folder, must exit 2 with one line on stderr that contains EXPECTED
# (anything when it is empty), and leave nothing in that folder.
expect_refused() {
  local what="$1" expected="$2"; shift 2
  local out="$work/bad-out"
  rm -rf "$out"; mkdir -p "$out"
  set +e
  "$@" --out "$out" >"$work/stdout" 2>"$work/stderr"
  local rc=$?
  set -e
  [ "$rc" -eq 2 ] || fail "$what: exit $rc, expected 2 ($(cat "$work/stderr"))"
  [ "$(wc -l <"$work/stderr")" -eq 1 ] || fail "$what: stderr is not one line: $(cat "$work/stderr")"
  [ -z "$expected" ] || grep -q -- "$expected" "$work/stderr" ||
    fail "$what: '$(cat "$work/stderr")' does not say '$expected'"
  [ -z "$(ls -A "$out")" ] || fail "$what: left files behind: $(ls -A "$out")"
  echo "ok   $what: $(cat "$work/stderr")"
}

# expect_refused_without_out WHAT EXPECTED COMMAND...: the same for a
# command that takes no --out (golden): exit 2, one line saying EXPECTED.
expect_refused_without_out() {
  local what="$1" expected="$2"; shift 2
  set +e
  "$@" >"$work/stdout" 2>"$work/stderr"
  local rc=$?
  set -e
  [ "$rc" -eq 2 ] || fail "$what: exit $rc, expected 2 ($(cat "$work/stderr"))"
  [ "$(wc -l <"$work/stderr")" -eq 1 ] || fail "$what: stderr is not one line: $(cat "$work/stderr")"
  grep -q -- "$expected" "$work/stderr" || fail "$what: '$(cat "$work/stderr")' does not say '$expected'"
  echo "ok   $what: $(cat "$work/stderr")"
}

# sdk_setup SOURCE_DIR BUILD_DIR CXX_COMPILER (the sdk tests' arguments):
# sets src, build and cxx; makes the scratch folder `work`, removed at exit;
# installs this build into `prefix` ($work/prefix), as a user's would be.
sdk_setup() {
  src="$1"
  build="$2"
  cxx="$3"
  work=$(mktemp -d)
  trap 'rm -rf "$work"' EXIT
  prefix="$work/prefix"
  cmake --install "$build" --prefix "$prefix" >"$work/install.log" || { cat "$work/install.log"; fail "install"; }
}
