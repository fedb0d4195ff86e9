/**
 * The test generators an experiment compares, each a {@link sitcov.experiment.Driver}: random maps
 * ({@link sitcov.drivers.RandomDriver}), every other candidate ({@link sitcov.drivers.EveryOtherDriver}),
 * the paper's coverage filter ({@link sitcov.drivers.CoverageFilterDriver}), and the search that edits
 * situations towards uncovered cells or towards faults ({@link sitcov.drivers.CoverageSearchDriver},
 * with its {@link sitcov.drivers.AimedEdits} and {@link sitcov.drivers.ElitePreference}). A new driver
 * lives here and is named in {@link sitcov.drivers.Drivers#standard()}, the names a preset can use.
 */
package sitcov.drivers;
