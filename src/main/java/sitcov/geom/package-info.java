/**
 * Small immutable value maths: vectors, bearings and compass directions, axis-aligned rectangles,
 * oriented boxes (vehicle footprints) and segment tests. Depends on nothing else in sitcov.
 *
 * <p>Conventions (those of the original simulation): metres, y grows downwards so north is −y;
 * a bearing β is measured from +y towards +x, so a move of length v at β is
 * (v·sin β, v·cos β): 0° is south, 90° east, 180° north, 270° west, and increasing β turns left.
 */
package sitcov.geom;
