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

# expect_answer_or_refusal WHAT FILE COMMAND...: the command (an option at an
# edge of its values) either answers, exit 0 with no NaN or infinity on
# stdout nor in FILE (a table it writes; "" for none), or refuses, exit 2
# with exactly one line on stderr and FILE not written. Anything else fails:
# another exit code (a crash, a sanitizer's report), more lines, a NaN with
# exit 0, or no end within 30 s (scaled by SHADERTWIN_TIME_SCALE). Sets `rc`
# and `refusal` (the line, when it refused).
# Lines of a table that start with '#' (its maker's record) are not read.
expect_answer_or_refusal() {
  local what="$1" file="$2"; shift 2
  [ -z "$file" ] || rm -rf "$file"
  set +e
  timeout $((30 * ${SHADERTWIN_TIME_SCALE:-1})) "$@" >"$work/stdout" 2>"$work/stderr"
  rc=$?
  set -e
  local err
  mapfile -t err <"$work/stderr"
  refusal=""
  if [ "$rc" -eq 2 ]; then
    refusal="${err[0]:-}"
    [ "${#err[@]}" -eq 1 ] || fail "$what: exit 2 with ${#err[@]} lines on stderr: $(head -c 2000 "$work/stderr")"
    [ -z "$file" ] || [ ! -e "$file" ] || fail "$what: refused, yet wrote $file"
    return 0
  fi
  [ "$rc" -eq 0 ] || fail "$what: exit $rc ($(head -c 2000 "$work/stderr"))"
  local re='(^|[^A-Za-z_])[-+]?(nan|inf|null)'
  ! grep -qiE "$re" "$work/stdout" || fail "$what: exit 0 with a value that is not finite: $(grep -iE -m1 "$re" "$work/stdout")"
  if [ -n "$file" ]; then
    [ -s "$file" ] || fail "$what: exit 0 without $file"
    grep -v '^#' "$file" >"$work/table" || true
    ! grep -qiE "$re" "$work/table" || fail "$what: $file holds a value that is not finite: $(grep -iE -m1 "$re" "$work/table")"
  fi
}
