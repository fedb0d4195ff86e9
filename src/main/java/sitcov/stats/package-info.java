/**
 * Statistics as pure functions of numbers: no other sitcov package is used here.
 */
package sitcov.stats;
