/**
 * The builtin car: sitcov's own controller, one plug-in among others behind the seam of
 * {@link sitcov.control}. {@link sitcov.builtin.BuiltinCar} reads what its observation carries,
 * processes the standard sensors of {@link sitcov.sensors} as any controller could (its camera's
 * lane estimate, its LIDAR's parked-car sightings, its radar's path and oncoming gaps), and lets
 * named behaviours decide: junctions ({@link sitcov.builtin.JunctionDriver}), overtaking
 * ({@link sitcov.builtin.Overtaker}), keeping its distance, reaching the Target. Its twenty seeded
 * faults act at the seams the behaviours name; its factory is a
 * {@link sitcov.faults.SeededControllerFactory}, handed each run's switchboard. Only the command
 * line and the controller registry ({@link sitcov.protocol}) name it. What a run holds keeps no
 * final instance fields: a checkpoint copies it field by field ({@link sitcov.engine.ModelCopy}).
 */
package sitcov.builtin;
