# shellcheck shell=bash
# Stage times for .ci/test and .ci/sanitize (sourced, not run). `stage NAME COMMAND...` runs COMMAND, which may be a
# shell function, and records how long it took; when the outermost script exits, passed or failed, it prints every
# stage's time as a table at the end of the log. A nested script (.ci/sanitize under .ci/test) adds its rows to the
# outer one's table through HEXC_CI_TIMES.
ci_owner=""
if [ -z "${HEXC_CI_TIMES:-}" ]; then
  HEXC_CI_TIMES=$(mktemp)
  export HEXC_CI_TIMES
  ci_owner=1
fi
stage_name=""
trap 'stage_exit' EXIT

# Under set -e a failing COMMAND ends the script at once, so the EXIT trap records the running stage as failed.
stage() {
  stage_name=$1 stage_started=$SECONDS
  shift
  echo "=== stage: $stage_name"
  "$@"
  stage_record passed
}

stage_record() {
  printf '%s\t%d\t%s\n' "$stage_name" $((SECONDS - stage_started)) "$1" >> "$HEXC_CI_TIMES"
  stage_name=""
}

stage_exit() {
  local status=$?
  [ -n "$stage_name" ] && stage_record "FAILED (exit $status)"
  [ -n "$ci_owner" ] || return 0
  echo
  echo "=== stage times (wall clock; $(nproc) cores, load average at the end $(cut -d' ' -f1-3 /proc/loadavg))"
  printf '%-52s %8s  %s\n' stage "m:ss" result
  while IFS=$'\t' read -r name seconds result; do
    printf '%-52s %5d:%02d  %s\n' "$name" $((seconds / 60)) $((seconds % 60)) "$result"
  done < "$HEXC_CI_TIMES"
  local total=$SECONDS
  printf '%-52s %5d:%02d\n' total $((total / 60)) $((total % 60))
  rm -f "$HEXC_CI_TIMES"
}
