/**
 * The figures of a results folder, drawn with Java2D (headless) on a {@link sitcov.figures.Chart} with its
 * {@link sitcov.figures.Axis} and {@link sitcov.figures.Band}s: the paper's Fig. 2 and 3 and coverage over
 * time ({@link sitcov.figures.ExperimentFigures}), the comparison's measures, odds ratios and faults found
 * against ticks ({@link sitcov.figures.StatsFigures}), the effort sweep's Fig. 4
 * ({@link sitcov.figures.SweepReport}) and the coverage grid as heat-map slices
 * ({@link sitcov.figures.CoverageHeatMap}).
 */
package sitcov.figures;
