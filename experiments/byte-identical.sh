#!/usr/bin/env bash
# Proves a restructuring changed no output: record what a build writes, then compare two records.
#
#   experiments/byte-identical.sh record JAR OUTDIR    run the fixed commands below with JAR, into OUTDIR
#   experiments/byte-identical.sh compare BASE NEW     compare two records byte for byte; exit 1 if any differ
#
# Typical use: build the untouched branch (mvn -q -B package -DskipTests), copy target/sitcov-*.jar aside,
# record it into /tmp/base; build the changed branch, record it into /tmp/new; compare /tmp/base /tmp/new.
# Every command has fixed seeds and thread counts; the results are the same on every machine (src/README.md,
# "Determinism"). What measures the machine rather than the results is left out of the comparison: the files
# timings.csv, execution.properties and fig3-coverage-time.png, each command's stderr (progress and ETA),
# and in stdout the wall-clock seconds and the record's own folder (rewritten as OUTDIR).
set -euo pipefail

TIMED_FILES=(timings.csv execution.properties fig3-coverage-time.png)

usage() {
    echo "usage: $0 record JAR OUTDIR | compare BASE_OUTDIR NEW_OUTDIR" >&2
    exit 2
}

# One command: its stdout (normalised), stderr (kept, not compared) and exit code go to OUTDIR/NAME.*
step() {
    local name="$1"; shift
    echo "== $name: sitcov $*" >&2
    local rc=0
    java -jar "$JAR" "$@" >"$OUT/$name.stdout.raw" 2>"$OUT/$name.stderr" || rc=$?
    echo "$rc" >"$OUT/$name.rc"
    # The record's own path and the wall-clock tail of "Results in DIR (28 s on 2 threads)" vary from run to run.
    sed -e "s|$OUT|OUTDIR|g" \
        -e 's|^\(Results in .*\) ([^()]* on [0-9]* threads\{0,1\})$|\1 (WALL-CLOCK)|' \
        "$OUT/$name.stdout.raw" >"$OUT/$name.stdout"
    rm "$OUT/$name.stdout.raw"
    if [ "$rc" != 0 ]; then
        echo "   exit code $rc (see $OUT/$name.stderr)" >&2
    fi
}

record() {
    JAR="$(realpath "$1")"
    OUT="$(realpath -m "$2")"
    [ -f "$JAR" ] || { echo "no jar at $1: build one with mvn -q -B package -DskipTests" >&2; exit 2; }
    if [ -e "$OUT" ] && [ -n "$(ls -A "$OUT")" ]; then
        echo "$OUT is not empty: name a new folder so no earlier record is mixed in" >&2
        exit 2
    fi
    mkdir -p "$OUT"
    # Presets name files relative to the repository root (grid=experiments/paper-grid.txt).
    cd "$(dirname "$0")/.."

    # The fixed commands whose output is compared.
    step smoke run smoke --out "$OUT/smoke" --threads 2
    step search-5000 run search-5000 --replications 3 --out "$OUT/search-5000" --threads 2
    step faults-calibrate faults --calibrate --maps 60 --seed 1 --threads 2
    step simulate-600 simulate --maps 600 --seed 1 --gallery "$OUT/simulate-600-gallery"

    # A few seconds more: the pictures, trace, replays and re-report that the four above do not draw.
    mkdir -p "$OUT/extra"
    step map map --seed 5 --png "$OUT/extra/seed5.png" --save "$OUT/extra/seed5.situation"
    step simulate-one simulate --seed 5 --internal-seed 7 --png "$OUT/extra/run.png" --trace "$OUT/extra/run.csv"
    step replay-row replay "$OUT/smoke" --row 3 --png "$OUT/extra/replay-row3.png" --gif "$OUT/extra/replay-row3.gif"
    step coverage coverage --maps 2000 --seed 1 --png "$OUT/extra/coverage.png"
    cp -r "$OUT/smoke" "$OUT/smoke-reported"
    step report report "$OUT/smoke-reported"
    echo "recorded into $OUT" >&2
}

compare() {
    local base new
    base="$(realpath "$1")"
    new="$(realpath "$2")"
    [ -d "$base" ] && [ -d "$new" ] || usage
    local excludes=()
    for f in "${TIMED_FILES[@]}" '*.stderr'; do excludes+=(-x "$f"); done
    local differences
    differences="$(diff -rq "${excludes[@]}" "$base" "$new" || true)"
    local files
    files="$(cd "$base" && find . -type f | grep -v -e '\.stderr$' $(printf -- "-e /%s\$ " "${TIMED_FILES[@]}") | wc -l)"
    if [ -z "$differences" ]; then
        echo "byte-identical: $files files of $base and $new agree (left out: ${TIMED_FILES[*]}, stderr)"
    else
        echo "$differences"
        echo "NOT byte-identical: $(echo "$differences" | wc -l) difference(s) between $base and $new"
        exit 1
    fi
}

case "${1:-}" in
    record) [ $# = 3 ] || usage; record "$2" "$3" ;;
    compare) [ $# = 3 ] || usage; compare "$2" "$3" ;;
    *) usage ;;
esac
