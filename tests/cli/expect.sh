# Shared by the command-line test scripts (source it): expect NAME CODE PATTERN -- command...
# runs the command and checks its exit code and that its output matches the extended regular
# expression; absent NAME FILE checks that a file was not made. Counts in $passed and $failures.
# With expect_timeout=SECONDS set, a command that runs longer fails (a hang becomes a failure).
failures=0; passed=0

expect() {
  local name="$1" code="$2" pattern="$3"; shift 4
  local out rc
  out=$(${expect_timeout:+timeout "$expect_timeout"} "$@" 2>&1); rc=$?
  if [ "$rc" -ne "$code" ]; then
    echo "FAIL $name: exit code $rc, expected $code"; echo "$out" | tail -5; failures=$((failures+1)); return
  fi
  if ! grep -qE -- "$pattern" <<<"$out"; then
    echo "FAIL $name: output lacks /$pattern/"; echo "$out" | tail -5; failures=$((failures+1)); return
  fi
  echo "ok   $name"; passed=$((passed+1))
}

absent() {
  if [ -e "$2" ]; then echo "FAIL $1: $2 exists"; failures=$((failures+1)); else passed=$((passed+1)); fi
}
