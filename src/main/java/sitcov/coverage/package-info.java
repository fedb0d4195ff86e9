/**
 * Situation coverage: the criteria computed from a generated map before any simulation, their bins
 * (read from a grid definition file), and the grid of cells that counts maps.
 */
package sitcov.coverage;
