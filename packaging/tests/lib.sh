# Shared by the package tests (sourced). A test that cannot run skips (exit 77, CTest's
# SKIP_RETURN_CODE) with its reason, except under CI=true, where it fails with that reason: a
# missing tool or network must not pass CI as a skip (the rule of tests/support/MissingData.h).
skip_or_fail() {
  if [ "${CI:-}" = true ]; then
    echo "FAIL: $* (CI=true makes that a failure, not a skip)" >&2
    exit 1
  fi
  echo "SKIP: $*"
  exit 77
}

fail() {
  echo "FAIL: $*" >&2
  exit 1
}

# Every command of "$@" on PATH, else skip naming the first missing one and its package.
need() {
  local entry
  for entry in "$@"; do
    command -v "${entry%%:*}" >/dev/null 2>&1 ||
      skip_or_fail "${entry%%:*} is not installed (apt-get install ${entry#*:})"
  done
}
