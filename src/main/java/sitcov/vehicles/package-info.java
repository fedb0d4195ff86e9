/**
 * Vehicles. The world's side: the car under test ({@link sitcov.vehicles.AutonomousCar}, a body the
 * world moves on its controller's commands, judging arrival from geometry), its
 * {@link sitcov.vehicles.SceneObservation observation}, the moving cars that drive by ground truth,
 * the junction locks, the {@link sitcov.vehicles.Scene} they share and the run's
 * {@link sitcov.vehicles.Telemetry}, all that watchers of a run receive. The builtin controller:
 * {@link sitcov.vehicles.BuiltinCar} with its sensors (camera, LIDAR, radar processing) and named
 * behaviours, which sees only what its observation carries. What a run holds keeps no final instance
 * fields: a checkpoint copies it field by field ({@link sitcov.engine.ModelCopy}).
 */
package sitcov.vehicles;
