#!/usr/bin/env python3
"""How many times fewer ticks could any proposal over the generator's counts save? (experiments/estimate.md)

    python3 experiments/proposal_bound.py RESULTS_DIR [REQUIREMENT]

Reads the plain Monte Carlo rows of an estimate's samples.csv (or samples.csv.gz) and, for each count site
the generator traces (junctions, parked, moving) and for their pairs and triple, splits the maps into
strata by the bins drawn. It then asks what the best importance sampling over those strata could do: the
proposal that draws stratum i with probability proportional to a_i * sqrt(r_i / c_i) (a_i its share under
the generator, r_i its failure rate, c_i its mean ticks) has the least variance per tick of any proposal
that tilts only those sites. Its ticks saving against plain Monte Carlo at equal precision is
    p (1 - p) c  /  ((sum_i a_i^2 r_i / q_i - p^2) * sum_i q_i c_i).
Fitted to the same maps it is measured on, that figure flatters (a stratum without a failure gets no
draws); so the rates are fitted on the even-indexed maps and the saving measured on the odd ones, and
the other way round, and the two are averaged ("held out"). A proposal that saves nothing held out
cannot be found by the cross-entropy stages either: the failures do not depend on those draws.
Standard library only.
"""
import csv
import gzip
import itertools
import math
import os
import sys

SITES = ["junctions", "parked", "moving"]


def rows_of(folder):
    path = os.path.join(folder, "samples.csv")
    opener = open if os.path.exists(path) else gzip.open
    path = path if os.path.exists(path) else path + ".gz"
    with opener(path, "rt", newline="") as f:
        return [r for r in csv.DictReader(f) if r["stage"] == "mc"]


def bin_of(row, site):
    return row["bins_" + site].split().index("1")


def saving(fit, test, key, failed):
    """Ticks saving of the best stratified proposal fitted on `fit` and measured on `test` (defensive share 0.1)."""
    p_fit = sum(failed(r) for r in fit) / len(fit)
    strata = {}
    for r in test:
        strata.setdefault(key(r), []).append(r)
    fitted = {}
    for r in fit:
        fitted.setdefault(key(r), []).append(r)
    n = len(test)
    share, q = {}, {}
    for k, members in strata.items():
        seen = fitted.get(k, [])
        rate = (sum(failed(r) for r in seen) + 200 * p_fit) / (len(seen) + 200)  # shrunk to the mean
        share[k] = len(members) / n
        q[k] = share[k] * math.sqrt(rate / (sum(int(r["ticks"]) for r in members) / len(members)))
    total = sum(q.values())
    q = {k: 0.9 * v / total + 0.1 * share[k] for k, v in q.items()}
    p = sum(failed(r) for r in test) / n
    if p == 0:
        return float("nan")
    ticks = sum(int(r["ticks"]) for r in test) / n
    variance = sum(share[k] ** 2 / q[k] * sum(failed(r) for r in m) / len(m) for k, m in strata.items()) - p * p
    cost = sum(q[k] * sum(int(r["ticks"]) for r in m) / len(m) for k, m in strata.items())
    return p * (1 - p) * ticks / (variance * cost)


def refuse(message):
    print("proposal_bound.py: " + message, file=sys.stderr)
    sys.exit(2)


def main(argv):
    if len(argv) not in (2, 3):
        refuse("usage: python3 experiments/proposal_bound.py RESULTS_DIR [REQUIREMENT]")
    if not any(os.path.exists(os.path.join(argv[1], f)) for f in ("samples.csv", "samples.csv.gz")):
        refuse(argv[1] + " holds no samples.csv: give the folder an estimate wrote")
    rows = rows_of(argv[1])
    if not rows:
        refuse(argv[1] + " has no plain Monte Carlo maps (mc_maps=0)")
    column = argv[2] if len(argv) == 3 else "any"
    failures = [c for c in rows[0] if c in ("clashwithobstacle", "clashwithothercar", "leaveroad", "crosscentreline",
                                            "timeout", "controller_timeout", "controller_error")]
    if column != "any" and column not in failures:
        refuse("no requirement '" + column + "'; they are any, " + ", ".join(failures))
    failed = (lambda r: any(r[c] == "1" for c in failures)) if column == "any" else (lambda r: r[column] == "1")
    even, odd = rows[0::2], rows[1::2]
    print(f"{len(rows)} plain Monte Carlo maps, {sum(failed(r) for r in rows)} failing ({column})")
    print("sites                      strata  best ticks saving: held out, fitted on all (flatters)")
    for size in (1, 2, 3):
        for sites in itertools.combinations(SITES, size):
            key = lambda r, s=sites: tuple(bin_of(r, x) for x in s)
            mean = (saving(even, odd, key, failed) + saving(odd, even, key, failed)) / 2
            strata = len({key(r) for r in rows})
            print(f"{' x '.join(sites):26s} {strata:6d}  {mean:.2f}x  {saving(rows, rows, key, failed):.2f}x")


if __name__ == "__main__":
    main(sys.argv)
