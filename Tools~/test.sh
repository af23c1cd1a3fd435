#!/usr/bin/env bash
# The whole default test suite: package lint, core tests, tool tests. Slow suites (Category "Slow")
# are left out unless AVATARGO_SLOW=1. Prints one closing line "N passed, N failed, N skipped".
set -uo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
results="$here/out/test-results"
rm -rf "$results"
filter="TestCategory!=Slow"
[ "${AVATARGO_SLOW:-0}" = "1" ] && filter=""
dotnet test "$here/AvatarGo.slnx" -c Release ${filter:+--filter "$filter"} \
  --logger "trx" --results-directory "$results" "$@"
status=$?
python3 - "$results" <<'PY' || true
import glob, sys, xml.etree.ElementTree as ET
p = f = s = 0
for path in glob.glob(sys.argv[1] + '/*.trx'):
    c = ET.parse(path).getroot().find('.//{*}ResultSummary/{*}Counters')
    if c is None: continue
    p += int(c.get('passed', 0)); f += int(c.get('failed', 0)) + int(c.get('error', 0))
    s += int(c.get('total', 0)) - int(c.get('executed', 0))
print(f"tests: {p} passed, {f} failed, {s} skipped")
PY
exit $status
