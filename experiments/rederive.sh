#!/bin/sh
# Computes each kept results folder's published files again from what the folder keeps, and compares them
# byte for byte: experiments/rederive.sh [FOLDER...] (default: every folder under experiments/results).
#   a test suite (runs.csv.xz):  unpack runs.csv, timings.csv, situations/, then 'report COPY'
#   a campaign (campaign.csv):   'report COPY' from campaign.csv alone
#   an estimate (samples.csv.gz): gunzip samples.csv, then 'merge COPY --out NEW'
# Works on copies in a temporary folder; the kept folders are never written. Exit 1 when a file differs or a
# folder keeps nothing to compute it from. About 5 minutes for all of them on 2 cores.
set -eu
here=$(cd "$(dirname "$0")" && pwd)
sitcov="$here/sitcov"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
if [ $# -eq 0 ]; then
    set -- $(find "$here/results" -name manifest.properties -o -name campaign.properties | xargs -n 1 dirname | sort)
fi
failed=0
n=0
for kept in "$@"; do
    kept=${kept%/}
    n=$((n + 1))
    copy="$tmp/$n"
    made="$copy"
    mkdir -p "$copy"
    if [ -f "$kept/campaign.properties" ]; then
        cp "$kept/campaign.csv" "$kept/campaign.properties" "$kept/grid.txt" "$copy/"
        "$sitcov" report "$copy" > "$tmp/log" 2>&1 || { cat "$tmp/log"; failed=1; continue; }
    elif [ -f "$kept/runs.csv.xz" ]; then
        cp -r "$kept/." "$copy/"
        (cd "$copy" && unxz runs.csv.xz && { [ ! -f timings.csv.xz ] || unxz timings.csv.xz; } \
            && { [ ! -f situations.tar.xz ] || tar xJf situations.tar.xz; })
        "$sitcov" report "$copy" > "$tmp/log" 2>&1 || { cat "$tmp/log"; failed=1; continue; }
    elif [ -f "$kept/samples.csv.gz" ]; then
        cp -r "$kept/." "$copy/"
        gunzip "$copy/samples.csv.gz"
        made="$tmp/$n-merged"
        "$sitcov" merge "$copy" --out "$made" > "$tmp/log" 2>&1 || { cat "$tmp/log"; failed=1; continue; }
    else
        echo "$kept: keeps neither runs.csv.xz, campaign.csv nor samples.csv.gz to compute its files from"
        failed=1
        continue
    fi
    same=0
    for f in "$kept"/*; do
        name=$(basename "$f")
        case "$name" in README.md|*.xz|*.gz) continue ;; esac
        [ -f "$f" ] || continue
        if cmp -s "$f" "$made/$name"; then
            same=$((same + 1))
        else
            echo "$kept: $name differs from what its kept data gives"
            failed=1
        fi
    done
    echo "$kept: $same files computed again, the same bytes"
done
exit $failed
