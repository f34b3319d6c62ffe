# Sourced by tests that change a repository: scratch_repo ROOT DEST makes DEST a git repository of
# ROOT's tracked files as they are on disk (uncommitted edits included), committed once.
# shellcheck shell=bash
scratch_repo() {
  mkdir -p "$2"
  (cd "$1" && git ls-files -z | tar --null -T - -cf -) | tar -xf - -C "$2"
  git -C "$2" init -q
  git -C "$2" add -A
  git -C "$2" -c user.name=test -c user.email=test@example.com commit -qm scratch
}
