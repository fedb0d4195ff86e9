/**
 * Situation coverage: the criteria computed from a generated map before any simulation, their bins
 * (read from a grid definition file), and the grid of cells that counts maps. {@link sitcov.coverage.GridDefinition}
 * is the one place that numbers cells from bins and back, and says which cells are neighbours.
 */
package sitcov.coverage;
