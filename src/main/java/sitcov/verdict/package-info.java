/**
 * The verdict in words: what a {@link sitcov.analysis.Comparison} found, as {@code verdict.txt} and the
 * report say it ({@link sitcov.verdict.VerdictText}: the primary answer first, then each pair of drivers
 * in one sentence and measure by measure, then the faults and the uniformity test), and the numbers as a
 * person writes them. Text only: no files, no pictures.
 */
package sitcov.verdict;
