# quiet.sh (sourced): run_logged NAME COMMAND... runs a step of the main job
# with its output in $ST_LOG_DIR/NAME.log and one line on stderr saying what
# it did; when the step fails, the log's last lines and its path. Without
# ST_LOG_DIR (./test.sh, CI) the output goes to stderr as it comes.
run_logged() {
  local name="$1"; shift
  if [ -z "${ST_LOG_DIR:-}" ]; then
    "$@" >&2
    return
  fi
  mkdir -p "$ST_LOG_DIR"
  local log="$ST_LOG_DIR/$name.log" start=$SECONDS
  if "$@" >"$log" 2>&1; then
    echo "$name: done in $(( SECONDS - start )) s (log: $log)" >&2
  else
    local rc=$?
    tail -n 30 "$log" >&2
    echo "$name: FAILED (exit $rc) after $(( SECONDS - start )) s; the whole log: $log" >&2
    return "$rc"
  fi
}
