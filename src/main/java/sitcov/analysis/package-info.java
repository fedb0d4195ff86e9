/**
 * The analysis of what an experiment recorded, as numbers: the paper's measures per driver and
 * replication ({@link sitcov.analysis.Metrics}, gathered by {@link sitcov.analysis.Summary}), faults
 * found against ticks ({@link sitcov.analysis.Discovery}), the coverage curve
 * ({@link sitcov.analysis.CurvePoint}), the paired {@link sitcov.analysis.Comparison} of drivers that the
 * declared {@link sitcov.experiment.AnalysisPlan} judges (one primary question, an exploratory family,
 * equivalence margins: {@link sitcov.analysis.MeasureComparison}, {@link sitcov.analysis.FaultComparison},
 * {@link sitcov.analysis.Finding}), situations against faults ({@link sitcov.analysis.SituationFaults})
 * and the effort sweep ({@link sitcov.analysis.Sweep}). Knows no driver by name and no file; the words of
 * the verdict are in {@code sitcov.verdict}.
 */
package sitcov.analysis;
