/**
 * The report of an experiment: the listener that journals it as it runs and completes its results
 * folder when it ends ({@link sitcov.report.ResultsRecorder}, {@link sitcov.report.ResultsFinisher}: the
 * journal in canonical order, every table, statistic, figure and replay, then the manifest marked
 * complete), the merge of shards into that same folder ({@link sitcov.report.ShardMerger}), and the page
 * a person opens, {@code report.html} ({@link sitcov.report.HtmlReport} and its sections). Knows every
 * job below it; nothing below knows it.
 */
package sitcov.report;
