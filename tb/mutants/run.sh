#!/usr/bin/env bash
# Mutation check of the test suite: each mutant of tb/mutants/list.txt (one
# planted bug) must be KILLED, i.e. make some test of its binaries fail.
#
#   tb/mutants/run.sh [--rev REV] [NAME...]
#
# The tree (the working tree's files, or commit REV with --rev, e.g. to show
# which mutants an older suite let through) is copied once to
# $BUILD/mutants/src and built in $BUILD/mutants/build (ccache makes the
# first build cheap, later ones are incremental). The unmutated suite must
# pass first. Then for each mutant: apply its sed expression to its file,
# rebuild only its test binaries, run them (gtest, stopping at the first
# failure), report KILLED (and the test that failed) or SURVIVED, restore
# the file. Exit status 1 if any mutant survived or did not apply (its
# expression changed nothing), 2 if the unmutated suite fails or a NAME is
# not in the list.
set -uo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
list="$root/tb/mutants/list.txt"
work="$root/${BUILD:-build}/mutants"
jobs=${JOBS:-2}
rev=""
if [ "${1:-}" = "--rev" ]; then rev=$2; shift 2; fi
only=" $* "

copy_tree() {  # the sources into $work/src, node_modules (asm80) linked
  rm -rf "$work/src" && mkdir -p "$work/src"
  if [ -n "$rev" ]; then
    git -C "$root" archive "$rev" | tar -x -C "$work/src"
  else
    (cd "$root" && git ls-files -z --cached --others --exclude-standard | tar --null -T - -cf -) | tar -x -C "$work/src"
  fi
  ln -s "$root/sw8085/node_modules" "$work/src/sw8085/node_modules"
}

build() {  # build BINARY... -> status
  local targets=()
  for b in "$@"; do targets+=("$(basename "$b")"); done
  cmake --build "$work/build" -j"$jobs" --target "${targets[@]}" > "$work/build.log" 2>&1
}

run_tests() {  # run_tests BINARY... -> 0 all passed; else prints the first failure
  for b in "$@"; do
    local log="$work/test.log"
    if ! (cd "$work/build" && timeout 600 "./$b" --gtest_fail_fast > "$log" 2>&1); then
      local failed
      failed=$(grep -m1 -o '^\[  FAILED  \] [A-Za-z0-9_./]*' "$log" | sed 's/^\[  FAILED  \] //')
      echo "${failed:-$(basename "$b") (exit without a gtest failure: timeout or crash)}"
      return 1
    fi
  done
  return 0
}

mutants() {  # the list's lines: name|file|sed|binaries, trimmed
  sed -e '/^#/d' -e '/^[[:space:]]*$/d' "$list" | sed -e 's/[[:space:]]*|[[:space:]]*/|/g'
}

# A name given that the list does not have is an error, not an empty run.
for n in $only; do
  mutants | cut -d'|' -f1 | grep -qx "$n" ||
    { echo "tb/mutants/run.sh: no mutant '$n' in tb/mutants/list.txt ($(mutants | cut -d'|' -f1 | tr '\n' ' '))" >&2; exit 2; }
done

copy_tree
cmake -S "$work/src" -B "$work/build" -DCMAKE_BUILD_TYPE=Release > "$work/configure.log" 2>&1 || { echo "configure failed: $work/configure.log"; exit 2; }
all=$(mutants | cut -d'|' -f4 | tr ' ' '\n' | sort -u)
# shellcheck disable=SC2086
build $all || { echo "the unmutated tree does not build: $work/build.log"; exit 2; }
# shellcheck disable=SC2086
if f=$(run_tests $all); then echo "unmutated: all tests pass"; else echo "unmutated: FAILS ($f)"; exit 2; fi

bad=0
while IFS='|' read -r name file expr bins; do
  [ "$only" = "  " ] || [[ "$only" == *" $name "* ]] || continue
  t0=$(date +%s)
  cp "$work/src/$file" "$work/pristine"
  sed -i -e "$expr" "$work/src/$file"
  if cmp -s "$work/src/$file" "$work/pristine"; then
    printf '%-12s %-28s NOT APPLIED (the expression changed nothing)\n' "$name" "$file"
    bad=$((bad + 1))
  # shellcheck disable=SC2086
  elif ! build $bins; then
    printf '%-12s %-28s KILLED by the build (%s s)\n' "$name" "$file" $(( $(date +%s) - t0 ))
  # shellcheck disable=SC2086
  elif f=$(run_tests $bins); then
    printf '%-12s %-28s SURVIVED (%s s)\n' "$name" "$file" $(( $(date +%s) - t0 ))
    bad=$((bad + 1))
  else
    printf '%-12s %-28s KILLED by %s (%s s)\n' "$name" "$file" "$f" $(( $(date +%s) - t0 ))
  fi
  cp "$work/pristine" "$work/src/$file"
done < <(mutants)
# Leave the scratch build unmutated for the next run.
build $all > /dev/null 2>&1 || true
exit $((bad > 0))
