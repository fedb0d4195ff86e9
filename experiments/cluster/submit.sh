#!/bin/bash
# Submits a sitcov experiment to Slurm: a job array with one task per shard (shards.sbatch), then
# a merge job (merge.sbatch) that starts only when every shard succeeded.
# Run it from the repository checkout, on a file system the compute nodes share:
#   experiments/cluster/submit.sh PRESET SHARDS [RESULTS]
# Environment: CPUS (cpus per shard = sitcov threads; default 1), SBATCH_OPTS (more sbatch options
# for both jobs, e.g. "--partition=short --time=02:00:00"), SITCOV_JAR, JAVA, JAVA_OPTS.
# Before submitting it has sitcov check the preset (run PRESET --dry-run, here, with JAVA): a preset
# mistake, or more shards than the preset has replications, is refused before anything is queued.
set -euo pipefail

die() { echo "submit.sh: $*" >&2; exit 2; }

if [[ $# -lt 2 || $# -gt 3 || $1 == -h || $1 == --help ]]; then
    echo "Usage: $0 PRESET SHARDS [RESULTS]" >&2
    echo "  PRESET   experiments/NAME.properties by NAME, or a .properties path" >&2
    echo "  SHARDS   number of array tasks N (one shard each), at most the preset's replications (map sets)" >&2
    echo "  RESULTS  results root [target/results/slurm-NAME-YYYYmmdd-HHMMSS]; shards go to RESULTS/shard-K, the merge to RESULTS/merged" >&2
    exit 2
fi
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
PRESET=$1
SHARDS=$2
[[ $SHARDS =~ ^[1-9][0-9]*$ ]] || die "SHARDS must be a positive integer, got '$SHARDS'."
[[ -f $PRESET || -f experiments/$PRESET.properties ]] \
    || die "no preset '$PRESET' (neither a file nor experiments/$PRESET.properties in $PWD); run from the repository checkout."
name=${PRESET##*/}
name=${name%.properties}
RESULTS=${3:-target/results/slurm-$name-$(date +%Y%m%d-%H%M%S)}
[[ $RESULTS == /* ]] || RESULTS=$PWD/$RESULTS

if [[ -z ${SITCOV_JAR:-} ]]; then
    jars=()
    for f in target/sitcov-*.jar; do
        case $f in *-sources.jar | *-javadoc.jar | *-tests.jar) ;; *) [[ -f $f ]] && jars+=("$f") ;; esac
    done
    (( ${#jars[@]} == 1 )) || die "found ${#jars[@]} jars target/sitcov-*.jar in $PWD; build with 'mvn -q package' or set SITCOV_JAR."
    SITCOV_JAR=${jars[0]}
fi
[[ $SITCOV_JAR == /* ]] || SITCOV_JAR=$PWD/$SITCOV_JAR
[[ -f $SITCOV_JAR ]] || die "SITCOV_JAR=$SITCOV_JAR is not a file."
if [[ -n ${JAVA:-} ]]; then :; elif [[ -n ${JAVA_HOME:-} ]]; then JAVA=$JAVA_HOME/bin/java; else JAVA=java; fi
read -r -a java_opts <<< "${JAVA_OPTS:-}"

# sitcov reads the preset as the jobs will (from here) and says how many replications it has; a shard
# beyond them would run nothing, and a preset mistake would fail every array task after its wait in the queue
command -v "$JAVA" > /dev/null || die "cannot run '$JAVA' here to check the preset; load Java 17 (e.g. module load java/17) or set JAVA."
if ! plan=$("$JAVA" ${java_opts[@]+"${java_opts[@]}"} -jar "$SITCOV_JAR" run "$PRESET" --dry-run --threads 1 2>&1); then
    printf '%s\n' "$plan" >&2
    die "sitcov refused the preset (above); nothing was submitted."
fi
[[ $plan =~ :\ ([0-9]+)\ (replications|map\ sets), ]] || die "cannot read the preset's replications from sitcov's check: $plan"
units=${BASH_REMATCH[1]}
(( SHARDS <= units )) || die "SHARDS=$SHARDS is more than the $units ${BASH_REMATCH[2]} of $name; each shard needs one: submit at most $units shards."
if [[ -d $RESULTS/merged ]] && [[ -n $(ls -A "$RESULTS/merged") ]]; then
    die "$RESULTS/merged exists already; choose another RESULTS."
fi

read -r -a extra <<< "${SBATCH_OPTS:-}"
cpus=()
[[ -z ${CPUS:-} ]] || cpus=(--cpus-per-task="$CPUS")
mkdir -p "$RESULTS/logs"
export PRESET SHARDS RESULTS SITCOV_JAR

array_cmd=(sbatch --parsable --export=ALL --chdir="$PWD" --array="1-$SHARDS" ${cpus[@]+"${cpus[@]}"}
    --output="$RESULTS/logs/%x-%A_%a.out" ${extra[@]+"${extra[@]}"} "$here/shards.sbatch")
echo "+ PRESET=$PRESET SHARDS=$SHARDS RESULTS=$RESULTS SITCOV_JAR=$SITCOV_JAR $(printf '%q ' "${array_cmd[@]}")"
array_id=$("${array_cmd[@]}")
array_id=${array_id%%;*}

merge_cmd=(sbatch --parsable --export=ALL --chdir="$PWD" --dependency="afterok:$array_id" --kill-on-invalid-dep=yes
    --output="$RESULTS/logs/%x-%j.out" ${extra[@]+"${extra[@]}"} "$here/merge.sbatch")
echo "+ $(printf '%q ' "${merge_cmd[@]}")"
merge_id=$("${merge_cmd[@]}")
merge_id=${merge_id%%;*}

echo "Shards: array job $array_id (tasks 1-$SHARDS) -> $RESULTS/shard-1 .. $RESULTS/shard-$SHARDS"
echo "Merge:  job $merge_id (after all shards succeed) -> $RESULTS/merged"
echo "Logs:   $RESULTS/logs/"
echo "Check:  squeue -j $array_id,$merge_id (queued and running jobs); a shard's progress: tail -f $RESULTS/logs/sitcov-shard-${array_id}_1.out"
