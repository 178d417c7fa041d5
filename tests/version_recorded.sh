#!/bin/sh
# The version of `aspects --version` (CMake's project version, then the git commit when
# known) is the one recorded in summary.json and in the certificate's `tool` line, and
# check_cert reports the same and still verifies that certificate.
# Usage: version_recorded.sh ASPECTS CHECK_CERT MODEL PROJECT_VERSION
set -eu
aspects=$1 check=$2 model=$3 want=$4
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
fail() { echo "version_recorded: $*" >&2; exit 1; }

v=$("$aspects" --version) || fail "aspects --version exited $?"
echo "$v"
version=$(echo "$v" | sed -n 's/^aspects \([^ ]*\).*/\1/p')
commit=$(echo "$v" | sed -n 's/^aspects [^ ]* (git \([0-9a-f]*\(-dirty\)\{0,1\}\))$/\1/p')
[ "$version" = "$want" ] || fail "aspects --version says '$version', CMake's project version is '$want'"
echo "$v" | grep -Eqx "aspects [^ ]+( \(git [0-9a-f]+(-dirty)?\))?" || fail "unexpected form: $v"
c=$("$check" --version) || fail "check_cert --version exited $?"
[ "$c" = "check_cert${v#aspects}" ] || fail "check_cert --version says '$c', aspects says '$v'"

"$aspects" solve "$model" --eps 0.1 --out "$out" --quiet
/usr/bin/python3 - "$out/summary.json" "$version" "$commit" <<'PY'
import json, sys
s = json.load(open(sys.argv[1]))
want_commit = sys.argv[3] or None
assert s["version"] == sys.argv[2], ("version", s.get("version"))
assert s["git_commit"] == want_commit, ("git_commit", s.get("git_commit"), want_commit)
PY
token=$version${commit:++g$commit}
tool=$(sed -n 2p "$out/aspects.cert")
[ "$tool" = "tool aspects $token" ] || fail "certificate line 2 is '$tool', expected 'tool aspects $token'"
"$check" --quiet "$out/aspects.cert" | grep -q '^check_cert: VERIFIED' || fail "check_cert rejected the certificate"
echo "ok"
