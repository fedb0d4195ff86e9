/**
 * Vehicles: the autonomous car (the system under test) with its sensors and named behaviours,
 * the moving cars that drive by ground truth, and the {@link sitcov.vehicles.Scene} they share.
 */
package sitcov.vehicles;
