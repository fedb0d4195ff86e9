#!/usr/bin/env bash
# Do near misses fail under other traffic? (experiments/README.md, "Requirement campaigns: where your controller
# itself fails")
#
#   experiments/near_misses.sh RESULTS_DIR [MAPS] [SEEDS]
#
# RESULTS_DIR is a run's results folder with variants=none (its runs.csv holds the reference's runs and their
# robustness ρ). For each requirement it takes the MAPS generated maps (default 10) that came nearest to
# violating it without doing so (least ρ) and as many that violated it, runs each again fault-free with the
# internal seeds 1..SEEDS (default 5: other moving cars' turns and restarts, the controller's other random
# choices) and counts the runs that violate that requirement. Runs experiments/sitcov simulate, so the
# controller is the builtin car. If near misses failed again more often than maps at random, ρ would be a guide
# to failures; the share among the failing maps says how much a failure owes to the map rather than the traffic.
set -eu
here=$(cd "$(dirname "$0")" && pwd)
dir=${1:?usage: experiments/near_misses.sh RESULTS_DIR [MAPS] [SEEDS]}
maps=${2:-10}
seeds=${3:-5}
if [[ ! -f "$dir/runs.csv" ]]; then
    echo "near_misses.sh: $dir holds no runs.csv: give the results folder of a run with variants=none" >&2
    exit 2
fi
# column numbers by name, so the script does not depend on runs.csv's column order
col() { head -1 "$dir/runs.csv" | tr ',' '\n' | grep -n -x "$1" | cut -d: -f1; }
map=$(col map); fault=$(col fault)
printf '%-18s %-9s %5s %6s  %s\n' requirement maps runs failed share
for type in clashwithobstacle clashwithothercar leaveroad crosscentreline timeout; do
    count=$(col "$type"); rho=$(col "rho_$type")
    for group in near failing; do
        if [[ $group == near ]]; then
            picked=$(awk -F, -v m="$map" -v f="$fault" -v c="$count" -v r="$rho" \
                'NR > 1 && $m ~ /^seed:/ && $f == "NONE" && $c == 0 && $r != "" { print $r, substr($m, 6) }' "$dir/runs.csv" \
                | sort -g | head -n "$maps" | cut -d' ' -f2)
        else
            picked=$(awk -F, -v m="$map" -v f="$fault" -v c="$count" \
                'NR > 1 && $m ~ /^seed:/ && $f == "NONE" && $c > 0 { print substr($m, 6) }' "$dir/runs.csv" | head -n "$maps")
        fi
        n=0; runs=0; failed=0
        for seed in $picked; do
            n=$((n + 1))
            for internal in $(seq 1 "$seeds"); do
                runs=$((runs + 1))
                if "$here/sitcov" simulate --seed "$seed" --internal-seed "$internal" | head -1 | grep -q -i "${type}"; then
                    failed=$((failed + 1))
                fi
            done
        done
        share=$(awk -v f="$failed" -v r="$runs" 'BEGIN { if (r > 0) printf "%.1f %%", 100 * f / r; else print "-" }')
        printf '%-18s %-9s %5d %6d  %s\n' "$type" "$group:$n" "$runs" "$failed" "$share"
    done
done
