# lib.sh: what the command-line test scripts share (sourced, after they set
# `work` to their scratch folder).

fail() { echo "FAIL: $*" >&2; exit 1; }

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
