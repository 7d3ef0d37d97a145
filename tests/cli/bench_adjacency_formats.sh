#!/usr/bin/env bash
# bench_adjacency keeps Google Benchmark's own output options: --benchmark_format=json gives a
# valid JSON document on stdout (the ratio table, an extra, goes to stderr then), and
# --benchmark_out writes its file; the console display ends with the ratio table.
set -uo pipefail
build=$2
bench=$build/bench_adjacency
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }
filter=(--benchmark_filter='grid_1058/' --benchmark_min_time=0.001)

"$bench" "${filter[@]}" --benchmark_format=json >"$work/out.json" 2>"$work/err" || fail "json run exited $?"
python3 - "$work/out.json" <<'PY' || fail "stdout is not the benchmark JSON: $(head -c 300 "$work/out.json")"
import json, sys
doc = json.load(open(sys.argv[1]))
names = [b["name"] for b in doc["benchmarks"]]
assert "grid_1058/bz_line_mesh" in names and "grid_1058/meshopt" in names, names
PY
grep -q "^grid_1058 .*x" "$work/err" || fail "no ratio table on stderr after JSON: $(cat "$work/err")"

"$bench" "${filter[@]}" --benchmark_format=csv >"$work/out.csv" 2>"$work/err" || fail "csv run exited $?"
grep -q '^name,iterations,' "$work/out.csv" || fail "csv header: $(head -3 "$work/out.csv")"

"$bench" "${filter[@]}" --benchmark_out="$work/file.json" --benchmark_out_format=json >"$work/out" 2>&1 ||
  fail "console run exited $?"
grep -q '"grid_1058/meshopt"' "$work/file.json" || fail "--benchmark_out wrote no JSON file"
grep -q "^mesh .*speedup" "$work/out" || fail "no ratio table after the console display"
echo "ok bench_adjacency formats"
